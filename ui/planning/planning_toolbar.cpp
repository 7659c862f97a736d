#include "ui/planning/planning_toolbar.h"

#include "core/mission/planner_kinds.h"
#include "core/sensor/camera.h"
#include "ui/commands/set_planner_options_command.h"
#include "ui/mission_document.h"
#include "ui/planning/plan_controller.h"

#include <QAction>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QMessageBox>
#include <QSettings>
#include <QStandardItemModel>

namespace pf::ui {

namespace {
QIcon icon(const char* name) { return QIcon(QStringLiteral(":/icons/%1.svg").arg(QLatin1String(name))); }
} // namespace

PlanningToolBar::PlanningToolBar(MissionDocument* doc, PlanController* planner, QAction* exportRoutes,
                                 bool interactive, QWidget* parent)
    : QToolBar(tr("Planning"), parent), m_doc(doc), m_planner(planner), m_interactive(interactive) {
    setObjectName(QStringLiteral("PlanningToolBar"));
    setIconSize(QSize(22, 22));

    m_plan = new QAction(icon("plan"), tr("&Plan now"), this);
    connect(m_plan, &QAction::triggered, this, &PlanningToolBar::planNow);
    m_plan->setShortcut(QKeySequence(Qt::Key_F5));
    m_plan->setToolTip(tr("Plan the mission (F5)"));
    m_cancel = new QAction(icon("cancel"), tr("&Cancel planning"), this);
    connect(m_cancel, &QAction::triggered, m_planner, &PlanController::cancel);
    m_cancel->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F5));
    m_cancel->setEnabled(false);
    connect(m_planner, &PlanController::busyChanged, m_cancel, &QAction::setEnabled);
    m_autoPlan = new QAction(tr("Plan &automatically after edits"), this);
    m_autoPlan->setCheckable(true);
    m_autoPlan->setChecked(QSettings().value(QStringLiteral("plan/auto"), true).toBool());
    m_planner->setAutoPlan(m_autoPlan->isChecked());
    connect(m_autoPlan, &QAction::toggled, this, [this](bool on) {
        m_planner->setAutoPlan(on);
        QSettings().setValue(QStringLiteral("plan/auto"), on);
    });

    m_plannerBox = new QComboBox;
    m_plannerBox->setObjectName(QStringLiteral("PlannerBox"));
    m_plannerBox->setToolTip(tr("Coverage planner"));
    for (const auto& k : mission::plannerKinds()) {
        m_plannerBox->addItem(plannerName(k.kind), int(k.kind));
        m_plannerBox->setItemData(m_plannerBox->count() - 1, QString::fromLatin1(k.summary), Qt::ToolTipRole);
    }
    // Keep inside area, one click away: waypoints stay inside the area (as far as each photo still
    // sees the ground it is responsible for).
    m_keepInside = new QAction(icon("keep_inside"), tr("Keep inside area"), this);
    m_keepInside->setObjectName(QStringLiteral("KeepInsideAction"));
    m_keepInside->setCheckable(true);
    m_keepInside->setToolTip(
        tr("Keep inside area: off, lanes end where the photos cover the boundary, so waypoints may lie "
           "outside the area; on, waypoints stay within it"));
    connect(m_keepInside, &QAction::triggered, this, [this](bool on) {
        auto o = m_doc->mission().options;
        if (o.keepInsideArea == on) return;
        o.keepInsideArea = on;
        m_doc->undoStack()->push(new SetPlannerOptionsCommand(
            m_doc, o, on ? tr("Keep waypoints inside the area") : tr("Let lanes end beyond the area")));
    });
    // A second pass across the first: two independent views of every point, for 3D models.
    m_doubleGrid = new QAction(icon("double_grid"), tr("Double grid"), this);
    m_doubleGrid->setObjectName(QStringLiteral("DoubleGridAction"));
    m_doubleGrid->setCheckable(true);
    m_doubleGrid->setToolTip(
        tr("Double grid: a second pass with lanes at 90° to the first, each pass covering the "
           "whole area (two independent views of every point, for 3D models)"));
    connect(m_doubleGrid, &QAction::triggered, this, [this](bool on) {
        auto o = m_doc->mission().options;
        if (o.doubleGrid == on)
            return;
        o.doubleGrid = on;
        m_doc->undoStack()->push(
            new SetPlannerOptionsCommand(m_doc, o, on ? tr("Double grid") : tr("Single grid")));
    });
    m_angleBox = new QDoubleSpinBox;
    m_angleBox->setObjectName(QStringLiteral("GridAngleBox"));
    m_angleBox->setToolTip(tr("Grid angle in degrees from east; Auto tries many angles and keeps the fastest plan"));
    m_angleBox->setRange(-1, 179);
    m_angleBox->setDecimals(0);
    m_angleBox->setSingleStep(5);
    m_angleBox->setSuffix(QStringLiteral("°"));
    m_angleBox->setSpecialValueText(tr("Auto angle"));
    m_angleBox->setKeyboardTracking(false);
    connect(m_plannerBox, QOverload<int>::of(&QComboBox::activated), this, [this](int i) {
        auto o = m_doc->mission().options;
        const auto kind = mission::PlannerKind(m_plannerBox->itemData(i).toInt());
        if (o.planner == kind) return;
        if (!m_planner->plannerRefusal(kind).isEmpty()) {
            syncControls(); // not offered: the mission keeps its planner
            return;
        }
        o.planner = kind;
        m_doc->undoStack()->push(new SetPlannerOptionsCommand(m_doc, o, tr("Planner %1").arg(plannerName(kind))));
    });
    connect(m_angleBox, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        auto o = m_doc->mission().options;
        std::optional<double> angle;
        if (v >= 0) angle = v;
        if (o.gridAngleDeg == angle) return;
        o.gridAngleDeg = angle;
        m_doc->undoStack()->push(new SetPlannerOptionsCommand(
            m_doc, o, angle ? tr("Grid angle %1°").arg(*angle, 0, 'f', 0) : tr("Automatic grid angle")));
    });
    makeSafetyMarginBox();
    makeCameraTiltBox();
    explainOptions();
    connect(m_doc, &MissionDocument::optionsChanged, this, &PlanningToolBar::syncControls);
    connect(m_doc, &MissionDocument::missionReset, this, &PlanningToolBar::syncControls);
    // A planner flying over the no-fly zones is offered only where it crosses none (as in Compare).
    connect(m_doc, &MissionDocument::changed, this, &PlanningToolBar::syncControls);
    connect(m_planner, &PlanController::comparisonChanged, this, &PlanningToolBar::syncControls);

    addAction(m_plan);
    addAction(m_cancel);
    addWidget(m_plannerBox);
    addWidget(m_angleBox);
    addWidget(m_marginBox);
    addAction(m_keepInside);
    addAction(m_doubleGrid);
    addWidget(m_tiltBox);
    addAction(exportRoutes);
    syncControls();
}

void PlanningToolBar::syncControls() {
    const auto& o = m_doc->mission().options;
    const QSignalBlocker b1(m_plannerBox), b2(m_angleBox);
    if (auto* items = qobject_cast<QStandardItemModel*>(m_plannerBox->model()))
        for (int i = 0; i < m_plannerBox->count(); ++i) {
            const auto& info = mission::plannerKinds()[std::size_t(i)];
            const QString refusal =
                info.kind == o.planner ? QString() : m_planner->plannerRefusal(info.kind);
            items->item(i)->setEnabled(refusal.isEmpty());
            items->item(i)->setToolTip(
                refusal.isEmpty() ? QString::fromLatin1(info.summary)
                                  : QStringLiteral("<p>%1</p>").arg(refusal.toHtmlEscaped()));
        }
    m_plannerBox->setCurrentIndex(m_plannerBox->findData(int(o.planner)));
    m_keepInside->setChecked(o.keepInsideArea);
    m_doubleGrid->setChecked(o.doubleGrid);
    m_angleBox->setValue(o.gridAngleDeg ? *o.gridAngleDeg : -1.0);
    const QSignalBlocker b3(m_marginBox), b4(m_tiltBox);
    m_marginBox->setValue(o.safetyMarginM);
    m_tiltBox->setValue(o.cameraTiltDeg);
}

// The keep-out distance around the no-fly zones, an undoable mission edit like the other options.
void PlanningToolBar::makeSafetyMarginBox() {
    m_marginBox = new QDoubleSpinBox;
    m_marginBox->setObjectName(QStringLiteral("SafetyMarginBox"));
    m_marginBox->setRange(0, 1000);
    m_marginBox->setDecimals(1);
    m_marginBox->setSingleStep(1);
    m_marginBox->setPrefix(tr("Margin "));
    m_marginBox->setSuffix(tr(" m"));
    m_marginBox->setKeyboardTracking(false);
    connect(
        m_marginBox, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this](double v) {
            auto o = m_doc->mission().options;
            if (o.safetyMarginM == v)
                return;
            o.safetyMarginM = v;
            m_doc->undoStack()->push(
                new SetPlannerOptionsCommand(m_doc, o, tr("Safety margin %1 m").arg(v, 0, 'f', 1)));
        });
}

// The cameras' forward tilt for oblique photos, an undoable mission edit; 0 shows "Nadir".
void PlanningToolBar::makeCameraTiltBox() {
    m_tiltBox = new QDoubleSpinBox;
    m_tiltBox->setObjectName(QStringLiteral("CameraTiltBox"));
    m_tiltBox->setRange(0, sensor::kMaxCameraTiltDeg);
    m_tiltBox->setDecimals(0);
    m_tiltBox->setSingleStep(5);
    m_tiltBox->setPrefix(tr("Tilt "));
    m_tiltBox->setSuffix(QStringLiteral("°"));
    m_tiltBox->setSpecialValueText(tr("Nadir photos"));
    m_tiltBox->setKeyboardTracking(false);
    connect(m_tiltBox, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        auto o = m_doc->mission().options;
        if (o.cameraTiltDeg == v)
            return;
        o.cameraTiltDeg = v;
        m_doc->undoStack()->push(new SetPlannerOptionsCommand(
            m_doc, o, v == 0 ? tr("Nadir photos") : tr("Camera tilt %1°").arg(v, 0, 'f', 0)));
    });
}

// Tool tips say what a control is; "What's this?" (Shift+F1) says what it does to the plan, in the
// words of the user guide (docs/user-guide.md, docs/planning.md).
void PlanningToolBar::explainOptions() {
    m_plannerBox->setWhatsThis(tr(
        "<p><b>Coverage planner.</b> <i>Auto</i> (the default) plans each aircraft's region with "
        "sweep, stride and raster and keeps the plan it flies soonest, home to home. <i>Sweep</i> "
        "lays straight lanes on the exact area round the no-fly zones; <i>Stride</i> follows the "
        "area's limits with long straight strides and no jumps; <i>Raster</i> scans row by row and "
        "may jump; <i>Wavefront</i> climbs a distance map. <i>Lawnmower</i> is a ground station's "
        "Survey pattern: it flies straight over no-fly zones, so it is offered only where it "
        "crosses none. Plan ▸ Compare planners shows them side by side.</p>"));
    m_angleBox->setWhatsThis(tr(
        "<p><b>Grid angle.</b> The direction of the grid and its lanes, counter-clockwise from "
        "east about the area's centre. <i>Auto angle</i> tries 0 to 175° in 5° steps and the "
        "directions of the area's two longest edges, and keeps the plan with the shortest flight "
        "time.</p>"));
    m_marginBox->setToolTip(
        tr("Safety margin: no waypoint or leg comes closer than this to a no-fly zone"));
    m_marginBox->setWhatsThis(
        tr("<p><b>Safety margin</b> (default 5 m). The keep-out distance around every no-fly zone: "
           "no waypoint lies inside a zone or its margin, and a leg that would cross one takes the "
           "shortest safe detour. The ground inside the margin is photographed from outside it as "
           "far as the footprints reach; ground no footprint reaches is reported in m². The route "
           "check before export and upload uses the same margin.</p>"));
    m_keepInside->setWhatsThis(tr(
        "<p><b>Keep inside area.</b> Off: lanes end where the photos cover the area's boundary, "
        "so waypoints may lie outside the area (Problems says how far). On: waypoints stay inside "
        "the area as far as each photo still sees the ground it is responsible for; what cannot "
        "be kept covered is reported.</p>"));
    m_doubleGrid->setWhatsThis(tr(
        "<p><b>Double grid.</b> Plans the area twice: the first pass as a single grid, the second "
        "with straight lanes at 90° to the first, flown after it, so every point is seen from two "
        "directions (for 3D models). The coverage check counts each pass on its own. A corridor "
        "is flown once.</p>"));
    m_tiltBox->setToolTip(tr("Camera tilt: oblique photos, every camera tilted forward along the "
                             "lanes from straight down (0: nadir photos)"));
    m_tiltBox->setWhatsThis(tr(
        "<p><b>Camera tilt</b> (0 to 45°). Tilts every camera forward from straight down, along "
        "the direction of flight, for oblique photos of façades and slopes; with <i>Double "
        "grid</i> every point is seen from four directions (for 3D models). Footprints and "
        "overlaps are those of the tilted camera: each photo sees the ground ahead of the "
        "aircraft, so lanes start that far before the ground they photograph, and the route "
        "check keeps the aircraft, not the photo, out of the no-fly margins. The exports point "
        "the gimbal at -90° + the tilt. Multirotors only, area surveys only.</p>"));
}

void PlanningToolBar::planNow() {
    if (m_doc->anyRouteEdited() && m_interactive) {
        const auto answer = QMessageBox::question(
            parentWidget(), tr("Replace edited paths?"),
            tr("Some paths were edited by hand. A new plan replaces them. Plan now and replace the edited paths?"),
            QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel);
        if (answer != QMessageBox::Yes) return;
        m_planner->planNow(/*replaceEdited=*/true); // consent given
        return;
    }
    m_planner->planNow();
}

} // namespace pf::ui
