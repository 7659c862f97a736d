// The upload content is the export's content: same items as the .waypoints file, fence, rally.
#include "core/mavlink/vehicle_plan.h"

#include "core/io/mission_items.h"
#include "core/io/qgc_wpl.h"
#include "tests/core/io/formats_test_util.h"

#include <gtest/gtest.h>

using namespace pf;

TEST(VehiclePlan, TheItemsAreTheWaypointsFileLinesWithTheHomeApart) {
    std::mt19937 rng(51);
    io::ExportContext ctx = io::makeExportContext(test::demoMission(), {test::randomRoute(rng, "A")});
    io::ExportOptions opt;
    opt.trigger = io::CameraTrigger::Distance;
    auto plan = mavlink::vehiclePlanFor(ctx, 0, opt);
    ASSERT_TRUE(plan.ok());
    // Every line of the .waypoints file is one uploaded item, in the same order (line 0: home).
    const std::string wpl = *io::qgcWplText(ctx, 0, opt);
    const auto lines = std::count(wpl.begin(), wpl.end(), '\n') - 1;
    ASSERT_TRUE(plan->home.has_value());
    ASSERT_EQ(static_cast<long>(plan->mission.size()) + 1, lines);
    const auto items = *io::missionItems(ctx, 0, opt);
    ASSERT_EQ(items.size(), plan->mission.size());
    for (std::size_t i = 0; i < items.size(); ++i) {
        const auto& w = plan->mission[i];
        EXPECT_EQ(w.command, items[i].command);
        if (items[i].hasPosition()) {
            EXPECT_EQ(w.x, std::lround(items[i].params[4] * 1e7));
            EXPECT_EQ(w.y, std::lround(items[i].params[5] * 1e7));
            EXPECT_FLOAT_EQ(w.z, static_cast<float>(items[i].params[6]));
        }
    }
    EXPECT_EQ(plan->home->frame, 0); // home, above sea level
    EXPECT_EQ(plan->home->x, std::lround(ctx.mission.home->lat * 1e7));
    EXPECT_EQ(plan->mission[0].command, io::mav::kNavTakeoff);
    EXPECT_EQ(plan->fence.size(), 20u);
    EXPECT_EQ(plan->fence[0].command, 5002);
    EXPECT_EQ(plan->rally.size(), 1u);
}

TEST(VehiclePlan, AnEmptyRouteIsRefusedWithItsName) {
    io::ExportContext ctx = io::makeExportContext(test::demoMission(), {route::Route{"Falcon 8", {}, 8, {}}});
    auto plan = mavlink::vehiclePlanFor(ctx, 0);
    ASSERT_FALSE(plan.ok());
    EXPECT_NE(plan.error().message.find("Falcon 8"), std::string::npos);
}
