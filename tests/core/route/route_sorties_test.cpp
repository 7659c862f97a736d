// The sorties of a route read from its waypoints (route/route_sorties.h): on a planned route they
// are exactly the plan's sorties; a route edited by hand keeps them as long as it keeps the
// waypoint at home; only a transit waypoint at home cuts.
#include "core/mission/plan_mission.h"
#include "core/route/route_sorties.h"
#include "tests/short_battery_demo.h"

#include <gtest/gtest.h>

namespace pf::route {
namespace {

const mission::MissionPlan& plannedShortBattery() {
    static const mission::MissionPlan plan = [] {
        auto p = mission::planMission(test::shortBatteryDemo());
        EXPECT_TRUE(p.ok()) << p.error().message;
        return p.ok() ? *p : mission::MissionPlan{};
    }();
    return plan;
}

TEST(RouteSorties, APlannedRouteSplitsIntoThePlansSorties) {
    const auto& plan = plannedShortBattery();
    ASSERT_EQ(plan.aircraft.size(), 2u);
    EXPECT_GE(plan.aircraft[0].sorties.size(), 2u);
    EXPECT_EQ(plan.aircraft[1].sorties.size(), 1u);
    for (const auto& a : plan.aircraft) {
        const auto ranges = sortieRanges(a.route, a.route.home);
        ASSERT_EQ(ranges.size(), a.sorties.size()) << a.aircraft;
        for (std::size_t s = 0; s < ranges.size(); ++s) {
            EXPECT_EQ(ranges[s].first, std::size_t(a.sorties[s].firstWaypoint))
                << a.aircraft << " sortie " << s;
            EXPECT_EQ(ranges[s].last, std::size_t(a.sorties[s].lastWaypoint))
                << a.aircraft << " sortie " << s;
        }
        const auto split = splitSorties(a.route, a.route.home);
        ASSERT_EQ(split.size(), a.sortieRoutes.size());
        for (std::size_t s = 0; s < split.size(); ++s) {
            EXPECT_EQ(split[s].waypoints, a.sortieRoutes[s].waypoints);
            EXPECT_EQ(split[s].aircraft, a.aircraft);
            EXPECT_EQ(split[s].home, a.route.home);
        }
        // The waypoint at home between two sorties is in none.
        const auto of = sortieOfWaypoints(a.route, a.route.home);
        int between = 0;
        for (std::size_t i = 0; i < of.size(); ++i)
            if (of[i] < 0) {
                ++between;
                EXPECT_EQ(a.route.waypoints[i].kind, WaypointKind::Transit);
            }
        EXPECT_EQ(between, int(a.sorties.size()) - 1);
    }
}

TEST(RouteSorties, AnEditedRouteKeepsItsSortiesWhileItKeepsTheWaypointAtHome) {
    const auto& a = plannedShortBattery().aircraft.front();
    ASSERT_GE(a.sorties.size(), 2u);
    Route edited = a.route;
    // Waypoints deleted and moved in the first sortie: still two flights, the first one shorter.
    edited.waypoints.erase(edited.waypoints.begin() + 3, edited.waypoints.begin() + 6);
    edited.waypoints[1].position.lat += 1e-5;
    const auto ranges = sortieRanges(edited, a.route.home);
    ASSERT_EQ(ranges.size(), a.sorties.size());
    EXPECT_EQ(ranges[0].last, std::size_t(a.sorties[0].lastWaypoint) - 3);
    // The waypoint at home removed: one flight (what the route now flies).
    Route joined = a.route;
    joined.waypoints.erase(joined.waypoints.begin() + a.sorties[1].firstWaypoint - 1);
    EXPECT_EQ(sortieRanges(joined, a.route.home).size(), a.sorties.size() - 1);
}

TEST(RouteSorties, OnlyATransitWaypointAtHomeCuts) {
    const geo::LonLat home{8.3270554, 49.010741};
    Route r("A", home, 5.0, {});
    auto at = [](double dx, double dy, WaypointKind k) {
        return Waypoint{{8.3270554 + dx, 49.010741 + dy}, 30.0, 0.0, k};
    };
    r.waypoints = {at(0, 0, WaypointKind::Transit), // leaving home: no empty sortie before it
                   at(1e-4, 1e-4, WaypointKind::Photo),
                   at(0, 0, WaypointKind::Turn), // a turn at home is part of the flight
                   at(2e-4, 1e-4, WaypointKind::Photo),
                   at(3e-6, 0, WaypointKind::Transit), // 0.2 m from home: the battery change
                   at(3e-4, 1e-4, WaypointKind::Photo),
                   at(2e-5, 0, WaypointKind::Transit), // 1.5 m away: a transit point of the flight
                   at(4e-4, 1e-4, WaypointKind::Photo),
                   at(0, 0, WaypointKind::Transit)};
    const auto ranges = sortieRanges(r, home);
    ASSERT_EQ(ranges.size(), 2u);
    EXPECT_EQ(ranges[0], (SortieRange{1, 3}));
    EXPECT_EQ(ranges[1], (SortieRange{5, 7}));
    // Without a home, or far from it, the route is one flight; an empty route is none.
    EXPECT_EQ(sortieRanges(r, std::nullopt), (std::vector<SortieRange>{{0, 8}}));
    EXPECT_EQ(sortieRanges(r, geo::LonLat{8.4, 49.1}).size(), 1u);
    EXPECT_TRUE(sortieRanges(Route{}, home).empty());
}

} // namespace
} // namespace pf::route
