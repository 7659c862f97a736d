#include "ui/panels/statistics_panel.h"

#include "core/geo/local_frame.h"
#include "ui/mission_document.h"
#include "ui/planning/plan_controller.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>
#include <optional>

namespace pf::ui {

namespace {

QString minutes(double seconds) {
    const int s = int(std::lround(seconds));
    return QStringLiteral("%1:%2").arg(s / 60).arg(s % 60, 2, 10, QLatin1Char('0'));
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
    // Columns share the width: a horizontal scroll bar would hide the last row in a short dock.
    t->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    t->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    t->horizontalHeader()->setMinimumSectionSize(40);
    t->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    t->setVerticalScrollBarPolicy(Qt::ScrollBarAsNeeded);
    t->setEditTriggers(QAbstractItemView::NoEditTriggers);
    t->setSelectionMode(QAbstractItemView::NoSelection);
    return t;
}

} // namespace

StatisticsPanel::StatisticsPanel(MissionDocument* doc, PlanController* planner, QWidget* parent)
    : QWidget(parent), m_doc(doc), m_planner(planner) {
    setObjectName(QStringLiteral("StatisticsPanel"));
    m_stats = makeTable({tr("Aircraft"), tr("Photos"), tr("km"), tr("Time"), tr("Turns"),
                         tr("Sorties"), tr("Cover %"), tr("Plan ms")});
    m_compare = makeTable({tr("Planner"), tr("Photos"), tr("km"), tr("Time"), tr("Turns"),
                           tr("Cover %"), tr("Plan ms")});
    const QStringList tips = {QString(),
                              tr("Photos taken"),
                              tr("Distance flown, home to home"),
                              tr("Flight time (min:s), transit and every sortie included"),
                              tr("Turns"),
                              tr("Sorties: batteries needed")};
    for (int c = 1; c < tips.size(); ++c)
        m_stats->horizontalHeaderItem(c)->setToolTip(tips[c]);
    m_compareButton =
        new QPushButton(QIcon(QStringLiteral(":/icons/compare.svg")), tr("Compare planners"));
    m_compareButton->setToolTip(
        tr("Plan the current mission with stride, raster and wavefront and compare them"));
    m_compareState = new QLabel;
    // Room for a header and three rows each (two aircraft and the total; the three planners).
    m_stats->setMinimumHeight(26 + 3 * 22 + 4);
    m_compare->setMinimumHeight(26 + 3 * 22 + 4);
    auto* lay = new QVBoxLayout(this);
    lay->setContentsMargins(4, 4, 4, 4);
    lay->setSpacing(3);
    lay->addWidget(m_stats, 3);
    auto* row = new QHBoxLayout;
    row->addWidget(m_compareButton);
    row->addWidget(m_compareState, 1);
    lay->addLayout(row);
    lay->addWidget(m_compare, 2);
    connect(m_compareButton, &QPushButton::clicked, m_planner, &PlanController::compare);
    connect(m_planner, &PlanController::planChanged, this, &StatisticsPanel::refreshStatistics);
    connect(m_doc, &MissionDocument::routesChanged, this, &StatisticsPanel::refreshStatistics);
    connect(m_planner, &PlanController::comparisonChanged, this,
            &StatisticsPanel::refreshComparison);
    refreshStatistics();
    refreshComparison();
}

void StatisticsPanel::refreshStatistics() {
    m_stats->setRowCount(0);
    const auto& plan = m_planner->plan();
    if (!plan)
        return;
    const auto& mission = m_doc->mission();
    int batteriesTotal = 0;
    int photosDelta = 0;
    double distanceDelta = 0.0;
    for (const auto& ap : plan->aircraft) {
        const int r = m_stats->rowCount();
        m_stats->insertRow(r);
        // Batteries: flights of the usable endurance (the reserve kept) this aircraft's time needs.
        // The plan's sorties when the core cut the flight into them; else an estimate.
        const double timeS = ap.timeS > 0 ? ap.timeS : ap.metrics.estimatedTimeS;
        const double distanceM =
            ap.flightDistanceM > 0 ? ap.flightDistanceM : ap.metrics.pathLengthM;
        int batteries = std::max<int>(1, int(ap.sorties.size()));
        QColor colour(Qt::gray);
        for (const auto& a : mission.aircraft) {
            if (a.name != ap.aircraft)
                continue;
            const double usableS = a.enduranceMin * 60.0 * (1.0 - mission.options.batteryReserve);
            if (ap.sorties.empty() && usableS > 0)
                batteries = std::max(1, int(std::ceil(timeS / usableS)));
            colour = QColor(QString::fromStdString(a.colour));
        }
        batteriesTotal += batteries;
        bool edited = false;
        const route::Route* flown = nullptr;
        for (const auto& pr : m_doc->routes())
            if (pr.route.aircraft == ap.aircraft) {
                edited = pr.edited;
                flown = &pr.route;
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
            photosDelta += photos - ap.metrics.photos;
            distanceDelta += length - distanceM;
        }
        auto* name =
            cell(QString::fromStdString(ap.aircraft) + (edited ? tr(" (edited)") : QString()),
                 Qt::AlignLeft | Qt::AlignVCenter);
        QPixmap swatch(12, 12);
        swatch.fill(colour);
        name->setIcon(QIcon(swatch));
        m_stats->setItem(r, 0, name);
        m_stats->setItem(r, 1, cell(QString::number(photos)));
        m_stats->setItem(r, 2, cell(QString::number(shownDistanceM / 1000.0, 'f', 2)));
        m_stats->setItem(r, 3, cell(minutes(shownTimeS)));
        if (edited)
            m_stats->item(r, 0)->setToolTip(
                tr("Photos, distance and time measured on the edited route"));
        m_stats->setItem(r, 4, cell(QString::number(ap.metrics.turns)));
        m_stats->setItem(r, 5, cell(QString::number(batteries)));
        const double cov =
            ap.metrics.visitable > 0 ? 100.0 * ap.metrics.cells / ap.metrics.visitable : 0.0;
        m_stats->setItem(r, 6, cell(QString::number(cov, 'f', 1)));
        m_stats->setItem(r, 7, cell(QString::number(ap.metrics.planningMs, 'f', 0)));
    }
    const auto& t = plan->totals;
    const int r = m_stats->rowCount();
    m_stats->insertRow(r);
    QFont bold = m_stats->font();
    bold.setBold(true);
    // Coverage in total: the core's independent check of the real footprints when it ran.
    const double cov = plan->coverageRatio > 0 ? 100.0 * plan->coverageRatio
                       : t.visitable > 0       ? 100.0 * t.cells / t.visitable
                                               : 0.0;
    double distance = 0;
    for (const auto& ap : plan->aircraft)
        distance += ap.flightDistanceM > 0 ? ap.flightDistanceM : ap.metrics.pathLengthM;
    const double makespan = plan->makespanS > 0 ? plan->makespanS : t.estimatedTimeS;
    const QStringList values = {tr("Total"),
                                QString::number(t.photos + photosDelta),
                                QString::number((distance + distanceDelta) / 1000.0, 'f', 2),
                                minutes(makespan),
                                QString::number(t.turns),
                                QString::number(batteriesTotal),
                                QString::number(cov, 'f', 1),
                                QString::number(m_planner->lastWallMs(), 'f', 0)};
    for (int c = 0; c < values.size(); ++c) {
        auto* item = cell(values[c], c == 0 ? Qt::AlignLeft | Qt::AlignVCenter
                                            : Qt::AlignRight | Qt::AlignVCenter);
        item->setFont(bold);
        m_stats->setItem(r, c, item);
    }
    m_stats->item(r, 3)->setToolTip(tr("The longest aircraft's flight: they fly at the same time"));
    m_stats->item(r, 6)->setToolTip(
        tr("Share of the area seen by the real footprints of all photos"));
}

void StatisticsPanel::refreshComparison() {
    const auto& rows = m_planner->comparison();
    m_compareButton->setEnabled(!m_planner->isComparing());
    m_compareState->setText(m_planner->isComparing()
                                ? tr("running… (%1 of 3 done)").arg(rows.size())
                            : rows.empty() ? tr("not run yet")
                                           : tr("best value in bold green"));
    m_compare->setRowCount(int(rows.size()));
    // Per column: the best value (fewest photos, shortest distance and time, fewest turns, most
    // coverage, fastest planning).
    auto value = [](const PlannerComparisonRow& row, int col) -> double {
        switch (col) {
        case 1:
            return row.totals.photos;
        case 2:
            return row.totals.pathLengthM;
        case 3:
            return row.totals.estimatedTimeS;
        case 4:
            return row.totals.turns;
        case 5:
            return -row.coveragePercent;
        case 6:
            return row.wallMs;
        }
        return 0;
    };
    for (int r = 0; r < int(rows.size()); ++r) {
        const auto& row = rows[std::size_t(r)];
        m_compare->setItem(r, 0, cell(plannerName(row.planner), Qt::AlignLeft | Qt::AlignVCenter));
        if (!row.ok) {
            m_compare->setItem(r, 1, cell(row.error, Qt::AlignLeft | Qt::AlignVCenter));
            for (int c = 2; c < 7; ++c)
                m_compare->setItem(r, c, cell(QString()));
            continue;
        }
        const auto& t = row.totals;
        const QStringList values = {QString::number(t.photos),
                                    QString::number(t.pathLengthM / 1000.0, 'f', 2),
                                    minutes(t.estimatedTimeS),
                                    QString::number(t.turns),
                                    QString::number(row.coveragePercent, 'f', 1),
                                    QString::number(row.wallMs, 'f', 0)};
        for (int c = 1; c <= 6; ++c) {
            auto* item = cell(values[c - 1]);
            bool best = true;
            for (const auto& other : rows)
                if (other.ok && value(other, c) < value(row, c) - 1e-9)
                    best = false;
            if (best && rows.size() > 1) {
                QFont f = item->font();
                f.setBold(true);
                item->setFont(f);
                item->setForeground(QColor(20, 120, 40));
                item->setBackground(QColor(220, 245, 220));
            }
            m_compare->setItem(r, c, item);
        }
    }
}

} // namespace pf::ui
