// Large inputs: an area beyond the cell budget is refused with advice, and planning about 10^6 cells
// stays well inside the memory of an ordinary laptop (peak resident memory read from /proc).
#include "core/io/mission_file.h"
#include "core/mission/plan_mission.h"
#include "core/mission/validation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

namespace {

using namespace pf;

// Peak resident set size of this process in kB (VmHWM), or -1 if /proc is not available.
long peakRssKb() {
    std::ifstream in("/proc/self/status");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("VmHWM:", 0) == 0) return std::stol(line.substr(6));
    return -1;
}

// The demo mission with one aircraft over a square area of about `side` metres centred on the site.
mission::Mission squareMission(double sideM) {
    auto demo = io::readMissionFile(std::string(PF_RESOURCES_DIR) + "/demo/demo_mission.json");
    EXPECT_TRUE(demo) << (demo ? "" : demo.error().message);
    mission::Mission m = demo ? demo.value() : mission::Mission{};
    const double lat0 = 49.0, lon0 = 8.33;
    const double dLat = sideM / 111'200.0;
    const double dLon = sideM / (111'320.0 * std::cos(lat0 * M_PI / 180.0));
    m.area = geo::GeoPolygon{};
    m.area.outer = {{lon0, lat0}, {lon0 + dLon, lat0}, {lon0 + dLon, lat0 + dLat}, {lon0, lat0 + dLat}};
    m.noFlyZones.clear();
    m.home = geo::LonLat{lon0 - 0.0005, lat0 - 0.0005};
    m.aircraft.resize(1);
    m.options.gridAngleDeg = 0.0; // one grid, not the angle search
    return m;
}

TEST(LargeInput, AreaBeyondTheBudgetIsRefusedWithAdvice) {
    mission::Mission m = squareMission(20'000.0);
    m.options.maxCells = 100'000;
    // The check before planning (what the CLI and the GUI show): the altitude that would fit.
    const mission::ValidationReport report = mission::validateMission(m);
    ASSERT_TRUE(report.hasErrors());
    const std::string summary = report.errorSummary();
    EXPECT_NE(summary.find("the area is too large for the cell budget"), std::string::npos) << summary;
    EXPECT_NE(summary.find("more than the budget of 100,000"), std::string::npos) << summary;
    EXPECT_NE(summary.find("an altitude of at least"), std::string::npos) << summary;
    EXPECT_NE(summary.find("would fit"), std::string::npos) << summary;
    // Planning anyway is refused before any per-cell memory is taken, with the cell size that fits.
    const auto plan = mission::planMission(m);
    ASSERT_FALSE(plan);
    const std::string& msg = plan.error().message;
    EXPECT_NE(msg.find("the area is too large for the cell budget"), std::string::npos) << msg;
    EXPECT_NE(msg.find("more than the budget of 100,000"), std::string::npos) << msg;
    EXPECT_NE(msg.find("a cell size of at least"), std::string::npos) << msg;
    EXPECT_NE(msg.find("would fit"), std::string::npos) << msg;
}

// About 10^6 cells (Falcon 8 at 40 m: 16.8 m cells, a 16.8 km square). Labelled "large" in CTest.
TEST(LargeInput, PlanningAMillionCellsStaysUnderOneGigabyte) {
    mission::Mission m = squareMission(16'800.0);
    // One long flight: the test is about memory, not about splitting the route into sorties.
    m.aircraft.front().enduranceMin = 1e6;
    // The grid planner's memory (the automatic choice plans with each planner in turn at this size,
    // so its peak is that of the largest one).
    m.options.planner = mission::PlannerKind::Stride;
    const auto plan = mission::planMission(m);
    ASSERT_TRUE(plan) << plan.error().message;
    ASSERT_EQ(plan->aircraft.size(), 1u);
    const auto& a = plan->aircraft.front();
    EXPECT_GT(a.grid.cellCount(), 900'000);
    EXPECT_LT(a.grid.cellCount(), 1'200'000);
    EXPECT_GT(a.metrics.photos, 100'000);
    EXPECT_GT(a.route.waypoints.size(), 1000u);
    const long peak = peakRssKb();
    ASSERT_GT(peak, 0);
    RecordProperty("peak_rss_kb", std::to_string(peak));
    std::printf("peak resident memory while planning %d cells: %.0f MB\n", a.grid.cellCount(), peak / 1024.0);
    EXPECT_LT(peak, 1024L * 1024L) << "peak resident memory " << peak << " kB";
}

} // namespace
