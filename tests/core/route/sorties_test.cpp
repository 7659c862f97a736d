#include "core/route/sorties.h"

#include "core/plan/coverage_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace pf;
using namespace pf::route;
using geo::Vec2;

namespace {
// Photos every 10 m on the x axis from x0 to x1 inclusive, flown eastwards.
std::vector<LocalWaypoint> photoLine(int x0, int x1) {
    std::vector<LocalWaypoint> out;
    for (int x = x0; x <= x1; x += 10) {
        LocalWaypoint w;
        w.pos = Vec2(x, 0);
        w.headingDeg = 90;
        out.push_back(w);
    }
    return out;
}
// Paper 004's model alone: no stop at the turns (infinite acceleration, no hold).
FlightModel noStops(double speed, double turnRate) {
    FlightModel m;
    m.speedMps = speed;
    m.turnRateDegS = turnRate;
    m.accelerationMps2 = std::numeric_limits<double>::infinity();
    m.stopHoldS = 0.0;
    return m;
}
} // namespace

TEST(FlightTime, LengthOverSpeedPlusTurnsOverRate) {
    const FlightModel m = noStops(10.0, 90.0);
    EXPECT_DOUBLE_EQ(flightTimeS({Vec2(0, 0), Vec2(100, 0)}, m), 10.0);
    EXPECT_DOUBLE_EQ(flightTimeS({Vec2(0, 0), Vec2(100, 0), Vec2(100, 100)}, m), 21.0);
    EXPECT_DOUBLE_EQ(flightTimeS({Vec2(0, 0), Vec2(100, 0), Vec2(0, 0)}, m), 22.0);
}

// Hand-computed split: home at the origin in the middle of a photo line from -300 to 300 m, 10 m/s,
// 90 deg/s, budget 108 s x (1 - 0.25) = 81 s.
// Sortie 1 starts at -300: 30 s out, U-turn (2 s), east to x, U-turn (2 s), x/10 s back:
// 64 + x/5 <= 81 -> x <= 85, so it ends at 80 m (80 s). Sortie 2: 9 s out to 90 m, east to 300,
// U-turn, 30 s back: 9 + 21 + 2 + 30 = 62 s.
TEST(Sorties, HandComputedSplit) {
    const auto survey = photoLine(-300, 300);
    const SafePathFinder finder;
    auto plan = splitIntoSorties(survey, Vec2(0, 0), finder, noStops(10.0, 90.0), SortieOptions{1.8, 0.25},
                                 "Falcon 8 #1");
    ASSERT_TRUE(plan.ok()) << plan.error().message;
    EXPECT_DOUBLE_EQ(plan->budgetS, 81.0);
    ASSERT_EQ(plan->batteries(), 2);
    const auto& s1 = plan->sorties[0];
    const auto& s2 = plan->sorties[1];
    EXPECT_EQ(s1.firstSurvey, 0);
    EXPECT_EQ(survey[static_cast<std::size_t>(s1.lastSurvey)].pos.x(), 80.0);
    EXPECT_NEAR(s1.timeS, 80.0, 1e-9);
    EXPECT_NEAR(s1.lengthM, 300 + 380 + 80, 1e-9);
    EXPECT_EQ(s2.firstSurvey, s1.lastSurvey + 1);
    EXPECT_EQ(s2.lastSurvey, static_cast<int>(survey.size()) - 1);
    EXPECT_NEAR(s2.timeS, 62.0, 1e-9);
    EXPECT_NEAR(plan->totalTimeS, 142.0, 1e-9);
    EXPECT_EQ(s1.waypoints.size() + s2.waypoints.size(), survey.size()); // no transit needed
}

TEST(Sorties, FitsInOneWhenShort) {
    const auto survey = photoLine(10, 100);
    auto plan = splitIntoSorties(survey, Vec2(0, 0), SafePathFinder(), FlightModel{}, SortieOptions{20, 0.2}, "A");
    ASSERT_TRUE(plan.ok());
    EXPECT_EQ(plan->batteries(), 1);
    EXPECT_EQ(plan->sorties[0].waypoints.size(), survey.size());
}

// A lawnmower survey behind a no-fly zone: every sortie fits its budget, includes its safe transit,
// and the sorties take the survey waypoints once each, in order.
TEST(Sorties, EverySortieFitsAndTransitsSafely) {
    std::vector<LocalWaypoint> survey;
    for (int track = 0; track < 12; ++track)
        for (int k = 0; k <= 20; ++k) {
            LocalWaypoint w;
            const int x = track % 2 == 0 ? 10 * k : 200 - 10 * k;
            w.pos = Vec2(x, 100 + 20 * track);
            w.headingDeg = track % 2 == 0 ? 90 : 270;
            survey.push_back(w);
        }
    const std::vector<geo::Polygon> zones{
        geo::Polygon{{Vec2(-20, 40), Vec2(220, 40), Vec2(220, 60), Vec2(-20, 60)}, {}}};
    const SafePathFinder finder(NoFlyField(zones, 5));
    // With the stops and a dwell per photo: the sortie times must still add up leg by leg.
    const FlightModel model{8.0, 60.0, 2.0, 1.0};
    auto plan = splitIntoSorties(survey, Vec2(100, 0), finder, model, SortieOptions{4.0, 0.2}, "Hexa");
    ASSERT_TRUE(plan.ok()) << plan.error().message;
    EXPECT_GE(plan->batteries(), 3);
    int next = 0;
    for (const auto& s : plan->sorties) {
        EXPECT_LE(s.timeS, plan->budgetS + 1e-9);
        EXPECT_EQ(s.firstSurvey, next);
        next = s.lastSurvey + 1;
        // Recompute the time from the sortie's own waypoints, home to home.
        std::vector<Vec2> path{Vec2(100, 0)};
        int photos = 0;
        for (const auto& w : s.waypoints) {
            path.push_back(w.pos);
            photos += w.kind == WaypointKind::Photo;
        }
        path.push_back(Vec2(100, 0));
        EXPECT_NEAR(flightTimeS(path, model) + photos * model.photoDwellS, s.timeS, 1e-6);
        EXPECT_EQ(plan::countNoFlyViolations({path}, zones, 5).total(), 0);
        EXPECT_EQ(s.waypoints.front().kind, WaypointKind::Transit); // around the zone
    }
    EXPECT_EQ(next, static_cast<int>(survey.size()));
}

TEST(Sorties, UnreachableWaypointIsAnError) {
    auto plan = splitIntoSorties(photoLine(1000, 1000), Vec2(0, 0), SafePathFinder(), noStops(10, 90),
                                 SortieOptions{1.8, 0.25}, "Falcon 8 #1");
    ASSERT_FALSE(plan.ok());
    EXPECT_EQ(
        plan.error().message,
        "Falcon 8 #1 cannot fly to waypoint 1 (1000 m from home) and back within its endurance of "
        "1.8 min less the 25 % reserve (81 s available, 202 s needed): take off closer or use an "
        "aircraft with "
        "more endurance.");
}

TEST(Sorties, BadSettingsAreRejectedWithAMessage) {
    const auto survey = photoLine(0, 10);
    auto e = splitIntoSorties(survey, Vec2(0, 0), SafePathFinder(), FlightModel{}, SortieOptions{0, 0.2}, "K");
    ASSERT_FALSE(e.ok());
    EXPECT_EQ(e.error().message, "K has an endurance that is not positive.");
    auto r = splitIntoSorties(survey, Vec2(0, 0), SafePathFinder(), FlightModel{}, SortieOptions{10, 1.0}, "K");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().message, "The battery reserve must be a fraction from 0 up to (not including) 1.");
    auto s = splitIntoSorties(survey, Vec2(0, 0), SafePathFinder(), FlightModel{0, 90}, SortieOptions{}, "K");
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().message,
              "K needs a positive speed, turn rate and acceleration to estimate flight times.");
}
