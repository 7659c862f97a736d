// Planes in a mission: their figures validated with messages that name the aircraft and the value,
// and no multirotor route for them: a planner whose route turns on the spot refuses them by name.
#include "core/mission/plan_mission.h"
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
    AircraftConfig a;
    a.name = "Copter";
    a.camera.name = "GoPro Hero3 Medium";
    a.camera.hfovDeg = 94.4;
    a.camera.vfovDeg = 55.0;
    a.camera.imageWidthPx = 3840;
    a.camera.imageHeightPx = 2880;
    a.altitudeM = 80.0;
    m.aircraft.push_back(a);
    m.home = geo::LonLat{8.3270554, 49.010741};
    return m;
}

AircraftConfig plane(const AircraftConfig& base, const std::string& name,
                     fleet::AircraftKind kind) {
    AircraftConfig a = base;
    a.name = name;
    a.kind = kind;
    a.cruiseSpeedMps = 15.0;
    a.colour = "#3cb44b";
    return a;
}

std::vector<std::string> errors(const Mission& m) {
    std::vector<std::string> out;
    for (const auto& p : validateMission(m).problems)
        if (p.severity == geo::Severity::Error)
            out.push_back(p.message);
    return out;
}

bool hasMessage(const std::vector<std::string>& v, const std::string& text) {
    for (const auto& s : v)
        if (s.find(text) != std::string::npos)
            return true;
    return false;
}

} // namespace

// Each nonsense figure gets its message, naming the aircraft, the value and the limit; the radius
// wins over the bank, so a bad bank beside a good radius is not reported.
TEST(AircraftKindValidation, NonsenseFiguresAreRefusedWithClearMessages) {
    const AircraftConfig base = plane(demo().aircraft[0], "Wing", fleet::AircraftKind::FixedWing);
    const std::string who = "aircraft \"Wing\"";
    AircraftConfig a = base;
    a.plane.minTurnRadiusM = 0.0;
    EXPECT_EQ(planeErrors(a, who),
              std::vector<std::string>{
                  "aircraft \"Wing\": the minimum turn radius must be greater than 0 m (got 0 m): "
                  "a plane cannot turn on the spot"});
    a = base;
    a.plane.maxBankDeg = 90.0;
    EXPECT_EQ(planeErrors(a, who),
              std::vector<std::string>{
                  "aircraft \"Wing\": the bank limit must lie between 0 and 90 degrees (got 90): "
                  "the turn radius follows from it, V^2 / (g tan bank)"});
    a.plane.minTurnRadiusM = 40.0;
    EXPECT_TRUE(planeErrors(a, who).empty());
    a = base;
    a.plane.climbRateMps = -2;
    a.plane.runInM = -1;
    EXPECT_EQ(
        planeErrors(a, who),
        (std::vector<std::string>{
            "aircraft \"Wing\": the climb rate must be greater than 0 m/s (got -2 m/s)",
            "aircraft \"Wing\": the run-in before each lane must be 0 m or more (got -1 m)"}));
    // Stall: 15 m/s against 13 m/s x 1.2 = 15.6 m/s.
    a = base;
    a.plane.stallSpeedMps = 13.0;
    EXPECT_EQ(planeErrors(a, who),
              std::vector<std::string>{
                  "aircraft \"Wing\": the cruise speed of 15.0 m/s is below the stall-safe minimum "
                  "of 15.6 m/s (1.2 x its stall speed of 13.0 m/s): fly faster"});
    a.cruiseSpeedMps = 16.0;
    EXPECT_TRUE(planeErrors(a, who).empty());
    // A multirotor's plane figures are not its own: never checked.
    a.kind = fleet::AircraftKind::Multirotor;
    a.plane.climbRateMps = -5;
    EXPECT_TRUE(planeErrors(a, who).empty());
}

// validateMission reports the figures and a planner that cannot plan for a plane, naming the
// aircraft; a radius asking for a steep bank is a warning (15 m/s on 10 m needs atan(225 / 98.07) = 66
// degrees).
TEST(AircraftKindValidation, MissionReportNamesThePlane) {
    Mission m = demo();
    EXPECT_TRUE(errors(m).empty());
    m.aircraft.push_back(plane(m.aircraft[0], "Wing", fleet::AircraftKind::FixedWing));
    m.aircraft.back().plane.minTurnRadiusM = 10.0;
    EXPECT_TRUE(errors(m).empty()); // the automatic choice plans for planes
    m.options.planner = PlannerKind::Raster;
    const auto e = errors(m);
    ASSERT_EQ(e.size(), 1u);
    EXPECT_EQ(e[0], "Wing is a fixed-wing aircraft: the raster planner cannot plan for "
                    "a plane (a grid planner's path steps from cell to cell and turns on the spot, "
                    "which a plane cannot fly); choose auto or sweep");
    bool steep = false;
    for (const auto& p : validateMission(m).problems)
        steep =
            steep || (p.severity == geo::Severity::Warning &&
                      p.message.find("Wing: a turn radius of 10 m at 15.0 m/s needs a bank of 66 "
                                     "degrees") != std::string::npos);
    EXPECT_TRUE(steep);
    m.aircraft.back().kind = fleet::AircraftKind::Vtol;
    m.aircraft.back().plane.sinkRateMps = 0.0;
    const auto v = errors(m);
    EXPECT_TRUE(hasMessage(v, "Wing: the sink rate must be greater than 0 m/s (got 0 m/s)"));
    EXPECT_TRUE(hasMessage(v, "Wing is a VTOL aircraft (it flies its survey as a "
                              "plane): the raster planner cannot plan for a plane"));
}

// A plane never gets a multirotor's route: a grid planner fails with the message naming it, alone
// or beside a multirotor; the multirotor alone still plans, and the lawnmower refuses a VTOL too.
TEST(AircraftKindPlanning, PlaneIsRefusedByName) {
    Mission m = demo();
    m.options.planner = PlannerKind::Stride;
    m.aircraft[0].altitudeM = 100.0;
    auto ok = planMission(m);
    ASSERT_TRUE(ok) << ok.error().message;
    m.aircraft.push_back(plane(m.aircraft[0], "Wing", fleet::AircraftKind::FixedWing));
    auto refused = planMission(m);
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().message.find("Wing is a fixed-wing aircraft: the stride "
                                           "planner cannot plan for a plane"),
              std::string::npos)
        << refused.error().message;
    Mission alone = demo();
    alone.options.planner = PlannerKind::Lawnmower;
    alone.aircraft[0] = plane(alone.aircraft[0], "Trinity", fleet::AircraftKind::Vtol);
    auto vtol = planMission(alone);
    ASSERT_FALSE(vtol);
    EXPECT_NE(vtol.error().message.find("Trinity is a VTOL aircraft (it flies its survey "
                                        "as a plane): the lawnmower planner cannot plan for a plane"),
              std::string::npos)
        << vtol.error().message;
}
