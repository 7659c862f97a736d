#include "ui/panels/problems_panel.h"

#include "ui/map/mission_layer.h"
#include "ui/map/plan_layer.h"
#include "ui/mission_document.h"
#include "ui/planning/plan_controller.h"

#include <QStyle>

namespace pf::ui {

namespace {
enum Role { KindRole = Qt::UserRole, IndexRole, WaypointRole, SeverityRole };
enum Kind { NoTarget, AreaTarget, NoFlyTarget, WaypointTarget };
} // namespace

ProblemsPanel::ProblemsPanel(MissionDocument* doc, MissionLayer* shapes, PlanController* planner, PlanLayer* plan,
                             QWidget* parent)
    : QListWidget(parent), m_doc(doc), m_shapes(shapes), m_planner(planner), m_plan(plan) {
    setObjectName(QStringLiteral("ProblemsList"));
    setWordWrap(true);
    connect(this, &QListWidget::itemClicked, this, [this](QListWidgetItem* item) {
        switch (item->data(KindRole).toInt()) {
        case AreaTarget: emit areaActivated(); break;
        case NoFlyTarget: emit noFlyZoneActivated(item->data(IndexRole).toInt()); break;
        case WaypointTarget: emit waypointActivated(item->data(IndexRole).toInt(), item->data(WaypointRole).toInt()); break;
        default: break;
        }
    });
    // What an item is about is selected on the map.
    connect(this, &ProblemsPanel::areaActivated, this, [this] { m_shapes->select(ShapeRef::area()); });
    connect(this, &ProblemsPanel::noFlyZoneActivated, this, [this](int i) { m_shapes->select(ShapeRef::noFly(i)); });
    connect(this, &ProblemsPanel::waypointActivated, this, [this](int r, int w) { m_plan->selectWaypoints(r, {w}); });
    connect(m_shapes, &MissionLayer::problemsChanged, this, &ProblemsPanel::refresh);
    connect(m_planner, &PlanController::planChanged, this, &ProblemsPanel::refresh);
    connect(m_plan, &PlanLayer::routeProblemsChanged, this, &ProblemsPanel::refresh);
}

ProblemsPanel::Severity ProblemsPanel::severityOf(int row) const {
    return Severity(item(row)->data(SeverityRole).toInt());
}

QListWidgetItem* ProblemsPanel::add(const QString& text, const QString& source, Severity severity) {
    const auto& m = m_doc->mission();
    auto* item = new QListWidgetItem(text, this);
    item->setData(KindRole, NoTarget);
    item->setData(SeverityRole, int(severity));
    // Which shape a message names: a no-fly zone by its name, else the area.
    for (std::size_t i = 0; i < m.noFlyZones.size(); ++i) {
        const QString name = QString::fromStdString(m.noFlyZones[i].name);
        if (!name.isEmpty() && text.contains(name)) {
            item->setData(KindRole, NoFlyTarget);
            item->setData(IndexRole, int(i));
        }
    }
    if (item->data(KindRole).toInt() == NoTarget && text.contains(tr("area"), Qt::CaseInsensitive))
        item->setData(KindRole, AreaTarget);
    item->setToolTip(source);
    const auto icon = severity == Severity::Error     ? QStyle::SP_MessageBoxCritical
                      : severity == Severity::Warning ? QStyle::SP_MessageBoxWarning
                                                      : QStyle::SP_MessageBoxInformation;
    item->setIcon(style()->standardIcon(icon));
    return item;
}

void ProblemsPanel::refresh() {
    clear();
    for (const QString& p : m_shapes->problems())
        add(p, tr("mission shapes"), Severity::Warning);
    // A mission that cannot be planned: one item per reason.
    for (const QString& line : m_planner->lastError().split(QLatin1Char('\n'), Qt::SkipEmptyParts))
        add(line, tr("planner"), Severity::Error);
    if (const auto& plan = m_planner->plan()) {
        for (const auto& w : plan->warnings)
            add(QString::fromStdString(w), tr("planner"), Severity::Info);
        if (!plan->uncovered.empty())
            add(tr("%1 m² of the area in %n patch(es) is seen by no photo (hatched red on the map)", nullptr,
                   int(plan->uncovered.size()))
                    .arg(plan->uncoveredAreaM2, 0, 'f', 0),
                tr("coverage check"), Severity::Warning);
    }
    // The route check of every route shown (what export checks too).
    const auto& issues = m_plan->issues();
    const auto& routes = m_doc->routes();
    for (std::size_t r = 0; r < issues.size() && r < routes.size(); ++r) {
        const QString name = QString::fromStdString(routes[r].route.aircraft);
        auto flag = [&](int w, const QString& text) {
            auto* item = add(text, tr("route check"), Severity::Error);
            item->setData(KindRole, WaypointTarget);
            item->setData(IndexRole, int(r));
            item->setData(WaypointRole, w);
        };
        const auto& is = issues[r];
        const int n = int(is.waypoint.size());
        if (!is.fromHome.isEmpty()) flag(0, tr("%1, take-off: %2").arg(name, is.fromHome));
        for (int w = 0; w < n; ++w) {
            if (!is.waypoint[std::size_t(w)].isEmpty())
                flag(w, tr("%1, waypoint %2: %3").arg(name).arg(w + 1).arg(is.waypoint[std::size_t(w)]));
            if (w < int(is.leg.size()) && !is.leg[std::size_t(w)].isEmpty())
                flag(w, tr("%1, waypoint %2: %3").arg(name).arg(w + 1).arg(is.leg[std::size_t(w)]));
        }
        if (!is.toHome.isEmpty()) flag(n - 1, tr("%1, landing: %2").arg(name, is.toHome));
        // Why waypoints lie outside the area, and what to do about it.
        if (is.check.outsideArea > 0 && !m_doc->mission().options.keepInsideArea) {
            auto* item = add(tr("%1: %n waypoint(s) outside the area (up to %2 m): lanes end where the photos "
                                "cover the boundary; turn on Keep inside area to stay within it.",
                                nullptr, is.check.outsideArea)
                                 .arg(name)
                                 .arg(is.check.farthestOutsideM, 0, 'f', is.check.farthestOutsideM < 10 ? 1 : 0),
                             tr("route check: a note, not an error"), Severity::Info);
            item->setData(KindRole, WaypointTarget);
            item->setData(IndexRole, int(r));
            item->setData(WaypointRole, is.check.farthestOutside);
        }
    }
    emit countChanged(count());
}

} // namespace pf::ui
