// Independent check: GDAL's own ogrinfo must read what we write and count the features we expect.
#include "core/io/waypoint_formats.h"

#include "tests/core/io/formats_test_util.h"

#include <gtest/gtest.h>

#include <map>
#include <regex>

using namespace pf;
using namespace pf::io;

namespace {

// Layer name -> "Feature Count" from `ogrinfo -ro -al -so FILE`.
std::map<std::string, int> ogrinfoCounts(const std::string& path, int* status) {
    const auto r = test::run("ogrinfo -ro -al -so '" + path + "'");
    *status = r.status;
    std::map<std::string, int> counts;
    std::regex layer("Layer name: (.*)"), count("Feature Count: ([0-9]+)");
    std::string current;
    std::istringstream in(r.output);
    std::string line;
    std::smatch m;
    while (std::getline(in, line)) {
        if (std::regex_search(line, m, layer))
            current = m[1];
        else if (std::regex_search(line, m, count))
            counts[current] = std::stoi(m[1]);
    }
    return counts;
}

class OgrinfoReads : public ::testing::Test {
protected:
    void SetUp() override {
        if (!test::haveOgrinfo())
            GTEST_SKIP() << "ogrinfo is not installed (package gdal-bin)";
        dir = test::scratchDir("ogrinfo");
        std::mt19937 rng(41);
        std::vector<route::Route> routes{test::randomRoute(rng, "Falcon 8 #1"),
                                         test::randomRoute(rng, "Alpha")};
        ctx = makeExportContext(test::demoMission(), routes);
        ctx.footprints = {sensor::Footprint{60, 40}, sensor::Footprint{30, 20}};
        ctx.trajectories = {{{8.328, 49.011}, {8.329, 49.012}}, {}};
        for (const auto& r : ctx.routes) {
            waypoints += r.waypoints.size();
            for (const auto& w : r.waypoints)
                photos += w.kind == route::WaypointKind::Photo;
        }
    }
    std::string dir;
    ExportContext ctx;
    int waypoints = 0;
    int photos = 0;
};

} // namespace

TEST_F(OgrinfoReads, Kml) {
    ASSERT_TRUE(exportCombined(ctx, WaypointFormat::Kml, dir + "/all.kml").ok());
    int status = -1;
    const auto counts = ogrinfoCounts(dir + "/all.kml", &status);
    ASSERT_EQ(status, 0);
    EXPECT_EQ(counts.at("Rheinhafen training ground"), 1 + 2 + 1); // area, two zones, home
    // Path, photo points and footprints; the first route also has a trajectory.
    const auto& r0 = ctx.routes[0].waypoints;
    const auto& r1 = ctx.routes[1].waypoints;
    auto photosOf = [](const std::vector<route::Waypoint>& w) {
        return static_cast<int>(std::count_if(w.begin(), w.end(), [](const route::Waypoint& x) {
            return x.kind == route::WaypointKind::Photo;
        }));
    };
    EXPECT_EQ(counts.at("Falcon 8 #1"), 2 + 2 * photosOf(r0));
    EXPECT_EQ(counts.at("Alpha"), 1 + 2 * photosOf(r1));
}

TEST_F(OgrinfoReads, Gpx) {
    ASSERT_TRUE(exportCombined(ctx, WaypointFormat::Gpx, dir + "/all.gpx").ok());
    int status = -1;
    const auto counts = ogrinfoCounts(dir + "/all.gpx", &status);
    ASSERT_EQ(status, 0);
    EXPECT_EQ(counts.at("waypoints"), waypoints);
    EXPECT_EQ(counts.at("routes"), 2);
    EXPECT_EQ(counts.at("route_points"), waypoints);
}

TEST_F(OgrinfoReads, GeoJson) {
    ASSERT_TRUE(exportCombined(ctx, WaypointFormat::GeoJson, dir + "/all.geojson").ok());
    int status = -1;
    const auto counts = ogrinfoCounts(dir + "/all.geojson", &status);
    ASSERT_EQ(status, 0);
    ASSERT_EQ(counts.size(), 1u);
    // Area, two zones, home, a path per route and every waypoint.
    EXPECT_EQ(counts.begin()->second, 1 + 2 + 1 + 2 + waypoints);
}

TEST_F(OgrinfoReads, PerAircraftFilesToo) {
    for (auto fmt : {WaypointFormat::Kml, WaypointFormat::Gpx, WaypointFormat::GeoJson}) {
        const std::string path = dir + "/one" + formatInfo(fmt).extension;
        ASSERT_TRUE(exportRoute(ctx, 1, fmt, path).ok());
        int status = -1;
        const auto counts = ogrinfoCounts(path, &status);
        EXPECT_EQ(status, 0) << path;
        EXPECT_FALSE(counts.empty()) << path;
    }
}
