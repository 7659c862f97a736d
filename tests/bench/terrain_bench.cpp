// Terrain sampling cost: a plan's photos and legs sampled on a large DEM (the terrain stage of
// planMission: the DEM opened and read over the area and its margin, the lowest height above ground
// each camera sees, then every waypoint put at its height above the ground, every leg checked every
// metre and every photo's footprint traced on the terrain).
//
// The DEM is a tiled Float32 GeoTIFF in UTM (1 m pixels, gentle hills) written by the benchmark
// into a temporary directory and deleted afterwards; the plan (one aircraft over a square in the
// DEM's middle) is planned once, outside the timing. BM_TerrainSampling (a 1000 x 1000 px DEM, a
// thousand photos) always runs (CI smoke-runs it); BM_TerrainSamplingBig is the target case, a
// plan of about 10^4 photos on a 10000 x 10000 px (10^8 px, 400 MB) DEM, left out of the smoke run:
//   build/tests/bench/pf_bench --benchmark_filter=TerrainSampling
#include "core/geo/local_frame.h"
#include "core/io/mission_file.h"
#include "core/mission/plan_mission.h"
#include "core/mission/terrain_stage.h"

#include <benchmark/benchmark.h>
#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

using namespace pf;

constexpr double kCentreLon = 8.33, kCentreLat = 49.01;

// A temporary directory removed with everything in it when the benchmark ends.
struct ScratchDir {
    std::filesystem::path path;
    ScratchDir() {
        path = std::filesystem::temp_directory_path() /
               ("pf_terrain_bench_" + std::to_string(::getpid()));
        std::filesystem::create_directories(path);
    }
    ~ScratchDir() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
};

double groundAt(double e, double n) {
    // Rolling ground (30 m waves a few hundred metres long) and a 40 m hill, 200 m above sea level.
    const double hill = 40.0 * std::exp(-(e * e + n * n) / (2 * 500.0 * 500.0));
    return 200.0 + 15.0 * std::sin(e / 420.0) * std::cos(n / 530.0) + hill + 0.02 * n;
}

// A sidePx x sidePx GeoTIFF of 1 m pixels in UTM zone 32 N centred on the site, tiled 256 x 256.
std::string writeDem(const std::filesystem::path& dir, int sidePx, std::string& error) {
    GDALAllRegister();
    const std::string path = (dir / ("dem_" + std::to_string(sidePx) + ".tif")).string();
    GDALDriver* gtiff = GetGDALDriverManager()->GetDriverByName("GTiff");
    const char* opts[] = {"TILED=YES", "BLOCKXSIZE=256", "BLOCKYSIZE=256", "BIGTIFF=IF_SAFER",
                          nullptr};
    GDALDatasetUniquePtr ds(
        gtiff->Create(path.c_str(), sidePx, sidePx, 1, GDT_Float32, const_cast<char**>(opts)));
    if (!ds) {
        error = "cannot create " + path + ": " + CPLGetLastErrorMsg();
        return {};
    }
    OGRSpatialReference utm, geo;
    utm.importFromEPSG(32632);
    geo.SetWellKnownGeogCS("WGS84");
    utm.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    geo.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    std::unique_ptr<OGRCoordinateTransformation> toUtm(
        OGRCreateCoordinateTransformation(&geo, &utm));
    double e0 = kCentreLon, n0 = kCentreLat;
    toUtm->Transform(1, &e0, &n0);
    e0 = std::round(e0);
    n0 = std::round(n0);
    const double half = sidePx / 2.0;
    double gt[6] = {e0 - half, 1.0, 0, n0 + half, 0, -1.0};
    ds->SetGeoTransform(gt);
    ds->SetSpatialRef(&utm);
    GDALRasterBand* band = ds->GetRasterBand(1);
    band->SetNoDataValue(-9999.0);
    constexpr int kStrip = 256;
    std::vector<float> strip(static_cast<std::size_t>(sidePx) * kStrip);
    for (int r0 = 0; r0 < sidePx; r0 += kStrip) {
        const int rows = std::min(kStrip, sidePx - r0);
        for (int r = 0; r < rows; ++r)
            for (int c = 0; c < sidePx; ++c)
                strip[static_cast<std::size_t>(r) * sidePx + c] =
                    static_cast<float>(groundAt(c + 0.5 - half, half - (r0 + r + 0.5)));
        if (band->RasterIO(GF_Write, 0, r0, sidePx, rows, strip.data(), sidePx, rows, GDT_Float32,
                           0, 0, nullptr) != CE_None) {
            error = "cannot write " + path + ": " + CPLGetLastErrorMsg();
            return {};
        }
    }
    return path;
}

// The demo mission's Falcon 8 (60 % side, 70 % front overlap) over a square of `sideM` metres
// centred on the DEM, following the terrain at `heightM`.
Result<mission::Mission> site(double sideM, double heightM, const std::string& dem) {
    auto demo = io::readMissionFile(std::string(PF_RESOURCES_DIR) + "/demo/demo_mission.json");
    if (!demo)
        return demo.error();
    const geo::LocalFrame frame = *geo::LocalFrame::create({kCentreLon, kCentreLat});
    const double h = sideM / 2;
    mission::Mission m;
    m.area = frame.toGeo(geo::Polygon{{{-h, -h}, {h, -h}, {h, h}, {-h, h}}, {}});
    m.home = frame.toGeo(geo::Vec2{-h - 20, -h - 20});
    mission::AircraftConfig a = demo->aircraft.front();
    a.altitudeM = heightM;
    a.gsdCm.reset();
    a.maxAltitudeM = 500;
    a.overlap = {0.7, 0.6};
    a.enduranceMin = 60; // one flight, so that sorties do not add transit legs
    m.aircraft = {a};
    m.options.planner = mission::PlannerKind::Lawnmower;
    m.options.gridAngleDeg = 0.0;
    m.terrain.mode = mission::TerrainMode::Follow;
    m.terrain.demPath = dem;
    return m;
}

void terrainSampling(benchmark::State& state, int demSidePx, double siteM, double heightM) {
    ScratchDir dir;
    std::string error;
    const std::string dem = writeDem(dir.path, demSidePx, error);
    if (dem.empty()) {
        state.SkipWithError(error.c_str());
        return;
    }
    auto demo = site(siteM, heightM, dem);
    if (!demo) {
        state.SkipWithError(demo.error().message.c_str());
        return;
    }
    const mission::Mission& m = *demo;
    auto geom = mission::localGeometry(m);
    auto terrain = geom ? mission::loadMissionTerrain(m, *geom)
                        : Result<std::shared_ptr<const mission::MissionTerrain>>(geom.error());
    if (!terrain) {
        state.SkipWithError(terrain.error().message.c_str());
        return;
    }
    // The plan before terrain following: the same mission planned flat at the planning height.
    mission::Mission flat = mission::planningMission(m, *terrain);
    flat.terrain.prepared.reset();
    flat.terrain.mode = mission::TerrainMode::Off;
    auto plan = mission::planMission(flat);
    if (!plan) {
        state.SkipWithError(plan.error().message.c_str());
        return;
    }
    std::vector<std::optional<geo::Vec2>> homes(plan->aircraft.size(),
                                                geom->frame.toLocal(*m.home));
    std::size_t photos = 0, outlines = 0;
    double readS = 0.0, followS = 0.0;
    for (auto _ : state) {
        const auto start = std::chrono::steady_clock::now();
        auto t = mission::loadMissionTerrain(m, *geom);
        const auto read = std::chrono::steady_clock::now();
        if (!t) {
            state.SkipWithError(t.error().message.c_str());
            return;
        }
        mission::MissionPlan p = *plan;
        std::vector<plan::PhotoFootprint> footprints;
        std::vector<geo::Ring> rings;
        if (auto s = mission::applyTerrain(p, mission::planningMission(m, *t), geom->frame, homes,
                                           std::nullopt, footprints, rings);
            !s) {
            state.SkipWithError(s.error().message.c_str());
            return;
        }
        readS += std::chrono::duration<double>(read - start).count();
        followS += std::chrono::duration<double>(std::chrono::steady_clock::now() - read).count();
        photos = footprints.size();
        outlines = rings.size();
        benchmark::DoNotOptimize(rings.data());
    }
    // Wall-clock seconds per iteration of the two halves: the DEM read over the area (and the
    // lowest height above ground), then terrain following and the footprints.
    state.counters["read_s"] = readS / static_cast<double>(state.iterations());
    state.counters["follow_s"] = followS / static_cast<double>(state.iterations());
    state.counters["photos"] = static_cast<double>(photos);
    state.counters["outlines"] = static_cast<double>(outlines);
    state.counters["dem_px"] = static_cast<double>(demSidePx) * demSidePx;
    state.counters["grid_nodes"] = static_cast<double>((*terrain)->grid->cols()) *
                                   static_cast<double>((*terrain)->grid->rows());
}

void BM_TerrainSampling(benchmark::State& state) {
    terrainSampling(state, 1000, 400.0, 40.0);
}
BENCHMARK(BM_TerrainSampling)->Unit(benchmark::kMillisecond)->Iterations(1);

// About 10^4 photos: a 3 km square at 82 m above ground (0.48 H between lanes, 0.27 H between
// photos).
void BM_TerrainSamplingBig(benchmark::State& state) {
    terrainSampling(state, 10000, 3000.0, 82.0);
}
BENCHMARK(BM_TerrainSamplingBig)->Unit(benchmark::kMillisecond)->Iterations(3);

} // namespace
