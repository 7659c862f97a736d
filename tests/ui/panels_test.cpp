// The aircraft panel (altitude <-> GSD linkage, undo) and the ground-station position.
#include "core/sensor/camera.h"
#include "ui/ground_station.h"
#include "ui/mission_document.h"
#include "ui/panels/aircraft_panel.h"
#include "ui_test_util.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QSignalSpy>
#include <QUndoStack>

#include <gtest/gtest.h>

using namespace pf;
using namespace pf::ui;

TEST(AircraftPanel, AltitudeAndGsdDriveEachOther) {
    auto w = test::makeWindow();
    auto* panel = w->aircraftPanel();
    auto* doc = w->document();
    panel->addCustom();
    ASSERT_EQ(doc->mission().aircraft.size(), 1u);
    const sensor::Camera cam = doc->mission().aircraft[0].camera;

    for (double alt : {30.0, 55.5, 100.0, 115.0}) {
        panel->altitudeBox()->setValue(alt);
        const auto& a = doc->mission().aircraft[0];
        ASSERT_TRUE(a.altitudeM.has_value());
        EXPECT_DOUBLE_EQ(*a.altitudeM, alt);
        EXPECT_FALSE(a.gsdCm.has_value());
        EXPECT_NEAR(panel->gsdBox()->value(), *sensor::gsdCmAt(cam, alt), 0.006) << alt;
    }
    for (double gsd : {0.8, 1.5, 3.25}) {
        panel->gsdBox()->setValue(gsd);
        const auto& a = doc->mission().aircraft[0];
        ASSERT_TRUE(a.gsdCm.has_value());
        EXPECT_DOUBLE_EQ(*a.gsdCm, gsd);
        EXPECT_FALSE(a.altitudeM.has_value());
        EXPECT_NEAR(panel->altitudeBox()->value(), *sensor::altitudeForGsd(cam, gsd), 0.06) << gsd;
    }
    // The footprint shown is the camera's at the current altitude.
    const auto fp = sensor::footprintAt(cam, panel->altitudeBox()->value());
    ASSERT_TRUE(fp.ok());
    EXPECT_TRUE(panel->footprintLabel()->text().contains(QString::number(fp->longSideM, 'f', 1)))
        << panel->footprintLabel()->text().toStdString();
}

TEST(AircraftPanel, EditsAreUndoableAndRepeatedEditsMerge) {
    auto w = test::makeWindow();
    auto* panel = w->aircraftPanel();
    auto* doc = w->document();
    auto* stack = doc->undoStack();
    panel->addCustom();
    const auto added = doc->mission().aircraft[0];
    const int afterAdd = stack->count();
    panel->altitudeBox()->setValue(70);
    panel->altitudeBox()->setValue(80);
    panel->altitudeBox()->setValue(90);
    EXPECT_EQ(stack->count(), afterAdd + 1); // one step for the altitude edits
    panel->speedBox()->setValue(12.5);
    panel->frontOverlapBox()->setValue(80);
    panel->sideOverlapBox()->setValue(70);
    panel->enduranceBox()->setValue(35);
    panel->setColour(QColor(QStringLiteral("#123456")));
    const auto& a = doc->mission().aircraft[0];
    EXPECT_DOUBLE_EQ(a.cruiseSpeedMps, 12.5);
    EXPECT_DOUBLE_EQ(a.overlap.front, 0.8);
    EXPECT_DOUBLE_EQ(a.overlap.side, 0.7);
    EXPECT_DOUBLE_EQ(a.enduranceMin, 35);
    EXPECT_EQ(a.colour, "#123456");
    while (stack->count() > afterAdd && stack->index() > afterAdd) stack->undo();
    EXPECT_EQ(doc->mission().aircraft[0], added);
    EXPECT_DOUBLE_EQ(panel->altitudeBox()->value(), *added.altitudeM); // the form follows undo
    stack->undo();
    EXPECT_TRUE(doc->mission().aircraft.empty());
}

TEST(AircraftPanel, CatalogAircraftAndCameraChoiceAndRemove) {
    auto w = test::makeWindow();
    auto* panel = w->aircraftPanel();
    auto* doc = w->document();
    auto catalog = io::loadDefaultCatalog();
    ASSERT_TRUE(catalog.ok()) << catalog.error().message;
    ASSERT_FALSE(catalog->aircraft.empty());
    const auto& spec = catalog->aircraft.front();
    panel->addFromCatalog(QString::fromStdString(spec.name));
    ASSERT_EQ(doc->mission().aircraft.size(), 1u);
    EXPECT_EQ(doc->mission().aircraft[0].model, spec.name);
    EXPECT_DOUBLE_EQ(doc->mission().aircraft[0].cruiseSpeedMps, spec.cruiseSpeedMps);
    EXPECT_DOUBLE_EQ(doc->mission().aircraft[0].enduranceMin, spec.enduranceMin);

    // Changing the camera keeps the altitude and recomputes the GSD.
    const double alt = panel->altitudeBox()->value();
    const int other = panel->cameraBox()->currentIndex() == 0 ? 1 : 0;
    ASSERT_GT(panel->cameraBox()->count(), 1);
    panel->cameraBox()->setCurrentIndex(other);
    const auto& a = doc->mission().aircraft[0];
    EXPECT_EQ(QString::fromStdString(a.camera.name), panel->cameraBox()->itemText(other));
    EXPECT_NEAR(panel->altitudeBox()->value(), alt, 1e-9);
    EXPECT_NEAR(panel->gsdBox()->value(), *sensor::gsdCmAt(a.camera, alt), 0.006);

    panel->addCustom();
    EXPECT_EQ(doc->mission().aircraft.size(), 2u);
    EXPECT_NE(doc->mission().aircraft[0].colour, doc->mission().aircraft[1].colour);
    panel->setCurrent(0);
    panel->removeCurrent();
    ASSERT_EQ(doc->mission().aircraft.size(), 1u);
    EXPECT_EQ(doc->mission().aircraft[0].model, "custom");
    doc->undoStack()->undo();
    EXPECT_EQ(doc->mission().aircraft.size(), 2u);
    EXPECT_EQ(doc->mission().aircraft[0].model, spec.name);
}

// A catalog plane: its kind and figures shown (the plane's rows only for a plane), radius and bank
// driving each other through the speed, every edit undoable, and the footprint saying why it is not
// plannable with a grid planner. By hand at 16 m/s: bank 50 gives 16^2 / (9.80665 tan 50) = 21.9 m, bank 40 31.1 m; a
// 50 m radius needs atan(256 / (9.80665 x 50)) = 27.6 degrees.
TEST(AircraftPanel, PlaneKindAndFiguresAreUndoable) {
    auto w = test::makeWindow();
    auto* panel = w->aircraftPanel();
    auto* doc = w->document();
    auto* stack = doc->undoStack();
    panel->addFromCatalog(QStringLiteral("DeltaQuad Pro"));
    ASSERT_EQ(doc->mission().aircraft.size(), 1u);
    EXPECT_EQ(doc->mission().aircraft[0].kind, fleet::AircraftKind::Vtol);
    EXPECT_EQ(panel->kindBox()->currentIndex(), static_cast<int>(fleet::AircraftKind::Vtol));
    EXPECT_TRUE(panel->turnRadiusBox()->isVisibleTo(panel));
    EXPECT_TRUE(panel->runInBox()->isVisibleTo(panel));
    EXPECT_NEAR(panel->turnRadiusBox()->value(), 21.9, 0.05);
    EXPECT_NEAR(panel->bankBox()->value(), 50.0, 0.5);
    // The automatic choice plans for a plane; a grid planner cannot, and the footprint says so.
    EXPECT_FALSE(panel->footprintLabel()->text().contains(QStringLiteral("Not plannable")))
        << panel->footprintLabel()->text().toStdString();
    mission::PlannerOptions stride = doc->mission().options;
    stride.planner = mission::PlannerKind::Stride;
    doc->setOptions(stride);
    EXPECT_TRUE(panel->footprintLabel()->text().contains(
        QStringLiteral("VTOL aircraft (it flies its survey as a plane): the stride planner cannot plan for a plane")))
        << panel->footprintLabel()->text().toStdString();
    const int start = stack->count();

    panel->bankBox()->setValue(40);
    const auto& a = doc->mission().aircraft[0];
    EXPECT_EQ(a.plane.maxBankDeg, 40.0);
    EXPECT_FALSE(a.plane.minTurnRadiusM.has_value());
    EXPECT_NEAR(panel->turnRadiusBox()->value(), 31.1, 0.05);
    panel->turnRadiusBox()->setValue(50);
    EXPECT_EQ(doc->mission().aircraft[0].plane.minTurnRadiusM, 50.0);
    EXPECT_NEAR(panel->bankBox()->value(), 27.6, 0.5);
    panel->climbBox()->setValue(3.5);
    panel->runInBox()->setValue(80);
    EXPECT_EQ(doc->mission().aircraft[0].plane.climbRateMps, 3.5);
    EXPECT_EQ(doc->mission().aircraft[0].plane.runInM, 80.0);

    panel->kindBox()->setCurrentIndex(static_cast<int>(fleet::AircraftKind::Multirotor));
    EXPECT_EQ(doc->mission().aircraft[0].kind, fleet::AircraftKind::Multirotor);
    EXPECT_FALSE(panel->turnRadiusBox()->isVisibleTo(panel));
    EXPECT_FALSE(panel->footprintLabel()->text().contains(QStringLiteral("VTOL aircraft")));
    EXPECT_EQ(stack->count(), start + 5);

    stack->undo(); // the kind
    EXPECT_EQ(doc->mission().aircraft[0].kind, fleet::AircraftKind::Vtol);
    EXPECT_TRUE(panel->turnRadiusBox()->isVisibleTo(panel));
    EXPECT_EQ(panel->kindBox()->currentIndex(), static_cast<int>(fleet::AircraftKind::Vtol));
    while (stack->index() > start)
        stack->undo();
    EXPECT_EQ(doc->mission().aircraft[0].plane.maxBankDeg, 50.0);
    EXPECT_NEAR(panel->turnRadiusBox()->value(), 21.9, 0.05);
}

TEST(GroundStation, ReplaysAnNmeaLogAndCentresOnTheOperator) {
    auto w = test::makeWindow();
    auto* gs = w->groundStation();
    QSignalSpy spy(gs, &GroundStation::statusChanged);
    QString error;
    ASSERT_TRUE(gs->openNmeaFile(QStringLiteral(PF_UI_TEST_DATA_DIR "/operator.nmea"), &error)) << error.toStdString();
    ASSERT_TRUE(QTest::qWaitFor([&] { return gs->position().has_value(); }, 5000));
    EXPECT_GE(spy.count(), 1); // "reading operator.nmea"
    // 4900.6300 N 00819.5900 E = 49.0105 N, 8.326500 E; the log walks east by 1e-5 degrees a second.
    EXPECT_NEAR(gs->position()->lat, 49.0105, 2e-6);
    EXPECT_GE(gs->position()->lon, 8.3265 - 1e-9);
    EXPECT_LE(gs->position()->lon, 8.32652 + 1e-9);
    w->mapView()->centreOn({8.3300, 49.0125});
    const geo::LonLat me = *gs->position();
    w->mapView()->centreOn(me);
    EXPECT_LT(test::metresBetween(w->mapView()->centreLonLat(), me), 0.01);
    // The replay goes on at the log's pace: the operator walks east.
    EXPECT_TRUE(QTest::qWaitFor([&] { return gs->position()->lon > 8.32651 + 5e-6; }, 5000));
}

TEST(GroundStation, LiveDeviceIsPolled) {
    // A receiver's device is read as data arrives; a file stands in for /dev/ttyACM0 here.
    auto w = test::makeWindow();
    QString error;
    ASSERT_TRUE(w->groundStation()->openNmeaDevice(QStringLiteral(PF_UI_TEST_DATA_DIR "/operator.nmea"), &error))
        << error.toStdString();
    ASSERT_TRUE(QTest::qWaitFor([&] { return w->groundStation()->position().has_value(); }, 5000));
    EXPECT_NEAR(w->groundStation()->position()->lat, 49.0105, 2e-6);
    w->groundStation()->stop();
    EXPECT_FALSE(w->groundStation()->isActive());
}

TEST(GroundStation, MissingSourceIsAnError) {
    auto w = test::makeWindow();
    QString error;
    EXPECT_FALSE(w->groundStation()->openNmeaFile(QStringLiteral("/nonexistent/gps.nmea"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("/nonexistent/gps.nmea"))) << error.toStdString();
    EXPECT_FALSE(w->groundStation()->isActive());
}
