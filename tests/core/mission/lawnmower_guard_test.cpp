// The lawnmower, the yardstick that flies straight over the no-fly zones: planned as the mission's
// planner it says which zones its routes cross (the CLI prints it on stderr), and says nothing
// where it crosses none. The route check records every zone a route enters.
#include "core/geo/local_frame.h"
#include "core/io/mission_file.h"
#include "core/mission/plan_mission.h"
#include "core/mission/planner_kinds.h"
#include "core/mission/route_check.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace pf;
using namespace pf::mission;

namespace {

Mission demo(PlannerKind planner) {
    auto m = io::readMissionFile(std::string(PF_RESOURCES_DIR) + "/demo/demo_mission.json");
    EXPECT_TRUE(m.ok()) << m.error().message;
    m->options.planner = planner;
    return *m;
}

// The plan's warning about zones flown over, or "".
std::string zoneWarning(const Mission& m) {
    auto plan = planMission(m);
    EXPECT_TRUE(plan.ok()) << plan.error().message;
    if (!plan)
        return "failed";
    for (const auto& w : plan->warnings)
        if (w.find("flies straight over no-fly zone") != std::string::npos)
            return w;
    return {};
}

} // namespace

TEST(LawnmowerGuard, OnlyTheLawnmowerIsMarkedAsNotAvoidingZones) {
    for (const auto& k : plannerKinds())
        EXPECT_EQ(k.avoidsNoFly, k.kind != PlannerKind::Lawnmower) << k.id;
}

TEST(LawnmowerGuard, ARouteCheckRecordsEveryZoneEntered) {
    const geo::LocalFrame frame = *geo::LocalFrame::create({8.33, 49.01});
    RouteLimits limits;
    limits.safetyMarginM = 5.0;
    for (double x : {-50.0, 0.0, 50.0})
        limits.zones.push_back(
            {"Z" + std::to_string(int(x)),
             frame.toGeo(geo::Polygon{{{x - 5, -5}, {x + 5, -5}, {x + 5, 5}, {x - 5, 5}}, {}})});
    route::Route r;
    // One leg across the first two zones; the third is passed 20 m away.
    for (const geo::Vec2& p : {geo::Vec2{-80, 0}, geo::Vec2{20, 0}, geo::Vec2{50, 25}})
        r.waypoints.push_back({frame.toGeo(p), 30.0, 0.0, route::WaypointKind::Photo});
    const RouteCheck c = checkRoute(r, limits);
    EXPECT_EQ(c.zonesEntered, (std::vector<std::size_t>{0, 1}));
    EXPECT_EQ(c.leg[0],
              "the leg to waypoint 2 crosses no-fly zone Z-50"); // the message names the first
}

TEST(LawnmowerGuard, TheLawnmowerNamesTheZonesItsRoutesCross) {
    const std::string w = zoneWarning(demo(PlannerKind::Lawnmower));
    EXPECT_EQ(w.rfind("the lawnmower planner flies straight over no-fly zones Warehouse and Radio "
                      "mast: it ignores "
                      "no-fly zones by design",
                      0),
              0u)
        << w;
    // The planners that keep out of the zones say nothing of the kind.
    EXPECT_EQ(zoneWarning(demo(PlannerKind::Sweep)), "");
}

TEST(LawnmowerGuard, NothingToSayWhereItCrossesNoZone) {
    Mission none = demo(PlannerKind::Lawnmower);
    none.noFlyZones.clear();
    EXPECT_EQ(zoneWarning(none), "");
    // A zone 1 km east of the area and its home: not crossed, not named.
    Mission far = none;
    NoFlyZone z{"Far away", {}};
    const Mission withZones = demo(PlannerKind::Lawnmower);
    for (const auto& p : withZones.noFlyZones.front().polygon.outer)
        z.polygon.outer.push_back({p.lon + 0.014, p.lat});
    far.noFlyZones.push_back(z);
    EXPECT_EQ(zoneWarning(far), "");
}
