// pf_simulate_flight: the test flight simulator as a command, to try the mosaic without a drone:
// plans a mission, renders the photos each aircraft would take over the synthetic demo map and
// writes them (with EXIF GPS and DJI-style XMP) and the plan. Not installed; a development tool.
//
// Usage: pf_simulate_flight MISSION.json OUTDIR [--width PX] [--noise-pos M] [--noise-angle DEG]
//                           [--seed N] [--map FILE.tif]
// Writes OUTDIR/photos/AC1_0001.JPG, ... (AC2_ for the second aircraft, ...) and
// OUTDIR/plan/plan.geojson.
#include "core/io/mission_file.h"
#include "core/mission/plan_geojson.h"
#include "core/mission/plan_mission.h"
#include "core/sensor/camera.h"
#include "tests/support/flight_simulator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

using namespace pf;

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(
            stderr,
            "usage: %s MISSION.json OUTDIR [--width PX] [--noise-pos M] [--noise-angle DEG] "
            "[--seed N] [--map FILE.tif]\n",
            argv[0]);
        return 2;
    }
    int width = 480;
    testsim::SimOptions base;
    std::string map = testsim::demoMapPath();
    for (int i = 3; i + 1 < argc; i += 2) {
        const std::string a = argv[i], v = argv[i + 1];
        if (a == "--width")
            width = std::atoi(v.c_str());
        else if (a == "--noise-pos")
            base.positionNoiseM = std::atof(v.c_str());
        else if (a == "--noise-angle")
            base.angleNoiseDeg = std::atof(v.c_str());
        else if (a == "--seed")
            base.seed = static_cast<unsigned>(std::atoi(v.c_str()));
        else if (a == "--map")
            map = v;
        else {
            std::fprintf(stderr, "unknown option %s\n", a.c_str());
            return 2;
        }
    }
    if (map.empty()) {
        std::fprintf(stderr, "no demo map in this build: give --map FILE.tif\n");
        return 2;
    }
    auto mission = io::readMissionFile(argv[1]);
    if (!mission) {
        std::fprintf(stderr, "%s\n", mission.error().message.c_str());
        return 2;
    }
    auto plan = mission::planMission(*mission);
    if (!plan) {
        std::fprintf(stderr, "%s\n", plan.error().message.c_str());
        return 2;
    }
    const std::filesystem::path out(argv[2]);
    std::filesystem::create_directories(out / "plan");
    std::ofstream(out / "plan" / "plan.geojson") << mission::planToGeoJson(*plan);
    auto ground = testsim::GroundImage::load(map, plan->frame->origin(), 400.0, 300.0, 0.25);
    if (!ground) {
        std::fprintf(stderr, "%s\n", ground.error().message.c_str());
        return 1;
    }
    const auto flight = mosaic::plannedFlightFromPlan(*plan);
    int total = 0;
    for (std::size_t a = 0; a < plan->aircraft.size(); ++a) {
        const auto& cfg = mission->aircraft[a];
        testsim::SimOptions o = base;
        o.seed = base.seed + static_cast<unsigned>(a);
        o.camera.longSideFovDeg = sensor::horizontalFovDeg(cfg.camera);
        o.camera.shortSideFovDeg = sensor::verticalFovDeg(cfg.camera);
        o.camera.widthPx = width;
        o.camera.heightPx =
            static_cast<int>(std::lround(width * static_cast<double>(cfg.camera.imageHeightPx) /
                                         std::max(1, cfg.camera.imageWidthPx)));
        o.camera.model = cfg.camera.name;
        o.threads = 2;
        o.namePrefix = "AC" + std::to_string(a + 1) + "_";
        o.firstIndex = 1;
        std::vector<mosaic::PlannedPhoto> photos;
        for (const auto& p : flight.photos)
            if (p.aircraft == plan->aircraft[a].aircraft)
                photos.push_back(p);
        auto sim = testsim::simulateFlight(*ground, photos, o, (out / "photos").string());
        if (!sim) {
            std::fprintf(stderr, "%s\n", sim.error().message.c_str());
            return 1;
        }
        total += static_cast<int>(sim->size());
        std::printf("%s: %zu photos (%s, %d x %d px)\n", plan->aircraft[a].aircraft.c_str(),
                    sim->size(), cfg.camera.name.c_str(), o.camera.widthPx, o.camera.heightPx);
    }
    std::printf("wrote %d photos to %s and the plan to %s\n", total,
                (out / "photos").string().c_str(), (out / "plan").string().c_str());
    return 0;
}
