#include "core/route/transit.h"

#include "core/plan/coverage_check.h"

#include <gtest/gtest.h>

using namespace pf;
using namespace pf::route;
using geo::Vec2;

namespace {
geo::Polygon square(double x0, double y0, double s) {
    return geo::Polygon{{Vec2(x0, y0), Vec2(x0 + s, y0), Vec2(x0 + s, y0 + s), Vec2(x0, y0 + s)}, {}};
}
std::vector<LocalWaypoint> line(std::initializer_list<Vec2> pts) {
    std::vector<LocalWaypoint> out;
    for (const auto& p : pts) {
        LocalWaypoint w;
        w.pos = p;
        out.push_back(w);
    }
    return out;
}
} // namespace

TEST(Transit, StraightOutAndBackWhenClear) {
    const SafePathFinder finder(NoFlyField({square(100, 100, 10)}, 5));
    TransitReport rep;
    const auto survey = line({Vec2(0, 30), Vec2(40, 30)});
    auto wps = withTransit(survey, Vec2(0, 0), finder, std::nullopt, &rep);
    ASSERT_TRUE(wps.ok()) << wps.error().message;
    EXPECT_EQ(wps->size(), 2u);
    EXPECT_DOUBLE_EQ(rep.outboundM, 30.0);
    EXPECT_DOUBLE_EQ(rep.returnM, 50.0);
    EXPECT_EQ(rep.waypointsAdded, 0);
}

TEST(Transit, DetoursAroundAZoneBetweenHomeAndSurvey) {
    const std::vector<geo::Polygon> zones{square(-10, 20, 20)};
    const SafePathFinder finder(NoFlyField(zones, 5));
    TransitReport rep;
    const auto survey = line({Vec2(0, 80), Vec2(50, 80)});
    auto wps = withTransit(survey, Vec2(0, 0), finder, Vec2(50, 0), &rep);
    ASSERT_TRUE(wps.ok()) << wps.error().message;
    EXPECT_GT(rep.waypointsAdded, 0);
    EXPECT_GT(rep.outboundM, 80.0);
    EXPECT_DOUBLE_EQ(rep.returnM, 80.0); // (50, 80) -> (50, 0) passes clear of the zone
    ASSERT_EQ(wps->size(), survey.size() + static_cast<std::size_t>(rep.waypointsAdded));
    EXPECT_EQ(wps->front().kind, WaypointKind::Transit);
    std::vector<Vec2> path{Vec2(0, 0)};
    for (const auto& w : *wps)
        path.push_back(w.pos);
    path.push_back(Vec2(50, 0));
    EXPECT_EQ(plan::countNoFlyViolations({path}, zones, 5).total(), 0);
}

TEST(Transit, HomeInsideAMarginIsAnError) {
    const SafePathFinder finder(NoFlyField({square(0, 0, 10)}, 5));
    auto wps = withTransit(line({Vec2(50, 50)}), Vec2(12, 5), finder);
    ASSERT_FALSE(wps.ok());
    EXPECT_EQ(wps.error().message,
              "The home point (12.0, 5.0) m lies within the 5.0 m safety margin of a no-fly zone: move it.");
    auto land = withTransit(line({Vec2(50, 50)}), Vec2(50, 0), finder, Vec2(5, 5));
    ASSERT_FALSE(land.ok());
    EXPECT_EQ(land.error().message,
              "The landing point (5.0, 5.0) m lies within the 5.0 m safety margin of a no-fly zone: move it.");
}
