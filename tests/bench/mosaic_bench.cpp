// Mosaic speed: photos of a simulated flight over the demo site to a GeoTIFF at twice their GSD.
//
// BM_MosaicSmall (30 photos of 800 x 600) always runs (CI smoke-runs it). The target,
// 200 photos of 4000 x 3000 in at most 90 s and 1.5 GB, runs when PF_MOSAIC_BENCH_DIR names a
// scratch directory: the photos are rendered there once (about 700 MB, a few minutes) and reused by
// later runs, so that `/usr/bin/time -v pf_bench --benchmark_filter=Mosaic200` measures the mosaic
// alone:
//
//   PF_MOSAIC_BENCH_DIR=/tmp/pf_mosaic_bench build/tests/bench/pf_bench
//   --benchmark_filter=Mosaic200
#include "core/io/catalog.h"
#include "core/io/mission_file.h"
#include "core/mission/plan_mission.h"
#include "core/mosaic/mosaic_builder.h"
#include "tests/support/flight_simulator.h"

#include <benchmark/benchmark.h>

#include <sys/resource.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

using namespace pf;

namespace {

struct BenchSet {
    std::vector<std::string> photos;
    mosaic::PlannedFlight planned;
    double photoGsdM = 0.0;
    std::string error;
};

// `count` photos of `width` x 3/4 width of the demo mission's Falcon 8 flown at `altitudeM`, in
// `dir` (rendered only if the directory does not hold this set yet).
BenchSet photoSet(const std::string& dir, int count, int width, double altitudeM) {
    BenchSet s;
    auto m = io::readMissionFile(std::string(PF_RESOURCES_DIR) + "/demo/demo_mission.json");
    if (!m) {
        s.error = m.error().message;
        return s;
    }
    m->aircraft.resize(1);
    m->aircraft[0].altitudeM = altitudeM;
    auto plan = mission::planMission(*m);
    if (!plan) {
        s.error = plan.error().message;
        return s;
    }
    s.planned = mosaic::plannedFlightFromPlan(*plan);
    if (static_cast<int>(s.planned.photos.size()) < count) {
        s.error = "the plan has only " + std::to_string(s.planned.photos.size()) + " photos";
        return s;
    }
    s.planned.photos.resize(count);
    testsim::SimOptions o;
    o.camera.widthPx = width;
    o.camera.heightPx = width * 3 / 4;
    o.grain =
        18.0; // photo-scale texture, so the JPEGs carry (and decode) as much detail as real ones
    o.threads = 2;
    s.photoGsdM = 2.0 * altitudeM * std::tan(o.camera.longSideFovDeg * M_PI / 360.0) / width;
    const std::string marker = dir + "/set.txt";
    const std::string id =
        std::to_string(count) + " " + std::to_string(width) + " " + std::to_string(altitudeM);
    std::string have;
    std::getline(std::ifstream(marker), have);
    for (int i = 1; i <= count; ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "/IMG_%04d.JPG", i);
        s.photos.push_back(dir + name);
    }
    if (have == id)
        return s;
    const std::string map = testsim::demoMapPath();
    if (map.empty()) {
        s.error = "no demo map in this build (it needs the GUI)";
        return s;
    }
    auto ground = testsim::GroundImage::load(map, plan->frame->origin(), 320.0, 240.0, 0.25);
    if (!ground) {
        s.error = ground.error().message;
        return s;
    }
    std::filesystem::create_directories(dir);
    auto photos = testsim::simulateFlight(*ground, s.planned.photos, o, dir);
    if (!photos) {
        s.error = photos.error().message;
        return s;
    }
    std::ofstream(marker) << id << '\n';
    return s;
}

void runMosaic(benchmark::State& state, const BenchSet& set, const std::string& out) {
    if (!set.error.empty()) {
        state.SkipWithError(set.error.c_str());
        return;
    }
    auto cat = io::loadDefaultCatalog();
    mosaic::MosaicOptions o;
    o.photos = set.photos;
    o.plan = set.planned;
    o.catalog = cat ? cat->cameras : std::vector<sensor::Camera>{};
    o.gsdM = 2.0 * set.photoGsdM;
    o.outputPath = out;
    mosaic::MosaicReport report;
    for (auto _ : state) {
        Progress progress;
        auto r = mosaic::buildMosaic(o, progress);
        if (!r) {
            state.SkipWithError(r.error().message.c_str());
            return;
        }
        report = *r;
    }
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    state.counters["photos"] = report.photosUsed;
    state.counters["output_MP"] = report.widthPx * static_cast<double>(report.heightPx) / 1e6;
    state.counters["gsd_cm"] = report.gsdM * 100.0;
    state.counters["peak_RSS_MB"] = ru.ru_maxrss / 1024.0;
    for (const auto& st : report.stages) {
        state.counters[st.name + "_s"] = st.seconds;
        state.counters[st.name + "_cpu_s"] = st.cpuSeconds;
    }
}

void BM_MosaicSmall(benchmark::State& state) {
    const auto dir = std::filesystem::temp_directory_path() / "pf_mosaic_bench_small";
    static const BenchSet set = photoSet(dir.string(), 30, 800, 60.0);
    runMosaic(state, set, (dir / "mosaic.tif").string());
}
BENCHMARK(BM_MosaicSmall)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();

void BM_Mosaic200Photos4000x3000(benchmark::State& state) {
    const std::string dir = std::getenv("PF_MOSAIC_BENCH_DIR");
    static const BenchSet set = photoSet(dir + "/photos", 200, 4000, 76.0);
    runMosaic(state, set, dir + "/mosaic.tif");
}
// Registered only with a scratch directory: rendering its photos takes minutes and 700 MB.
const bool kLargeRegistered = [] {
    if (std::getenv("PF_MOSAIC_BENCH_DIR"))
        benchmark::RegisterBenchmark("BM_Mosaic200Photos4000x3000", BM_Mosaic200Photos4000x3000)
            ->Unit(benchmark::kSecond)
            ->Iterations(1)
            ->UseRealTime();
    return true;
}();

} // namespace
