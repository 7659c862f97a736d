// Tests of mission validation: the figures on the demo site and each kind of bad mission with its message.
#include "core/mission/validation.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pf;
using namespace pf::mission;

namespace {

Mission demo() {
    Mission m;
    m.name = "demo";
    m.area.outer = {{8.3272608, 49.0109209}, {8.3324653, 49.0108309}, {8.3327392, 49.0123597},
                    {8.3308218, 49.0125396}, {8.3305478, 49.0133489}, {8.3273978, 49.013259}};
    m.noFlyZones.push_back({"Warehouse",
                            {{{8.3291782, 49.0118201}, {8.3297261, 49.0118201}, {8.3297261, 49.0121799},
                              {8.3291782, 49.0121799}},
                             {}}});
    AircraftConfig a;
    a.name = "Test copter";
    a.camera.name = "GoPro Hero3 Medium";
    a.camera.hfovDeg = 94.4;
    a.camera.vfovDeg = 55.0;
    a.camera.imageWidthPx = 3840;
    a.camera.imageHeightPx = 2880;
    a.altitudeM = 50.0;
    a.overlap = {0.7, 0.6};
    a.maxAltitudeM = 120.0;
    m.aircraft.push_back(a);
    m.home = geo::LonLat{8.3270554, 49.010741};
    return m;
}

std::vector<std::string> messages(const ValidationReport& r, geo::Severity s) {
    std::vector<std::string> out;
    for (const auto& p : r.problems)
        if (p.severity == s)
            out.push_back(p.message);
    return out;
}

// The only error of the report.
std::string theError(const Mission& m) {
    const auto errors = messages(validateMission(m), geo::Severity::Error);
    EXPECT_EQ(errors.size(), 1u);
    return errors.empty() ? "<none>" : errors.front();
}

} // namespace

TEST(MissionValidation, DemoFigures) {
    const auto r = validateMission(demo());
    EXPECT_FALSE(r.hasErrors()) << r.errorSummary();
    EXPECT_TRUE(r.problems.empty());
    EXPECT_NEAR(r.areaM2, 90000, 15000); // "about 9 ha"
    const double warehouse = 0.0005479 * 111320 * std::cos(49.012 * M_PI / 180) * 0.0003598 * 110574;
    EXPECT_NEAR(r.areaM2 - r.admissibleAreaM2, warehouse, 0.02 * warehouse);
    ASSERT_EQ(r.aircraft.size(), 1u);
    const auto& f = r.aircraft[0];
    // Paper 004: W = 2h tan(FOVh / 2), L = 2h tan(FOVv / 2).
    const double w = 2 * 50 * std::tan(47.2 * M_PI / 180), l = 2 * 50 * std::tan(27.5 * M_PI / 180);
    EXPECT_NEAR(f.footprint.longSideM, w, 1e-9);
    EXPECT_NEAR(f.footprint.shortSideM, l, 1e-9);
    EXPECT_NEAR(f.cellSizeM, std::max(w * 0.4, l * 0.3), 1e-9);
    EXPECT_NEAR(f.gsdCm, 100 * w / 3840, 1e-9);
    EXPECT_TRUE(f.gridBuilt);
    EXPECT_GT(f.cellsToVisit, 0);
    EXPECT_LE(f.cellsToVisit, f.cols * f.rows);
}

// A fine grid next to a wide margin: cells wholly inside the margin are counted, and the warning says
// what happens to them instead of suggesting their ground is lost.
TEST(MissionValidation, CellsWithinAMarginAreExplained) {
    Mission m = demo();
    m.options.safetyMarginM = 25.0;
    m.aircraft[0].altitudeM = 20.0;
    const auto r = validateMission(m);
    ASSERT_EQ(r.aircraft.size(), 1u);
    ASSERT_GT(r.aircraft[0].unflyableCells, 0);
    bool explained = false;
    for (const auto& p : r.problems)
        explained = explained || (p.message.find(std::to_string(r.aircraft[0].unflyableCells) +
                                                 " cell(s) of the area lie wholly within the safety margin") !=
                                      std::string::npos &&
                                  p.message.find("photographed from the neighbouring cells") != std::string::npos);
    EXPECT_TRUE(explained);
}

TEST(MissionValidation, NoFlyZoneOutsideTheAreaIsAWarning) {
    Mission m = demo();
    m.noFlyZones.push_back({"Far away", {{{8.40, 49.05}, {8.41, 49.05}, {8.41, 49.06}}, {}}});
    const auto r = validateMission(m);
    EXPECT_FALSE(r.hasErrors()) << r.errorSummary();
    const auto w = messages(r, geo::Severity::Warning);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0], "no-fly zone \"Far away\" lies entirely outside the area; it is ignored");
    auto g = localGeometry(m);
    ASSERT_TRUE(g.ok());
    EXPECT_EQ(g->noFly.size(), 1u);
}

TEST(MissionValidation, NoFlyZoneCoveringTheArea) {
    Mission m = demo();
    m.noFlyZones.push_back({"Everything", {{{8.32, 49.00}, {8.34, 49.00}, {8.34, 49.02}, {8.32, 49.02}}, {}}});
    EXPECT_EQ(theError(m), "no-fly zone \"Everything\" covers the whole area: nothing admissible is left to photograph");
}

TEST(MissionValidation, BadPolygonsAreNamed) {
    Mission m = demo();
    m.noFlyZones[0].polygon.outer.resize(2);
    EXPECT_EQ(theError(m), "no-fly zone \"Warehouse\" has 2 distinct vertices; a polygon needs at least 3");
    Mission a = demo();
    std::swap(a.area.outer[1], a.area.outer[2]);
    EXPECT_EQ(theError(a).rfind("the area intersects itself: edges ", 0), 0u);
}

TEST(MissionValidation, AltitudeOutOfRange) {
    Mission m = demo();
    m.aircraft[0].altitudeM = 0.0;
    // 0 m says why it cannot be flown and what the lowest altitude is.
    EXPECT_EQ(theError(m),
              "Test copter: the flight altitude must be greater than 0 m (got 0 m): the "
              "altitude is measured above the take-off point, so 0 m is on the ground; the lowest "
              "allowed is 2 m");
    m.aircraft[0].altitudeM = 150.0;
    EXPECT_EQ(theError(m),
              "Test copter: the flight altitude of 150.0 m is above its maximum of 120.0 m");
    m.aircraft[0].altitudeM.reset();
    EXPECT_EQ(theError(m),
              "Test copter: neither a flight altitude nor a ground sample distance is set");
}

TEST(MissionValidation, GsdMustBePositiveAndGivesTheAltitude) {
    Mission m = demo();
    m.aircraft[0].altitudeM.reset();
    m.aircraft[0].gsdCm = -1.0;
    EXPECT_EQ(theError(m),
              "Test copter: the ground sample distance must be greater than 0 cm/px (got -1)");
    m.aircraft[0].gsdCm = 2.0;
    const auto r = validateMission(m);
    EXPECT_FALSE(r.hasErrors()) << r.errorSummary();
    EXPECT_NEAR(r.aircraft[0].gsdCm, 2.0, 1e-9);
    m.aircraft[0].gsdCm = 10.0; // needs an altitude far above 120 m
    EXPECT_EQ(theError(m).find("is above its maximum of 120.0 m (from the wanted GSD)") != std::string::npos, true);
}

TEST(MissionValidation, OverlapOutsideItsRange) {
    Mission m = demo();
    m.aircraft[0].overlap.front = 1.0;
    EXPECT_EQ(theError(m),
              "Test copter: the front overlap must lie in [0, 1), e.g. 0.7 for 70 % (got 1)");
    m.aircraft[0].overlap.front = 0.7;
    m.aircraft[0].overlap.side = -0.1;
    EXPECT_EQ(theError(m),
              "Test copter: the side overlap must lie in [0, 1), e.g. 0.7 for 70 % (got -0.1)");
}

TEST(MissionValidation, AreaTooLargeForTheCellBudgetSaysWhatWouldFit) {
    Mission m = demo();
    m.options.maxCells = 20;
    m.options.gridAngleDeg = 0.0;
    const std::string e = theError(m);
    EXPECT_EQ(
        e.rfind("Test copter: the area is too large for the cell budget: at 50.0 m (cell size ", 0),
        0u)
        << e;
    EXPECT_NE(e.find("cells, more than the budget of 20; an altitude of at least "), std::string::npos) << e;
    // The altitude it proposes really fits.
    const auto at = e.find("an altitude of at least ");
    const double alt = std::stod(e.substr(at + 24));
    m.aircraft[0].altitudeM = alt;
    const auto r = validateMission(m);
    EXPECT_FALSE(r.hasErrors()) << r.errorSummary();
    EXPECT_LE(r.aircraft[0].cols * r.aircraft[0].rows, 20);
    // Above the aircraft's ceiling the message says so.
    m.aircraft[0].altitudeM = 50.0;
    m.options.maxCells = 1;
    EXPECT_NE(theError(m).find("but that is above its maximum altitude of 120.0 m"), std::string::npos);
}

TEST(MissionValidation, OptionsHomeAndAircraft) {
    Mission m = demo();
    m.home = geo::LonLat{200.0, 49.0};
    EXPECT_EQ(theError(m), "the home point (200.000000, 49.000000) is out of range: longitude must lie within ±180 and "
                           "latitude within ±90 degrees");
    m = demo();
    m.options.safetyMarginM = -2;
    EXPECT_EQ(theError(m), "the safety margin must be zero or a positive number of metres (got -2)");
    m = demo();
    m.aircraft.clear();
    EXPECT_EQ(theError(m), "the mission has no aircraft: add at least one");
    m = demo();
    m.aircraft[0].camera.hfovDeg = 0;
    EXPECT_EQ(theError(m).rfind("Test copter: ", 0), 0u);
}

TEST(MissionValidation, GridOptionsFollowTheAircraft) {
    Mission m = demo();
    auto opt = gridOptionsFor(m, 0, 12.5);
    ASSERT_TRUE(opt.ok()) << opt.error().message;
    EXPECT_NEAR(opt->cellSize, validateMission(m).aircraft[0].cellSizeM, 1e-12);
    EXPECT_EQ(opt->angleDeg, 12.5); // automatic angle: the caller's
    m.options.gridAngleDeg = 30.0;
    EXPECT_EQ(gridOptionsFor(m, 0)->angleDeg, 30.0);
    EXPECT_FALSE(gridOptionsFor(m, 3).ok());
}

TEST(MissionValidation, AltitudeLimitsAreErrorsWithTheReason) {
    Mission m = demo();
    AircraftConfig& a = m.aircraft[0];
    // A 60 x 45 degree camera: 5 m is allowed (big sites are planned that low), 1 m is not.
    a.camera.hfovDeg = 60.0;
    a.camera.vfovDeg = 45.0;
    m.options.maxCells = 100'000'000; // the footprint, not the budget, is what this part checks
    EXPECT_TRUE(altitudeErrors(m, a, 5.0).empty()) << altitudeErrors(m, a, 5.0).front();
    auto low = altitudeErrors(m, a, 1.0);
    ASSERT_EQ(low.size(), 1u);
    EXPECT_EQ(
        low[0],
        "Test copter: the flight altitude of 1.0 m is below the minimum safe altitude of 2.0 m");
    auto small = altitudeErrors(m, a, 3.0);
    ASSERT_EQ(small.size(), 1u);
    EXPECT_EQ(
        small[0],
        "Test copter: at 3.0 m a photo covers only 3.5 x 2.5 m, below the smallest "
        "footprint of 3 m (planning and flying would take far too long): fly at 3.7 m or higher")
        << small[0];
    EXPECT_TRUE(altitudeErrors(m, a, 3.7).empty());
    a.camera.vfovDeg = 30.0; // narrower: 5 m is too low for it
    ASSERT_EQ(altitudeErrors(m, a, 5.0).size(), 1u);
    EXPECT_NE(altitudeErrors(m, a, 5.0).at(0).find("below the smallest footprint"), std::string::npos);
    a.camera.vfovDeg = 45.0;
    auto high = altitudeErrors(m, a, 5000.0);
    ASSERT_EQ(high.size(), 1u);
    EXPECT_EQ(high[0],
              "Test copter: the flight altitude of 5000.0 m is above its maximum of 120.0 m");
    auto zero = altitudeErrors(m, a, 0.0);
    ASSERT_EQ(zero.size(), 1u);
    EXPECT_NE(zero[0].find("so 0 m is on the ground"), std::string::npos);
    // The cell budget, where the value is typed too.
    m.options.maxCells = 1000;
    auto budget = altitudeErrors(m, a, 10.0);
    ASSERT_EQ(budget.size(), 1u);
    EXPECT_NE(budget[0].find("too large for the cell budget"), std::string::npos) << budget[0];
    // validateMission reports the same.
    a.altitudeM = 1.0;
    EXPECT_EQ(theError(m), low[0]);
}
