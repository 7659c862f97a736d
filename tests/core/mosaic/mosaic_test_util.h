// Shared set-up of the mosaic tests: the demo mission planned for one aircraft, the demo map around
// it for the flight simulator, scratch directories and default options.
#pragma once

#include "core/io/catalog.h"
#include "core/io/mission_file.h"
#include "core/mission/plan_mission.h"
#include "core/mosaic/mosaic_builder.h"
#include "tests/support/flight_simulator.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace pf::mosaic::test {

struct DemoFlight {
    mission::MissionPlan plan;
    PlannedFlight planned;
    std::optional<testsim::GroundImage> ground;
};

// The demo mission's first aircraft (Falcon 8 camera) alone at `altitudeM`, planned, and the demo
// map resampled around the site at `mapResolutionM`.
inline DemoFlight demoFlight(double altitudeM, double mapResolutionM = 0.25) {
    DemoFlight f;
    auto m = io::readMissionFile(std::string(PF_RESOURCES_DIR) + "/demo/demo_mission.json");
    EXPECT_TRUE(m.ok());
    if (!m)
        return f;
    m->aircraft.resize(1);
    m->aircraft[0].altitudeM = altitudeM;
    auto plan = mission::planMission(*m);
    EXPECT_TRUE(plan.ok()) << (plan ? "" : plan.error().message);
    if (!plan)
        return f;
    f.plan = *plan;
    f.planned = plannedFlightFromPlan(*plan);
    const std::string map = testsim::demoMapPath();
    if (map.empty())
        return f;
    auto ground =
        testsim::GroundImage::load(map, f.plan.frame->origin(), 320.0, 240.0, mapResolutionM);
    EXPECT_TRUE(ground.ok()) << (ground ? "" : ground.error().message);
    if (ground)
        f.ground.emplace(std::move(ground).value());
    return f;
}

// A fresh directory under the test's own temporary directory.
inline std::string scratchDir(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir.string();
}

inline MosaicOptions defaultOptions(const std::vector<std::string>& photos,
                                    const std::string& out) {
    MosaicOptions o;
    o.photos = photos;
    o.outputPath = out;
    auto cat = io::loadDefaultCatalog();
    if (cat)
        o.catalog = cat->cameras;
    o.threads = 2;
    return o;
}

inline std::vector<std::string> paths(const std::vector<testsim::SimulatedPhoto>& photos) {
    std::vector<std::string> out;
    for (const auto& p : photos)
        out.push_back(p.path);
    return out;
}

inline const PhotoFinding* findingFor(const MosaicReport& r, const std::string& file) {
    for (const auto& f : r.findings)
        if (f.file == file)
            return &f;
    return nullptr;
}

} // namespace pf::mosaic::test

// Skips a test that needs the demo map when this build has no GUI (the map is drawn with Qt).
#define PF_REQUIRE_DEMO_MAP(flight)                                                                \
    do {                                                                                           \
        if (!(flight).ground)                                                                      \
            GTEST_SKIP()                                                                           \
                << "the demo map is generated only in builds with the GUI (PF_BUILD_UI=ON)";       \
    } while (0)
