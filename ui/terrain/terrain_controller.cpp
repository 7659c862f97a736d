#include "ui/terrain/terrain_controller.h"

#include "core/mission/terrain_stage.h"
#include "core/terrain/dem.h"
#include "core/terrain/height_grid.h"
#include "ui/commands/set_terrain_command.h"
#include "ui/mission_document.h"
#include "ui/planning/plan_controller.h"
#include "ui/terrain/terrain_profile_widget.h"

#include <QComboBox>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QLabel>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QUndoStack>
#include <QVBoxLayout>

#include <cmath>

namespace pf::ui {

namespace {

// The flight of one planned route as a profile: home, every waypoint, home; the ground every 2 m.
TerrainProfile profileOf(const mission::MissionPlan& plan, std::size_t k, double minClearanceM, const QColor& colour) {
    TerrainProfile out;
    out.minClearanceM = minClearanceM;
    out.colour = colour;
    if (!plan.terrain || !plan.frame || k >= plan.aircraft.size())
        return out;
    const auto& r = plan.aircraft[k].route;
    if (!r.hasTerrain())
        return out;
    const double home = *r.homeElevationM;
    std::vector<geo::Vec2> pos;
    std::vector<double> z;
    if (r.home) {
        pos.push_back(plan.frame->toLocal(*r.home));
        z.push_back(home + r.waypoints.front().altitudeM); // climbs at home, then flies level out
    }
    for (const auto& w : r.waypoints) {
        pos.push_back(plan.frame->toLocal(w.position));
        z.push_back(home + w.altitudeM);
    }
    if (r.home) {
        pos.push_back(pos.front());
        z.push_back(z.back()); // back home level, then down
    }
    double s0 = 0.0;
    for (std::size_t i = 0; i + 1 < pos.size(); ++i) {
        const double len = (pos[i + 1] - pos[i]).norm();
        out.waypointsM.push_back(s0);
        const int n = std::max(1, static_cast<int>(std::ceil(len / 2.0)));
        for (int j = 0; j < n; ++j) {
            const double t = static_cast<double>(j) / n;
            out.distanceM.push_back(s0 + len * t);
            out.groundM.push_back(plan.terrain->heightOr(pos[i] + (pos[i + 1] - pos[i]) * t, std::nan("")));
            out.aircraftM.push_back(z[i] + (z[i + 1] - z[i]) * t);
        }
        s0 += len;
    }
    out.distanceM.push_back(s0);
    out.groundM.push_back(plan.terrain->heightOr(pos.back(), std::nan("")));
    out.aircraftM.push_back(z.back());
    return out;
}

} // namespace

TerrainController::TerrainController(QMainWindow* window, MissionDocument* doc, PlanController* planner,
                                     bool interactive)
    : QObject(window), m_window(window), m_doc(doc), m_planner(planner), m_interactive(interactive) {
    m_menu = new QMenu(tr("&Terrain model"), window);
    m_menu->setObjectName(QStringLiteral("TerrainMenu"));
    auto* choose = m_menu->addAction(tr("&Choose terrain model (DEM)…"), this, &TerrainController::chooseDem);
    choose->setObjectName(QStringLiteral("ChooseDemAction"));
    const QString demo = QString::fromStdString(mission::demoDemPath());
    if (!demo.isEmpty())
        m_menu->addAction(tr("Use the &demo terrain model (synthetic)"), this, [this, demo] { useDem(demo); });
    m_menu->addSeparator();
    m_followAct = m_menu->addAction(tr("&Follow the terrain"));
    m_followAct->setObjectName(QStringLiteral("FollowTerrainAction"));
    m_followAct->setCheckable(true);
    m_followAct->setToolTip(tr("Every photo at the aircraft's altitude above the ground under it (constant GSD), "
                               "every leg kept the minimum clearance above the ground"));
    connect(m_followAct, &QAction::triggered, this, &TerrainController::setFollow);
    m_clearanceAct = m_menu->addAction(tr("Minimum &clearance…"), this, &TerrainController::askClearance);
    m_removeAct = m_menu->addAction(tr("&Remove terrain model"), this, &TerrainController::removeDem);

    m_dock = new QDockWidget(tr("Terrain profile"), window);
    m_dock->setObjectName(QStringLiteral("TerrainDock"));
    auto* body = new QWidget;
    auto* lay = new QVBoxLayout(body);
    lay->setContentsMargins(4, 4, 4, 4);
    m_aircraft = new QComboBox;
    m_aircraft->setObjectName(QStringLiteral("TerrainAircraftBox"));
    m_summary = new QLabel;
    m_summary->setObjectName(QStringLiteral("TerrainSummary"));
    m_summary->setWordWrap(true);
    m_summary->setTextFormat(Qt::RichText);
    m_profile = new TerrainProfileWidget;
    lay->addWidget(m_aircraft);
    lay->addWidget(m_summary);
    lay->addWidget(m_profile, 1);
    m_dock->setWidget(body);
    connect(m_aircraft, QOverload<int>::of(&QComboBox::activated), this, [this](int) { refresh(); });
    connect(m_planner, &PlanController::planChanged, this, &TerrainController::refresh);
    connect(m_doc, &MissionDocument::optionsChanged, this, &TerrainController::refresh);
    connect(m_doc, &MissionDocument::changed, this, &TerrainController::refresh);
    refresh();
}

bool TerrainController::useDem(const QString& path) {
    auto dem = terrain::Dem::open(path.toStdString());
    if (!dem) {
        m_error = QString::fromStdString(dem.error().message);
        if (m_interactive)
            QMessageBox::warning(m_window, tr("Terrain model"), m_error);
        return false;
    }
    m_error.clear();
    mission::TerrainOptions t = m_doc->mission().terrain;
    t.demPath = path.toStdString();
    t.mode = mission::TerrainMode::Follow;
    m_doc->undoStack()->push(
        new SetTerrainCommand(m_doc, t, tr("Follow the terrain of %1").arg(QFileInfo(path).fileName())));
    return true;
}

void TerrainController::setFollow(bool on) {
    mission::TerrainOptions t = m_doc->mission().terrain;
    if (t.follows() == on)
        return;
    if (on && t.demPath.empty()) {
        m_followAct->setChecked(false);
        chooseDem();
        return;
    }
    t.mode = on ? mission::TerrainMode::Follow : mission::TerrainMode::Off;
    m_doc->undoStack()->push(new SetTerrainCommand(m_doc, t, on ? tr("Follow the terrain") : tr("Fly above take-off")));
}

void TerrainController::setMinClearance(double metres) {
    mission::TerrainOptions t = m_doc->mission().terrain;
    if (!(metres >= 0) || t.minClearanceM == metres)
        return;
    t.minClearanceM = metres;
    m_doc->undoStack()->push(
        new SetTerrainCommand(m_doc, t, tr("Minimum terrain clearance %1 m").arg(metres, 0, 'f', 1)));
}

void TerrainController::removeDem() {
    if (m_doc->mission().terrain.isDefault())
        return;
    mission::TerrainOptions t = m_doc->mission().terrain;
    t.demPath.clear();
    t.mode = mission::TerrainMode::Off;
    m_doc->undoStack()->push(new SetTerrainCommand(m_doc, t, tr("Remove the terrain model")));
}

void TerrainController::chooseDem() {
    if (!m_interactive)
        return;
    const QString path = QFileDialog::getOpenFileName(
        m_window, tr("Terrain model"), QString(),
        tr("Terrain models (*.tif *.tiff *.hgt *.vrt *.dem *.img *.asc *.bil);;All files (*)"));
    if (!path.isEmpty())
        useDem(path);
}

void TerrainController::askClearance() {
    if (!m_interactive)
        return;
    bool ok = false;
    const double v = QInputDialog::getDouble(m_window, tr("Minimum clearance"),
                                             tr("No leg closer to the ground than (m):"),
                                             m_doc->mission().terrain.minClearanceM, 0.0, 500.0, 1, &ok);
    if (ok)
        setMinClearance(v);
}

void TerrainController::refresh() {
    const auto& t = m_doc->mission().terrain;
    m_followAct->setChecked(t.follows());
    m_clearanceAct->setEnabled(!t.demPath.empty());
    m_removeAct->setEnabled(!t.isDefault());
    const auto& m = m_doc->mission();
    const int current = m_aircraft->currentIndex();
    {
        const QSignalBlocker block(m_aircraft);
        m_aircraft->clear();
        for (const auto& a : m.aircraft)
            m_aircraft->addItem(QString::fromStdString(a.name));
        m_aircraft->setCurrentIndex(current >= 0 && current < m_aircraft->count() ? current : 0);
    }
    const QString dem = QFileInfo(QString::fromStdString(t.demPath)).fileName();
    if (!t.follows()) {
        m_summary->setText(t.demPath.empty() ? tr("Terrain following is off: altitudes above the take-off point over "
                                                 "a flat world. File ▸ Terrain model chooses a DEM.")
                                             : tr("Terrain following is off (terrain model %1 not used).").arg(dem));
        m_profile->setProfile({});
        return;
    }
    const auto& plan = m_planner->plan();
    const int k = m_aircraft->currentIndex();
    if (!plan || k < 0 || static_cast<std::size_t>(k) >= plan->aircraft.size() || !plan->aircraft[k].terrain.active) {
        m_summary->setText(tr("Following the terrain of %1: no plan over it yet (see Problems if planning failed).").arg(dem));
        m_profile->setProfile({});
        return;
    }
    const auto& ts = plan->aircraft[k].terrain;
    const QColor colour(QString::fromStdString(m.aircraft[k].colour));
    TerrainProfile prof = profileOf(*plan, static_cast<std::size_t>(k), t.minClearanceM, colour);
    const double lowest = prof.lowestClearanceM();
    QString text = tr("<b>%1</b> over %2: %3 m above the ground under every photo (lanes for %4 m, photo "
                      "spacing per lane: %11 photo(s) fewer on %12 lane(s)), take-off ground %5 m, lowest "
                      "clearance %6 m (minimum %7 m), %8 waypoint(s) inserted, GSD %9 cm/px (photo edges down "
                      "to %10).")
                       .arg(QString::fromStdString(plan->aircraft[k].aircraft), dem)
                       .arg(ts.heightAboveGroundM, 0, 'f', 1)
                       .arg(ts.planningHeightM, 0, 'f', 1)
                       .arg(ts.homeGroundM, 0, 'f', 1)
                       .arg(std::isfinite(lowest) ? lowest : ts.lowestClearanceM, 0, 'f', 1)
                       .arg(t.minClearanceM, 0, 'f', 1)
                       .arg(ts.waypointsInserted)
                       .arg(ts.gsdCm, 0, 'f', 2)
                       .arg(ts.coarsestGsdCm, 0, 'f', 2)
                       .arg(ts.photosSavedPerLane)
                       .arg(ts.lanesRespaced);
    if (std::isfinite(lowest) && lowest < t.minClearanceM - 0.05)
        text += tr("<br><span style='color:#c00000'>Clearance below the minimum: see the red part of the "
                   "profile.</span>");
    if (ts.gsdCm > 0 && ts.coarsestGsdCm > 1.25 * ts.gsdCm)
        text += tr("<br><span style='color:#b35900'>GSD out of bounds: photo edges see ground up to %1 % farther "
                   "(steep slopes); see Problems.</span>")
                    .arg(100.0 * (ts.coarsestGsdCm / ts.gsdCm - 1.0), 0, 'f', 0);
    m_summary->setText(text);
    m_profile->setProfile(std::move(prof));
}

} // namespace pf::ui
