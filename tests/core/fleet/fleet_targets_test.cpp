// The fleet issue's targets, measured end to end through planMission on the sample areas: coverage by
// the real footprints >= 0.995 and no no-fly margin breach for stride and wavefront, and a makespan
// within 1.10 x the ideal with 2 to 4 mixed catalog aircraft. Set PF_FULL_TARGETS=1 to run the whole
// matrix (every area, planner and fleet size) instead of the representative subset.
#include "core/io/catalog.h"
#include "core/mission/plan_mission.h"
#include "core/plan/evaluation.h"
#include "tests/sample_missions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace pf::fleet {
namespace {

const std::vector<std::string> kAreas{"a_concave", "b_teeth", "c_l_shape", "d_nofly", "e_staircase", "f_complex"};

bool fullMatrix() {
    const char* v = std::getenv("PF_FULL_TARGETS");
    return v && std::string(v) == "1";
}

// The mission of a sample area (see test::sampleAreaMission).
mission::Mission sampleMission(const std::string& area) {
    auto ea = plan::loadEvalArea(std::string(PF_RESOURCES_DIR) + "/areas/" + area + ".geojson");
    EXPECT_TRUE(ea.ok()) << area << ": " << (ea.ok() ? "" : ea.error().message);
    if (!ea.ok())
        return {};
    mission::Mission m = test::sampleAreaMission(*ea);
    m.name = area;
    return m;
}

const io::Catalog& catalog() {
    static const io::Catalog cat = [] {
        auto c = io::loadCatalog(std::string(PF_RESOURCES_DIR) + "/catalog.json");
        EXPECT_TRUE(c.ok());
        return c.ok() ? *c : io::Catalog{};
    }();
    return cat;
}

// Mixed fleets: different cameras, altitudes, speeds and turn rates.
std::vector<mission::AircraftConfig> mixedFleet(int n) {
    const std::vector<std::pair<std::string, double>> all{{"Falcon 8", 50.0},
                                                          {"DJI Phantom 4 Pro", 60.0},
                                                          {"DJI Mavic 3 Enterprise", 70.0},
                                                          {"DJI Matrice 300 RTK", 80.0}};
    std::vector<mission::AircraftConfig> out;
    for (int k = 0; k < n; ++k) {
        const auto& [name, altitude] = all[static_cast<std::size_t>(k)];
        auto a = test::catalogAircraft(catalog(), name, altitude);
        EXPECT_TRUE(a.has_value()) << name;
        if (a)
            out.push_back(*a);
    }
    return out;
}

TEST(FleetTargets, EverySampleAreaCoveredWithoutMarginBreach) {
    const std::vector<mission::PlannerKind> planners{mission::PlannerKind::Stride, mission::PlannerKind::Wavefront};
    for (const auto& area : kAreas) {
        for (auto kind : planners) {
            mission::Mission m = sampleMission(area);
            m.aircraft = mixedFleet(1);
            m.options.planner = kind;
            auto plan = mission::planMission(m);
            ASSERT_TRUE(plan.ok()) << area << ": " << plan.error().message;
            std::printf("%-12s %-9s coverage %.4f violations %d jumps %d\n", area.c_str(),
                        kind == mission::PlannerKind::Stride ? "stride" : "wavefront", plan->coverageRatio,
                        plan->noFlyViolations, plan->totals.jumps);
            EXPECT_GE(plan->coverageRatio, 0.995) << area;
            EXPECT_EQ(plan->noFlyViolations, 0) << area;
            EXPECT_EQ(plan->totals.jumps, 0) << area;
        }
    }
}

// The raster baseline may jump over holes: the plan reports them (metrics and a warning) and the
// safety stage still flies every jump around the no-fly zones.
TEST(FleetTargets, RasterReportsItsJumpsAndStaysSafe) {
    mission::Mission m = sampleMission("d_nofly");
    m.aircraft = mixedFleet(1);
    m.options.planner = mission::PlannerKind::Raster;
    auto plan = mission::planMission(m);
    ASSERT_TRUE(plan.ok()) << plan.error().message;
    EXPECT_GT(plan->totals.jumps, 0);
    bool warned = false;
    for (const auto& w : plan->warnings)
        warned = warned || (w.find(std::to_string(plan->totals.jumps) + " leg(s) join parts") != std::string::npos &&
                            w.find("flown straight where that is safe") != std::string::npos);
    EXPECT_TRUE(warned);
    EXPECT_EQ(plan->noFlyViolations, 0);
    EXPECT_GE(plan->coverageRatio, 0.995);
}

TEST(FleetTargets, MakespanWithinTenPercentOfIdeal) {
    struct Case {
        std::string area;
        int aircraft;
    };
    std::vector<Case> cases;
    if (fullMatrix()) {
        for (const auto& a : kAreas)
            for (int n = 2; n <= 4; ++n)
                cases.push_back({a, n});
    } else {
        // c_l_shape with 4 aircraft: the case that ended at 1.118 x the ideal while the split was
        // balanced on the cell-path time and started from one aircraft order only.
        cases = {{"a_concave", 2}, {"d_nofly", 3}, {"c_l_shape", 4}, {"f_complex", 4}};
    }
    for (const auto& c : cases) {
        mission::Mission m = sampleMission(c.area);
        m.aircraft = mixedFleet(c.aircraft);
        auto plan = mission::planMission(m);
        ASSERT_TRUE(plan.ok()) << c.area << ": " << plan.error().message;
        ASSERT_EQ(plan->aircraft.size(), static_cast<std::size_t>(c.aircraft));
        const double ratio = plan->makespanS / plan->idealS;
        std::printf("%-12s %d aircraft: makespan %.0f s, ideal %.0f s, ratio %.3f, coverage %.4f, violations %d, "
                    "photos saved %d\n",
                    c.area.c_str(), c.aircraft, plan->makespanS, plan->idealS, ratio, plan->coverageRatio,
                    plan->noFlyViolations, plan->photosSaved);
        EXPECT_LE(ratio, 1.10) << c.area << " with " << c.aircraft << " aircraft";
        EXPECT_GE(plan->coverageRatio, 0.995) << c.area;
        EXPECT_EQ(plan->noFlyViolations, 0) << c.area;
        // Each aircraft's time is the sum of its sorties, each within its battery.
        for (const auto& a : plan->aircraft) {
            double sum = 0.0;
            for (const auto& s : a.sorties)
                sum += s.timeS;
            EXPECT_NEAR(sum, a.timeS, 1e-6);
        }
    }
}

} // namespace
} // namespace pf::fleet
