// A plane on the map and in the statistics, as the operator meets it: its landing drawn the way its
// vehicle files fly it (the approach, then the landing point), its Turns counted once per arc and
// explained in a tooltip. Offscreen, through the real widgets.
#include "core/geo/geodesic.h"
#include "core/io/mission_items.h"
#include "core/mission/planner_kinds.h"
#include "ui/commands/edit_aircraft_command.h"
#include "ui/dialogs/export_dialog.h"
#include "ui/map/plan_layer.h"
#include "ui/mission_document.h"
#include "ui/panels/aircraft_panel.h"
#include "ui/panels/statistics_panel.h"
#include "ui/planning/plan_controller.h"
#include "ui_test_util.h"

#include <QDir>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QUndoStack>

#include <gtest/gtest.h>

using namespace pf;
using namespace pf::ui;

TEST(PlaneOnTheMap, LandingApproachIsDrawnAndTurnsAreExplained) {
    auto w = test::makeWindow();
    w->planController()->setAutoPlan(false);
    QString error;
    ASSERT_TRUE(w->openDemoMission(&error)) << error.toStdString();
    MissionDocument* doc = w->document();
    w->aircraftPanel()->setCurrent(1);
    w->aircraftPanel()->removeCurrent();
    ASSERT_EQ(doc->mission().aircraft.size(), 1u);
    auto wing = doc->mission().aircraft[0];
    wing.kind = fleet::AircraftKind::FixedWing;
    wing.altitudeM = 80.0;
    wing.gsdCm.reset();
    wing.cruiseSpeedMps = 13.0;
    wing.plane.maxBankDeg = 45.0;
    doc->undoStack()->push(new EditAircraftCommand(doc, 0, wing, QStringLiteral("kind")));
    w->planNow();
    ASSERT_TRUE(w->planController()->waitForIdle(120000));

    // The way down: the approach waypoint 400 m out, then the landing point (home here).
    ASSERT_EQ(w->planLayer()->routeItems().size(), 1u);
    const auto& d = w->planLayer()->routeItems()[0]->data();
    ASSERT_EQ(d.landingLeg.size(), 2);
    ASSERT_TRUE(d.home.has_value());
    EXPECT_NEAR(test::metresBetween(fromScene(d.landingLeg[1]), fromScene(*d.home)), 0.0, 0.5);
    EXPECT_NEAR(test::metresBetween(fromScene(d.landingLeg[0]), fromScene(d.landingLeg[1])),
                io::kApproachDistanceM, 1.0);

    // Turns: one per arc (far fewer than the arcs' sampled vertices), with the tooltip saying why.
    const QTableWidget* stats = w->statisticsPanel()->statistics();
    const int turns = stats->item(0, StatisticsPanel::Turns)->text().toInt();
    int turnWaypoints = 0;
    for (const auto& r : doc->routes())
        for (const auto& p : r.route.waypoints)
            turnWaypoints += p.kind == route::WaypointKind::Turn ? 1 : 0;
    EXPECT_GT(turns, 0);
    EXPECT_LT(turns * 2, turnWaypoints);
    EXPECT_TRUE(stats->item(0, StatisticsPanel::Turns)->toolTip().contains(QStringLiteral("Turn arcs and run-ins")))
        << stats->item(0, StatisticsPanel::Turns)->toolTip().toStdString();

    // Compare planners: the sweep plans the plane; a grid planner says why it cannot, across the
    // figure columns, and is not offered.
    w->planController()->compare();
    ASSERT_TRUE(w->planController()->waitForIdle(180000));
    StatisticsPanel* panel = w->statisticsPanel();
    EXPECT_TRUE(panel->useButton(mission::PlannerKind::Sweep)->isEnabled());
    QPushButton* stride = panel->useButton(mission::PlannerKind::Stride);
    EXPECT_FALSE(stride->isEnabled());
    EXPECT_TRUE(stride->toolTip().contains(QStringLiteral("cannot plan for a plane"))) << stride->toolTip().toStdString();
    const QTableWidget* cmp = panel->comparison();
    int strideRow = -1;
    for (int r = 0; r < cmp->rowCount(); ++r)
        if (cmp->item(r, StatisticsPanel::Planner)->text() == QStringLiteral("Stride"))
            strideRow = r;
    ASSERT_GE(strideRow, 0);
    EXPECT_EQ(cmp->columnSpan(strideRow, StatisticsPanel::CPhotos), StatisticsPanel::CUse - StatisticsPanel::CPhotos);

    // The Export dialog: the heading typed is the one exported; the note says what a plane ignores.
    ExportDialog dialog(doc, w->planController(), QDir::tempPath());
    auto* heading = dialog.findChild<QDoubleSpinBox*>(QStringLiteral("ExportLandingHeading"));
    ASSERT_NE(heading, nullptr);
    EXPECT_FALSE(dialog.request().options.landingHeadingDeg.has_value()); // along the first lane
    heading->setValue(250);
    EXPECT_EQ(dialog.request().options.landingHeadingDeg, 250.0);
    auto* note = dialog.findChild<QLabel*>(QStringLiteral("PlaneOptionsNote"));
    ASSERT_NE(note, nullptr);
    EXPECT_TRUE(note->text().contains(QStringLiteral("photos by distance along each lane")));

    // Back to a multirotor: no approach, the flight returns home.
    wing.kind = fleet::AircraftKind::Multirotor;
    doc->undoStack()->push(new EditAircraftCommand(doc, 0, wing, QStringLiteral("kind")));
    w->planNow();
    ASSERT_TRUE(w->planController()->waitForIdle(120000));
    EXPECT_TRUE(w->planLayer()->routeItems()[0]->data().landingLeg.isEmpty());
    EXPECT_TRUE(w->statisticsPanel()->statistics()->item(0, StatisticsPanel::Turns)->toolTip().isEmpty() ||
                !w->statisticsPanel()->statistics()->item(0, StatisticsPanel::Turns)->toolTip().contains(
                    QStringLiteral("Turn arcs")));
}
