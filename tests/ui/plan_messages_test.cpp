// What the Problems and Statistics panels say about a plan: each thing once, in one unit, each
// aircraft named one way, altitudes as given, the covered share per aircraft and never "100.0"
// beside unseen ground, and an outdated plan's problems marked, then cleared while the new plan
// runs.
#include "core/mission/plan_messages.h"
#include "ui/commands/edit_aircraft_command.h"
#include "ui/mission_document.h"
#include "ui/panels/problems_panel.h"
#include "ui/panels/statistics_panel.h"
#include "ui/planning/plan_controller.h"
#include "ui_test_util.h"

#include <QTableWidget>
#include <QUndoStack>

#include <gtest/gtest.h>

using namespace pf;
using namespace pf::ui;

namespace {

// The demo with a 4-minute battery for the Falcon 8 (several sorties) and the Phantom 4 Pro half a
// metre above it, both from the mission's one home; planned.
std::unique_ptr<MainWindow> plannedCloseDemo() {
    auto w = test::makeWindow();
    w->planController()->setAutoPlan(false);
    QString error;
    EXPECT_TRUE(w->openDemoMission(&error)) << error.toStdString();
    auto* doc = w->document();
    auto falcon = doc->mission().aircraft[0];
    falcon.enduranceMin = 4.0;
    doc->undoStack()->push(new EditAircraftCommand(doc, 0, falcon, QStringLiteral("endurance")));
    auto phantom = doc->mission().aircraft[1];
    phantom.altitudeM = 40.5;
    doc->undoStack()->push(new EditAircraftCommand(doc, 1, phantom, QStringLiteral("altitude")));
    w->planNow();
    EXPECT_TRUE(w->planController()->waitForIdle(120000));
    EXPECT_TRUE(w->planController()->lastError().isEmpty())
        << w->planController()->lastError().toStdString();
    return w;
}

QStringList itemsContaining(ProblemsPanel* list, const QString& text,
                            std::vector<int>* rows = nullptr) {
    QStringList out;
    for (int i = 0; i < list->count(); ++i)
        if (list->item(i)->text().contains(text)) {
            out << list->item(i)->text();
            if (rows)
                rows->push_back(i);
        }
    return out;
}

} // namespace

TEST(PlanMessages, ProblemsSayEachThingOnceAndOneWay) {
    auto w = plannedCloseDemo();
    ASSERT_TRUE(w->planController()->plan());
    const auto& plan = *w->planController()->plan();
    auto* list = w->problemsList();
    ASSERT_GT(list->count(), 0);
    for (int i = 0; i < list->count(); ++i) {
        const std::string text = list->item(i)->text().toStdString();
        EXPECT_EQ(text.find("aircraft \""), std::string::npos) << text; // "Falcon 8: …" only
        EXPECT_EQ(text.find(" m2"), std::string::npos) << text;         // m² only
        EXPECT_EQ(text.find("unseen"), std::string::npos) << text;      // said once, below
    }
    // One home, 0.5 m apart: a note with the altitudes as set, not a warning saying "(41 m)".
    std::vector<int> rows;
    const QStringList close =
        itemsContaining(list, QStringLiteral("Falcon 8 and Phantom 4 Pro"), &rows);
    ASSERT_EQ(close.size(), 1) << close.join('\n').toStdString();
    EXPECT_EQ(close[0].toStdString(), "Falcon 8 and Phantom 4 Pro take off from the same home and "
                                      "fly at the same time only 0.5 m apart in "
                                      "altitude (40 m and 40.5 m), each over its own part of the "
                                      "area: launch them one after the other, or "
                                      "keep 10 m between their altitudes.");
    EXPECT_EQ(list->severityOf(rows[0]), ProblemsPanel::Severity::Info);
    // The batteries needed: a note naming the aircraft as the route check does.
    rows.clear();
    const QStringList sorties =
        itemsContaining(list, QStringLiteral("Falcon 8: the flight needs "), &rows);
    ASSERT_EQ(sorties.size(), 1);
    EXPECT_EQ(list->severityOf(rows[0]), ProblemsPanel::Severity::Info);
    // The ground no photo sees: one warning, the coverage check's figure.
    rows.clear();
    const QStringList unseen = itemsContaining(list, QStringLiteral("seen by no photo"), &rows);
    if (plan.uncoveredAreaM2 > 0) {
        ASSERT_EQ(unseen.size(), 1);
        EXPECT_EQ(unseen[0], QString::fromStdString(mission::uncoveredMessage(plan)) +
                                 QStringLiteral(" (hatched red on the map)"));
        EXPECT_EQ(list->severityOf(rows[0]), ProblemsPanel::Severity::Warning);
    } else {
        EXPECT_TRUE(unseen.isEmpty());
    }
    // Waypoints outside the area: each line is true of the waypoints it selects.
    int outsideLines = 0;
    for (int i = 0; i < list->count(); ++i) {
        const QString text = list->item(i)->text();
        if (!text.contains(QStringLiteral("outside the area")))
            continue;
        ++outsideLines;
        const auto& route =
            w->document()->routes().at(text.startsWith(QStringLiteral("Falcon 8")) ? 0 : 1).route;
        const QList<int> wps = list->waypointsOf(i);
        ASSERT_FALSE(wps.isEmpty()) << text.toStdString();
        const bool transitLine = text.contains(QStringLiteral("transit waypoint"));
        for (int k : wps)
            EXPECT_EQ(route.waypoints.at(std::size_t(k)).kind == route::WaypointKind::Transit,
                      transitLine)
                << text.toStdString() << " waypoint " << k;
    }
    EXPECT_GT(outsideLines, 0);
}

TEST(PlanMessages, StatisticsGiveEachAircraftsCoverAndNeverOneHundredBesideUnseenGround) {
    auto w = plannedCloseDemo();
    const auto& plan = *w->planController()->plan();
    auto* stats = w->statisticsPanel()->statistics();
    const int n = int(plan.aircraft.size());
    ASSERT_EQ(n, 2);
    for (int k = 0; k < n; ++k) {
        const QString cover = stats->item(k, StatisticsPanel::Cover)->text();
        const auto share = mission::aircraftCoverage(plan, std::size_t(k));
        ASSERT_TRUE(share) << k;
        EXPECT_GT(*share, 0.9);
        EXPECT_TRUE(cover.endsWith(QString::fromStdString(
            mission::coveragePercentText(*share, plan.aircraft[std::size_t(k)].uncoveredAreaM2))))
            << cover.toStdString();
        if (plan.aircraft[std::size_t(k)].uncoveredAreaM2 > 0) {
            EXPECT_FALSE(cover.contains(QStringLiteral("100.0"))) << cover.toStdString();
        }
    }
    const QString total = stats->item(n, StatisticsPanel::Cover)->text();
    EXPECT_EQ(total.toStdString(),
              mission::coveragePercentText(plan.coverageRatio, plan.uncoveredAreaM2));
    if (plan.uncoveredAreaM2 > 0) {
        EXPECT_NE(total, QStringLiteral("100.0"));
    }
}

TEST(PlanMessages, AnOutdatedPlansProblemsAreMarkedThenClearedWhileTheNewPlanRuns) {
    auto w = plannedCloseDemo();
    auto* list = w->problemsList();
    auto* doc = w->document();
    const int before = list->count();
    ASSERT_GT(before, 0);
    auto phantom = doc->mission().aircraft[1];
    phantom.altitudeM = 60.0;
    doc->undoStack()->push(new EditAircraftCommand(doc, 1, phantom, QStringLiteral("altitude")));
    ASSERT_TRUE(w->planController()->isOutdated());
    // Still listed, each marked as the outdated plan's.
    int marked = 0;
    for (int i = 0; i < list->count(); ++i)
        marked += list->item(i)->toolTip().endsWith(
            QStringLiteral("of the outdated plan: plan again (F5)"));
    EXPECT_GE(marked, before - 1) << list->count();
    // The new plan runs: one line says why the list is empty.
    w->planNow();
    ASSERT_TRUE(w->planController()->isBusy());
    ASSERT_EQ(list->count(), 1);
    EXPECT_EQ(
        list->item(0)->text(),
        QStringLiteral(
            "Planning the changed mission: the previous plan's problems are no longer listed."));
    ASSERT_TRUE(w->planController()->waitForIdle(120000));
    EXPECT_FALSE(w->planController()->isOutdated());
    // The new plan's own problems, none marked; 60 m is far from 40 m: no note on altitudes.
    for (int i = 0; i < list->count(); ++i) {
        EXPECT_FALSE(list->item(i)->toolTip().contains(QStringLiteral("outdated plan"))) << i;
        EXPECT_FALSE(list->item(i)->text().contains(QStringLiteral("Falcon 8 and Phantom 4 Pro")));
    }
}
