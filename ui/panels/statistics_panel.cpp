#include "ui/panels/statistics_panel.h"

#include "core/fleet/aircraft.h"
#include "core/geo/local_frame.h"
#include "core/mission/plan_messages.h"
#include "core/mission/planner_kinds.h"
#include "ui/commands/set_planner_options_command.h"
#include "ui/mission_document.h"
#include "ui/planning/plan_controller.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTabWidget>
#include <QTableWidget>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <optional>

namespace pf::ui {

namespace {

const QString kDash = QStringLiteral("–");

// The turns of the flown routes (what the aircraft stops for), as the plan's own table and the CLI
// show them; the cell paths' turns only when no route was flown out.
int flownTurns(const mission::PlanTotals& t) { return t.flightTurns > 0 ? t.flightTurns : t.turns; }

QString minutes(double seconds) {
    const int s = int(std::lround(seconds));
    return QStringLiteral("%1:%2").arg(s / 60).arg(s % 60, 2, 10, QLatin1Char('0'));
}

// A plane's turns in words: the length and time flown on its turn arcs and run-ins (the legs that
// begin or end at a turn waypoint, at the cruise speed: the one flight-time model of a plane), its
// turn radius, and how it lands. Empty for a multirotor.
QString planeTurnsTip(const route::Route& r, const mission::AircraftConfig& a,
                      const geo::LocalFrame& frame) {
    if (!fleet::fliesAsPlane(a.kind) || a.cruiseSpeedMps <= 0)
        return {};
    double turnM = 0.0;
    for (std::size_t i = 0; i + 1 < r.waypoints.size(); ++i)
        if (r.waypoints[i].kind == route::WaypointKind::Turn ||
            r.waypoints[i + 1].kind == route::WaypointKind::Turn)
            turnM += (frame.toLocal(r.waypoints[i + 1].position) - frame.toLocal(r.waypoints[i].position)).norm();
    const double radiusM = fleet::minTurnRadiusM(a.plane, a.cruiseSpeedMps);
    const QString landing =
        a.kind == fleet::AircraftKind::Vtol
            ? QObject::tr("it lands vertically (NAV_VTOL_LAND) at the landing point")
            : QObject::tr("it lands along a 400 m approach into the landing heading set on export "
                          "(else along the first lane), kept out of the no-fly margins");
    return QObject::tr("Turn arcs and run-ins: %1 km, %2 min at %3 m/s (arcs of at least %4 m "
                       "radius; no photo in a turn). After the survey %5.")
        .arg(turnM / 1000.0, 0, 'f', 2)
        .arg(minutes(turnM / a.cruiseSpeedMps))
        .arg(a.cruiseSpeedMps, 0, 'f', 1)
        .arg(radiusM, 0, 'f', 0)
        .arg(landing);
}

QTableWidgetItem* cell(const QString& text,
                       Qt::Alignment align = Qt::AlignRight | Qt::AlignVCenter) {
    auto* item = new QTableWidgetItem(text);
    item->setTextAlignment(int(align));
    item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    return item;
}

QTableWidget* makeTable(const QStringList& headers) {
    auto* t = new QTableWidget(0, headers.size());
    t->setHorizontalHeaderLabels(headers);
    t->verticalHeader()->hide();
    t->verticalHeader()->setDefaultSectionSize(22);
    // The figures always show in full; the name column takes the rest and elides a long name.
    t->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    t->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    t->horizontalHeader()->setMinimumSectionSize(36);
    t->setTextElideMode(Qt::ElideRight);
    t->setVerticalScrollBarPolicy(Qt::ScrollBarAsNeeded);
    t->setEditTriggers(QAbstractItemView::NoEditTriggers);
    t->setSelectionMode(QAbstractItemView::NoSelection);
    return t;
}

// An aircraft's Cover %: the share of its part of the area the independent check saw covered (by
// the photos of every aircraft: along the borders they share photos), marked "≤" when small patches
// that the plan does not list could not be given to an aircraft.
QTableWidgetItem* coverCell(const mission::MissionPlan& plan, std::size_t k) {
    const auto& ap = plan.aircraft[k];
    const auto cover = mission::aircraftCoverage(plan, k);
    if (!cover) {
        auto* item = cell(kDash);
        item->setToolTip(StatisticsPanel::tr("No coverage check of %1's part")
                             .arg(QString::fromStdString(ap.aircraft)));
        return item;
    }
    const double unattributed = mission::unattributedUncoveredM2(plan);
    const bool bound = unattributed >= 0.5;
    auto* item = cell((bound ? QStringLiteral("≤ ") : QString()) +
                      QString::fromStdString(mission::coveragePercentText(
                          *cover, ap.uncoveredAreaM2 + (bound ? 1 : 0))));
    QString tip = StatisticsPanel::tr(
                      "Share of %1's part of the area (%2 m² without the no-fly zones) seen by the "
                      "photos of every aircraft: %3 m² seen by none")
                      .arg(QString::fromStdString(ap.aircraft))
                      .arg(ap.admissibleAreaM2, 0, 'f', 0)
                      .arg(ap.uncoveredAreaM2, 0, 'f', ap.uncoveredAreaM2 < 10 ? 1 : 0);
    if (bound)
        tip += StatisticsPanel::tr(", and some of %1 m² in small patches not given to an aircraft")
                   .arg(unattributed, 0, 'f', 0);
    item->setToolTip(tip);
    return item;
}

// One line below the comparison for a planner shown as the yardstick only (the tooltip of its
// button says more).
QString yardstickNote(mission::PlannerKind kind, const std::vector<PlannerComparisonRow>& rows,
                      bool outdated) {
    for (const auto& row : rows)
        if (!outdated && row.planner == kind && row.ok && !row.zonesCrossed.isEmpty())
            return StatisticsPanel::tr(
                       "%1 is the yardstick here: its routes cross %2, so it is not offered as "
                       "this mission's planner.")
                .arg(plannerName(kind), row.zonesCrossed.join(QStringLiteral(", ")));
    return StatisticsPanel::tr(
               "%1 is the yardstick here: it flies straight over no-fly zones (compare to "
               "see which it crosses).")
        .arg(plannerName(kind));
}

QLabel* banner() {
    auto* l = new QLabel;
    l->setWordWrap(true);
    l->setStyleSheet(QStringLiteral("QLabel { color: #6b3a00; background: #ffe8b0; padding: 2px 6px; "
                                    "border-radius: 3px; font-weight: bold; }"));
    l->hide();
    return l;
}

} // namespace

StatisticsPanel::StatisticsPanel(MissionDocument* doc, PlanController* planner, QWidget* parent)
    : QWidget(parent), m_doc(doc), m_planner(planner) {
    setObjectName(QStringLiteral("StatisticsPanel"));
    m_state = banner();
    m_state->setObjectName(QStringLiteral("PlanStateLabel"));
    m_stats = makeTable({tr("Aircraft"), tr("Photos"), tr("km"), tr("Time"), tr("Turns"),
                         tr("Sorties"), tr("Cover %"), tr("Plan ms")});
    m_compare = makeTable({tr("Planner"), tr("Photos"), tr("km"), tr("Time"), tr("Turns"),
                           tr("Cover %"), tr("No-fly"), tr("Plan ms"), QString()});
    const QStringList tips = {
        QString(),
        tr("Photos taken"),
        tr("Distance flown, home to home"),
        tr("Flight time (min:s), transit and every sortie included; in total the "
           "longest aircraft's, as they fly at the same time"),
        tr("Turns"),
        tr("Sorties: batteries needed"),
        tr("Share of its part of the area seen by the real footprints of the photos; in "
           "total of the whole area (the independent coverage check)"),
        tr("Time to plan this aircraft's own part (its grid, path and photos); the "
           "total adds them up. Sharing the area between the aircraft comes on top "
           "(see below the table)")};
    for (int c = 1; c < tips.size(); ++c)
        m_stats->horizontalHeaderItem(c)->setToolTip(tips[c]);
    m_compare->horizontalHeaderItem(CNoFly)->setToolTip(
        tr("No-fly crossings: waypoints and legs (from and back to home included) inside a no-fly "
           "zone or its safety margin. Export asks before writing such routes."));
    m_compare->horizontalHeaderItem(CPlanMs)->setToolTip(tr("Time to plan the whole mission with this planner"));
    m_planTime = new QLabel;
    m_planTime->setObjectName(QStringLiteral("PlanTimeLabel"));
    m_planTime->setWordWrap(true);
    m_planTime->setStyleSheet(QStringLiteral("QLabel { color: palette(dark); }"));
    m_compareButton =
        new QPushButton(QIcon(QStringLiteral(":/icons/compare.svg")), tr("Compare planners"));
    m_compareButton->setToolTip(tr("Plan the current mission with every planner and compare them"));
    m_compareState = new QLabel;
    m_compareState->setWordWrap(true);
    auto* meaning = new QLabel(
        tr("Every planner on this same mission; figures for the whole mission (time: the longest flight; "
           "No-fly: waypoints and legs in a no-fly margin). <i>Use</i> makes it the mission's planner "
           "(Ctrl+Z undoes)."));
    meaning->setObjectName(QStringLiteral("ComparisonMeaning"));
    meaning->setWordWrap(true);
    meaning->setStyleSheet(QStringLiteral("QLabel { color: palette(dark); }"));
    // Room for a header and two rows each.
    m_stats->setMinimumHeight(26 + 2 * 22 + 4);
    m_compare->setMinimumHeight(26 + 2 * 22 + 4);
    // Two pages, so that neither the figures nor the comparison are squeezed in a short dock.
    auto* planPage = new QWidget;
    auto* pl = new QVBoxLayout(planPage);
    pl->setContentsMargins(2, 2, 2, 2);
    pl->setSpacing(3);
    pl->addWidget(m_state);
    pl->addWidget(m_stats, 1);
    pl->addWidget(m_planTime);
    auto* comparePage = new QWidget;
    auto* cl = new QVBoxLayout(comparePage);
    cl->setContentsMargins(2, 2, 2, 2);
    cl->setSpacing(3);
    auto* row = new QHBoxLayout;
    row->addWidget(m_compareButton);
    row->addWidget(m_compareState, 1);
    cl->addLayout(row);
    cl->addWidget(meaning);
    cl->addWidget(m_compare, 1);
    m_compareNote = new QLabel;
    m_compareNote->setObjectName(QStringLiteral("CompareNote"));
    m_compareNote->setWordWrap(true);
    m_compareNote->setStyleSheet(QStringLiteral("QLabel { color: #6b3a00; }"));
    m_compareNote->hide();
    cl->addWidget(m_compareNote);
    m_pages = new QTabWidget;
    m_pages->setObjectName(QStringLiteral("StatisticsPages"));
    m_pages->setDocumentMode(true);
    m_pages->addTab(planPage, tr("Plan"));
    m_pages->addTab(comparePage, tr("Compare planners"));
    auto* lay = new QVBoxLayout(this);
    lay->setContentsMargins(2, 2, 2, 2);
    lay->addWidget(m_pages);
    connect(m_compareButton, &QPushButton::clicked, m_planner, &PlanController::compare);
    connect(m_planner, &PlanController::planChanged, this, &StatisticsPanel::refreshStatistics);
    connect(m_planner, &PlanController::busyChanged, this, &StatisticsPanel::refreshState);
    connect(m_planner, &PlanController::pendingPlanChanged, this, &StatisticsPanel::refreshState);
    connect(m_doc, &MissionDocument::routesChanged, this, &StatisticsPanel::refreshStatistics);
    connect(m_doc, &MissionDocument::changed, this, &StatisticsPanel::refreshState);
    connect(m_doc, &MissionDocument::changed, this, &StatisticsPanel::refreshComparison);
    connect(m_planner, &PlanController::comparisonChanged, this,
            &StatisticsPanel::refreshComparison);
    refreshStatistics();
    refreshComparison();
}

QString StatisticsPanel::stateText() const {
    return m_state->isHidden() ? QString() : m_state->text();
}

void StatisticsPanel::refreshState() {
    QString text;
    if (m_planner->isOutdated()) {
        const QString why = tr("Outdated: the mission changed after this plan was made.");
        if (m_planner->hasPendingPlan())
            text = why + QLatin1Char(' ') + tr("A new plan waits: replace or keep the edited paths (status bar).");
        else if (m_planner->isBusy())
            text = why + QLatin1Char(' ') + tr("Planning the new one…");
        else if (!m_planner->lastError().isEmpty())
            text = why + QLatin1Char(' ') + tr("The new one could not be made (see Problems).");
        else
            text = why + QLatin1Char(' ') + tr("Press F5 to plan it.");
    }
    m_state->setText(text);
    m_state->setHidden(text.isEmpty());
    m_pages->setTabText(0, text.isEmpty() ? tr("Plan") : tr("Plan (outdated)"));
    // The figures of an outdated plan are greyed like its paths on the map.
    m_stats->setEnabled(text.isEmpty());
}

void StatisticsPanel::refreshStatistics() {
    refreshState();
    m_stats->setRowCount(0);
    m_planTime->clear();
    const auto& plan = m_planner->plan();
    if (!plan)
        return;
    const auto& mission = m_doc->mission();
    StatTotals total;
    for (std::size_t k = 0; k < plan->aircraft.size(); ++k) {
        const auto& ap = plan->aircraft[k];
        const int r = m_stats->rowCount();
        m_stats->insertRow(r);
        QColor colour(Qt::gray);
        const mission::AircraftConfig* config = nullptr;
        for (const auto& a : mission.aircraft)
            if (a.name == ap.aircraft) {
                config = &a;
                colour = QColor(QString::fromStdString(a.colour));
            }
        bool edited = false;
        const route::Route* flown = nullptr;
        for (const auto& pr : m_doc->routes())
            if (pr.route.aircraft == ap.aircraft) {
                edited = pr.edited;
                flown = &pr.route;
            }
        auto* name = cell(QString::fromStdString(ap.aircraft) + (edited ? tr(" (edited)") : QString()),
                          Qt::AlignLeft | Qt::AlignVCenter);
        name->setToolTip(edited ? tr("%1: photos, distance and time measured on the route edited by hand")
                                      .arg(QString::fromStdString(ap.aircraft))
                                : QString::fromStdString(ap.aircraft));
        QPixmap swatch(12, 12);
        swatch.fill(colour);
        name->setIcon(QIcon(swatch));
        m_stats->setItem(r, Aircraft, name);
        const int waypoints = flown ? int(flown->waypoints.size()) : int(ap.route.waypoints.size());
        if (waypoints == 0) {
            // Nothing is flown: no figure would mean anything.
            for (int c = Photos; c < StatColumns; ++c)
                m_stats->setItem(r, c, cell(kDash));
            name->setToolTip(tr("%1 has no waypoint to fly").arg(QString::fromStdString(ap.aircraft)));
            continue;
        }
        // Batteries: flights of the usable endurance (the reserve kept) this aircraft's time needs.
        // The plan's sorties when the core cut the flight into them; else an estimate.
        const double timeS = ap.timeS > 0 ? ap.timeS : ap.metrics.estimatedTimeS;
        const double distanceM = ap.flightDistanceM > 0 ? ap.flightDistanceM : ap.metrics.pathLengthM;
        int batteries = std::max<int>(1, int(ap.sorties.size()));
        if (config) {
            const double usableS = config->enduranceMin * 60.0 * (1.0 - mission.options.batteryReserve);
            if (ap.sorties.empty() && usableS > 0)
                batteries = std::max(1, int(std::ceil(timeS / usableS)));
        }
        int photos = ap.metrics.photos;
        double shownDistanceM = distanceM, shownTimeS = timeS;
        if (edited && flown && plan->frame) {
            // An edited route: photos and distance are measured on it; the time changes with the
            // distance at cruise speed (the planned turn time is kept).
            photos = 0;
            double length = 0;
            std::optional<geo::Vec2> prev;
            if (flown->home)
                prev = plan->frame->toLocal(*flown->home);
            for (const auto& w : flown->waypoints) {
                photos += w.kind == route::WaypointKind::Photo ? 1 : 0;
                const geo::Vec2 p = plan->frame->toLocal(w.position);
                if (prev)
                    length += (p - *prev).norm();
                prev = p;
            }
            if (flown->home && prev)
                length += (plan->frame->toLocal(*flown->home) - *prev).norm();
            const double speed = flown->cruiseSpeedMps > 0 ? flown->cruiseSpeedMps : 10.0;
            shownTimeS = std::max(0.0, timeS + (length - distanceM) / speed);
            shownDistanceM = length;
        }
        total.batteries += batteries;
        total.photos += photos;
        // The flown route's turns (what the aircraft stops for), as the CLI shows them; the cell
        // path's count only where no route was made.
        const int turns = ap.flight.lengthM > 0 ? ap.flight.turns : ap.metrics.turns;
        total.turns += turns;
        total.distanceM += shownDistanceM;
        total.longestS = std::max(total.longestS, shownTimeS);
        total.planMs += ap.metrics.planningMs;
        m_stats->setItem(r, Photos, cell(QString::number(photos)));
        m_stats->setItem(r, Km, cell(QString::number(shownDistanceM / 1000.0, 'f', 2)));
        m_stats->setItem(r, Time, cell(minutes(shownTimeS)));
        m_stats->setItem(r, Turns, cell(QString::number(turns)));
        if (config && plan->frame)
            if (const QString tip = planeTurnsTip(flown ? *flown : ap.route, *config, *plan->frame);
                !tip.isEmpty()) {
                m_stats->item(r, Turns)->setToolTip(tip);
                m_stats->item(r, Time)->setToolTip(tip);
            }
        m_stats->setItem(r, Sorties, cell(QString::number(batteries)));
        m_stats->setItem(r, Cover, coverCell(*plan, k));
        m_stats->setItem(r, PlanMs, cell(QString::number(ap.metrics.planningMs, 'f', 0)));
    }
    addTotalRow(*plan, total);
}

void StatisticsPanel::addTotalRow(const mission::MissionPlan& plan, const StatTotals& total) {
    const auto& t = plan.totals;
    const int r = m_stats->rowCount();
    m_stats->insertRow(r);
    QFont bold = m_stats->font();
    bold.setBold(true);
    // Coverage in total: the core's independent check of the real footprints when it ran.
    const double cov = plan.coverageRatio > 0 ? 100.0 * plan.coverageRatio
                       : t.visitable > 0       ? 100.0 * t.cells / t.visitable
                                               : 0.0;
    const bool anything = total.photos > 0 || total.distanceM > 0;
    // Never "100.0" beside ground that no photo sees.
    const QString covText = plan.coverageRatio > 0
                                ? QString::fromStdString(mission::coveragePercentText(
                                      plan.coverageRatio, plan.uncoveredAreaM2))
                                : QString::number(cov, 'f', 1);
    const QStringList values = {tr("Total"),
                                anything ? QString::number(total.photos) : kDash,
                                anything ? QString::number(total.distanceM / 1000.0, 'f', 2) : kDash,
                                anything ? minutes(total.longestS) : kDash,
                                anything ? QString::number(total.turns) : kDash,
                                anything ? QString::number(total.batteries) : kDash,
                                anything ? covText : kDash,
                                QString::number(total.planMs, 'f', 0)};
    for (int c = 0; c < values.size(); ++c) {
        auto* item = cell(values[c], c == 0 ? Qt::AlignLeft | Qt::AlignVCenter
                                            : Qt::AlignRight | Qt::AlignVCenter);
        item->setFont(bold);
        m_stats->setItem(r, c, item);
    }
    m_stats->item(r, Time)->setToolTip(tr("The longest aircraft's flight: they fly at the same time"));
    m_stats->item(r, Cover)->setToolTip(tr("Share of the area seen by the real footprints of all photos"));
    const double wallS = m_planner->lastWallMs() / 1000.0;
    const double ownS = total.planMs / 1000.0;
    m_planTime->setText(
        plan.aircraft.size() > 1
            ? tr("Planned in %1 s: %2 s for the aircraft's own parts (Plan ms), %3 s to share the area "
                 "between them and check the coverage.")
                  .arg(wallS, 0, 'f', 2)
                  .arg(ownS, 0, 'f', 2)
                  .arg(std::max(0.0, wallS - ownS), 0, 'f', 2)
            : tr("Planned in %1 s: %2 s for the aircraft's plan (Plan ms), %3 s to check the coverage.")
                  .arg(wallS, 0, 'f', 2)
                  .arg(ownS, 0, 'f', 2)
                  .arg(std::max(0.0, wallS - ownS), 0, 'f', 2));
}

QPushButton* StatisticsPanel::useButton(mission::PlannerKind kind) const {
    const auto& kinds = mission::plannerKinds();
    for (std::size_t i = 0; i < kinds.size() && int(i) < m_compare->rowCount(); ++i)
        if (kinds[i].kind == kind)
            return qobject_cast<QPushButton*>(m_compare->cellWidget(int(i), CUse));
    return nullptr;
}

bool StatisticsPanel::usePlanner(mission::PlannerKind kind) {
    auto o = m_doc->mission().options;
    if (o.planner == kind)
        return true;
    if (!m_planner->plannerRefusal(kind).isEmpty())
        return false;
    o.planner = kind;
    m_doc->undoStack()->push(new SetPlannerOptionsCommand(m_doc, o, tr("Planner %1").arg(plannerName(kind))));
    return true;
}

QString StatisticsPanel::compareNote() const {
    return m_compareNote->isHidden() ? QString() : m_compareNote->text();
}

void StatisticsPanel::refreshComparison() {
    const auto& rows = m_planner->comparison();
    const auto& kinds = mission::plannerKinds();
    // A comparison started (button, menu) is shown.
    if (m_planner->isComparing() && rows.empty())
        m_pages->setCurrentIndex(1);
    m_compareButton->setEnabled(!m_planner->isComparing());
    m_compareState->setText(m_planner->isComparing()
                                ? tr("running… (%1 of %2 done)").arg(rows.size()).arg(kinds.size())
                            : rows.empty() ? tr("not run yet")
                            : m_planner->isComparisonOutdated()
                                ? tr("<b>outdated</b>: the mission changed since; compare again")
                                : tr("best value in bold green"));
    // One row per planner kind, from the one table of kinds: a new kind appears by itself.
    m_compare->setRowCount(int(kinds.size()));
    auto value = [](const PlannerComparisonRow& row, int col) -> double {
        switch (col) {
        case CPhotos: return row.totals.photos;
        case CKm: return row.totals.pathLengthM;
        case CTime: return row.totals.estimatedTimeS;
        case CTurns: return flownTurns(row.totals);
        case CCover: return -row.coveragePercent;
        case CNoFly: return row.noFlyCrossings;
        case CPlanMs: return row.wallMs;
        }
        return 0;
    };
    const auto current = m_doc->mission().options.planner;
    QStringList refused;
    for (int r = 0; r < int(kinds.size()); ++r) {
        const auto& info = kinds[std::size_t(r)];
        auto* name = cell(plannerName(info.kind), Qt::AlignLeft | Qt::AlignVCenter);
        name->setToolTip(QString::fromLatin1(info.summary));
        m_compare->setItem(r, Planner, name);
        auto* use = qobject_cast<QPushButton*>(m_compare->cellWidget(r, CUse));
        if (!use) {
            use = new QPushButton;
            use->setObjectName(QStringLiteral("Use_%1").arg(QString::fromLatin1(info.id)));
            const auto kind = info.kind;
            connect(use, &QPushButton::clicked, this, [this, kind] { usePlanner(kind); });
            m_compare->setCellWidget(r, CUse, use);
        }
        const bool inUse = info.kind == current;
        // A planner flying over the mission's no-fly zones stays visible as the yardstick only.
        const QString refusal = inUse ? QString() : m_planner->plannerRefusal(info.kind);
        if (!refusal.isEmpty())
            refused << yardstickNote(info.kind, rows, m_planner->isComparisonOutdated());
        use->setText(inUse ? tr("In use") : refusal.isEmpty() ? tr("Use") : tr("Yardstick"));
        use->setEnabled(!inUse && refusal.isEmpty());
        use->setToolTip(inUse ? tr("The mission's planner")
                        : refusal.isEmpty()
                            ? tr("Plan the mission with %1").arg(plannerName(info.kind))
                            : QStringLiteral("<p>%1</p>").arg(refusal.toHtmlEscaped())); // wrapped
        const PlannerComparisonRow* row = nullptr;
        for (const auto& x : rows)
            if (x.planner == info.kind)
                row = &x;
        if (!row || !row->ok) {
            const QString text = row ? row->error : m_planner->isComparing() ? tr("…") : QString();
            auto* msg = cell(text, Qt::AlignLeft | Qt::AlignVCenter);
            msg->setToolTip(QStringLiteral("<p>%1</p>").arg(text.toHtmlEscaped())); // wrapped
            // Across the figure columns, elided, without widening them: a long refusal ("… cannot
            // plan for a plane …") would push the figures of the other rows out of sight.
            msg->setData(Qt::SizeHintRole, QSize(36, 22));
            m_compare->setItem(r, CPhotos, msg);
            for (int c = CKm; c < CUse; ++c)
                m_compare->setItem(r, c, cell(QString()));
            if (m_compare->columnSpan(r, CPhotos) != CUse - CPhotos)
                m_compare->setSpan(r, CPhotos, 1, CUse - CPhotos);
            if (row && !inUse) { // a planner that could not plan this mission is not offered
                use->setEnabled(false);
                use->setToolTip(QStringLiteral("<p>%1</p>").arg(text.toHtmlEscaped()));
            }
            continue;
        }
        if (m_compare->columnSpan(r, CPhotos) != 1)
            m_compare->setSpan(r, CPhotos, 1, 1);
        const auto& t = row->totals;
        const QStringList values = {QString::number(t.photos),
                                    QString::number(t.pathLengthM / 1000.0, 'f', 2),
                                    minutes(t.estimatedTimeS),
                                    QString::number(flownTurns(t)),
                                    QString::number(row->coveragePercent, 'f', 1),
                                    QString::number(row->noFlyCrossings),
                                    QString::number(row->wallMs, 'f', 0)};
        for (int c = CPhotos; c < CUse; ++c) {
            auto* item = cell(values[c - CPhotos]);
            bool best = true;
            for (const auto& other : rows)
                if (other.ok && value(other, c) < value(*row, c) - 1e-9)
                    best = false;
            if (best && rows.size() > 1) {
                QFont f = item->font();
                f.setBold(true);
                item->setFont(f);
                item->setForeground(QColor(20, 120, 40));
                item->setBackground(QColor(220, 245, 220));
            }
            if (c == CNoFly && row->noFlyCrossings > 0) {
                item->setForeground(QColor(190, 20, 20));
                item->setToolTip(tr("%n waypoint(s) or leg(s) inside a no-fly margin", nullptr, row->noFlyCrossings));
            }
            m_compare->setItem(r, c, item);
        }
    }
    m_compareNote->setText(refused.join(QLatin1Char('\n')));
    m_compareNote->setHidden(refused.isEmpty());
}

} // namespace pf::ui
