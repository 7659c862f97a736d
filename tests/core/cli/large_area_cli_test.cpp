// photoflight-cli on a traced boundary of 200,000 vertices: planned simplified within a tolerance
// far below the footprint, saying so; an area with too many vertices even then is refused with the
// limit.
#include "tests/core/cli/cli_test_util.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace pf::cli::test;

// A GeoJSON area file: a field of about 1.4 km across traced every 2 cm with tracing noise
// (`spikes` = 0), or a star of `spikes` teeth 5 m deep that no simplification can thin.
// `swapAt` > 0: vertices swapAt and swapAt + 3 (numbered from 1) trade places, a crossing 2 cm
// long.
std::string writeArea(const std::string& name, int vertices, int spikes = 0, int swapAt = 0) {
    const std::string path = testing::TempDir() + name;
    std::ofstream out(path);
    out << "{\"type\":\"FeatureCollection\",\"features\":[{\"type\":\"Feature\",\"properties\":{},"
           "\"geometry\":{\"type\":\"Polygon\",\"coordinates\":[[";
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> jitter(-0.1, 0.1);
    double noise = 0.0;
    const double lat0 = 49.0, lon0 = 8.33;
    const int n = spikes > 0 ? 2 * spikes : vertices;
    char buf[64];
    std::vector<std::string> pts;
    for (int i = 0; i < n; ++i) {
        const double t = 2.0 * M_PI * i / n;
        double r;
        if (spikes > 0) {
            r = 800.0 + (i % 2 ? 5.0 : 0.0);
        } else {
            noise = 0.9 * noise + jitter(rng);
            r = 700.0 * (1.0 + 0.12 * std::sin(3.0 * t) + 0.05 * std::cos(7.0 * t)) + noise;
        }
        const double lat = lat0 + r * std::sin(t) / 111'200.0;
        const double lon = lon0 + r * std::cos(t) / (111'320.0 * std::cos(lat0 * M_PI / 180.0));
        std::snprintf(buf, sizeof buf, "[%.9f,%.9f]", lon, lat);
        pts.push_back(buf);
    }
    if (swapAt > 0)
        std::swap(pts[static_cast<std::size_t>(swapAt - 1)], pts[static_cast<std::size_t>(swapAt + 2)]);
    for (const auto& p : pts)
        out << (&p == &pts.front() ? "" : ",") << p;
    out << "," << pts.front() << "]]}}]}\n"; // the ring closed
    return path;
}

} // namespace

TEST(CliLargeArea, TracedBoundaryOf200000VerticesIsPlannedSimplified) {
    const std::string area = writeArea("pf_traced_200k.geojson", 200'000);
    const CliRun r = cli("plan '" + area + "' --altitude 100 --quiet");
    std::remove(area.c_str());
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(has(r.err, "the area's traced boundary of 200,000 vertices was simplified to "))
        << r.err;
    EXPECT_TRUE(has(r.err, " within 0.50 m ")) << r.err;
    EXPECT_TRUE(has(r.err, " m2 (+")) << r.err;
    EXPECT_TRUE(has(r.out, "coverage 100.0 %")) << r.out;
}

TEST(CliLargeArea, TooManyVerticesAfterSimplifyingAreRefusedWithTheLimit) {
    const std::string area = writeArea("pf_serrated_30k.geojson", 0, 15'000);
    for (const char* command : {"validate", "plan"}) {
        SCOPED_TRACE(command);
        const CliRun r = cli(std::string(command) + " '" + area + "' --altitude 100");
        EXPECT_EQ(r.code, 2) << r.out << r.err;
        EXPECT_TRUE(has(r.err, "photoflight-cli: error: the area has ")) << r.err;
        EXPECT_TRUE(has(
            r.err, " vertices after simplifying to 0.50 m; Photoflight plans areas of at most "
                   "20,000 vertices (area and no-fly zones together): simplify it in a GIS first"))
            << r.err;
    }
    std::remove(area.c_str());
}

// A crossing in a traced boundary is named as in a small polygon, without searching every pair of
// its 200,000 edges.
TEST(CliLargeArea, CrossingInATracedBoundaryIsNamed) {
    const std::string area = writeArea("pf_traced_crossing.geojson", 200'000, 0, 150'000);
    const CliRun r = cli("validate '" + area + "' --altitude 100");
    std::remove(area.c_str());
    EXPECT_EQ(r.code, 2) << r.out << r.err;
    EXPECT_TRUE(has(r.err, "photoflight-cli: error: the area intersects itself: edges 150000-150001 and "
                           "150002-150003 cross near "))
        << r.err;
}
