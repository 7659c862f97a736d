#include "ui/panels/problems_panel.h"

#include "core/mission/plan_messages.h"
#include "ui/map/mission_layer.h"
#include "ui/map/plan_layer.h"
#include "ui/mission_document.h"
#include "ui/planning/plan_controller.h"

#include <QStyle>

namespace pf::ui {

namespace {
enum Role { KindRole = Qt::UserRole, IndexRole, WaypointRole, SeverityRole, WaypointsRole };
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
        case WaypointTarget:
            // The waypoint is brought into view; every waypoint the item lists is selected.
            emit waypointActivated(item->data(IndexRole).toInt(), item->data(WaypointRole).toInt());
            m_plan->selectWaypoints(item->data(IndexRole).toInt(), waypointsOf(row(item)));
            break;
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
    connect(m_planner, &PlanController::busyChanged, this, &ProblemsPanel::refresh);
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
    if (m_planner->isBusy() && m_planner->isOutdated()) {
        // What the previous plan got wrong no longer says anything about the plan under way.
        add(tr("Planning the changed mission: the previous plan's problems are no longer listed."),
            tr("planner"), Severity::Info);
        emit countChanged(count());
        return;
    }
    const int first = count();
    addPlanItems();
    addRouteItems();
    if (m_planner->isOutdated()) {
        // The plan shown is not the mission's: its problems are greyed like its paths on the map.
        for (int i = first; i < count(); ++i) {
            item(i)->setForeground(palette().brush(QPalette::Disabled, QPalette::Text));
            item(i)->setToolTip(
                tr("%1 — of the outdated plan: plan again (F5)").arg(item(i)->toolTip()));
        }
    }
    emit countChanged(count());
}

void ProblemsPanel::addPlanItems() {
    const auto& plan = m_planner->plan();
    if (!plan)
        return;
    // The ground no photo sees is said once, with where it is on the map (as the planner words
    // it: a double grid says which pass).
    std::string uncovered = mission::uncoveredMessage(*plan);
    for (const auto& w : plan->warnings) {
        const bool same = !uncovered.empty() && w.size() >= uncovered.size() &&
                          w.compare(w.size() - uncovered.size(), uncovered.size(), uncovered) == 0;
        if (same)
            uncovered = w;
        else
            add(QString::fromStdString(w), tr("planner"), Severity::Warning);
    }
    for (const auto& n : plan->notes)
        add(QString::fromStdString(n), tr("planner"), Severity::Info);
    if (!uncovered.empty())
        add(tr("%1 (hatched red on the map)").arg(QString::fromStdString(uncovered)),
            tr("coverage check"), Severity::Warning);
}

void ProblemsPanel::addRouteItems() {
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
        for (const auto& g : is.check.outside)
            addOutsideItem(int(r), name, g);
    }
}

// Waypoints outside the area, one item per reason, each true of every waypoint it selects.
void ProblemsPanel::addOutsideItem(int route, const QString& name, const mission::OutsideGroup& g) {
    using mission::OutsideReason;
    const int n = int(g.waypoints.size());
    const QString far = QString::number(g.farthestM, 'f', g.farthestM < 10 ? 1 : 0);
    const QString keepInside = m_doc->mission().options.keepInsideArea
                                   ? QStringLiteral(".")
                                   : tr("; turn on Keep inside area to stay within it.");
    QString text;
    Severity severity = Severity::Info;
    switch (g.reason) {
    case OutsideReason::CoversBoundary:
        text = tr("%1: %n waypoint(s) outside the area (up to %2 m) whose photos still see it: "
                  "lanes end where the "
                  "photos cover the boundary",
                  nullptr, n)
                   .arg(name, far) +
               keepInside;
        break;
    case OutsideReason::SeesNothing:
        text = tr("%1: %n waypoint(s) outside the area (up to %2 m) whose photos see none of it",
                  nullptr, n)
                   .arg(name, far) +
               keepInside;
        severity = Severity::Warning;
        break;
    case OutsideReason::Unknown:
        text = tr("%1: %n waypoint(s) outside the area (up to %2 m).", nullptr, n).arg(name, far);
        break;
    case OutsideReason::PlaneTurn:
        text = tr("%1: %n turn waypoint(s) outside the area (up to %2 m): the plane turns beyond the "
                  "lane ends on arcs of at least its turn radius, without photos.",
                  nullptr, n)
                   .arg(name, far);
        break;
    case OutsideReason::Transit:
        text = g.atHomeOnly ? tr("%1: %n transit waypoint(s) at home, %2 m outside the area: the "
                                 "flight comes back there "
                                 "between two batteries.",
                                 nullptr, n)
                                  .arg(name, far)
                            : tr("%1: %n transit waypoint(s) outside the area (up to %2 m), flown "
                                 "without photos on the way "
                                 "to and from home or around no-fly zones.",
                                 nullptr, n)
                                  .arg(name, far);
        break;
    }
    auto* item = add(text, tr("route check: a note, not an error"), severity);
    item->setData(KindRole, WaypointTarget);
    item->setData(IndexRole, route);
    item->setData(WaypointRole, g.farthest);
    item->setData(WaypointsRole,
                  QVariant::fromValue(QList<int>(g.waypoints.begin(), g.waypoints.end())));
}

QList<int> ProblemsPanel::waypointsOf(int row) const {
    if (row < 0 || row >= count() || item(row)->data(KindRole).toInt() != WaypointTarget)
        return {};
    const QVariant list = item(row)->data(WaypointsRole);
    return list.isValid() ? list.value<QList<int>>()
                          : QList<int>{item(row)->data(WaypointRole).toInt()};
}

} // namespace pf::ui
