// Area import: every supported format, projected and 3D inputs, multipolygons, and each kind of bad
// file, against the fixtures made by tests/data/import/make_fixtures.sh.
#include "core/io/area_import.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

using namespace pf;
using namespace pf::io;

namespace {

std::string fixture(const std::string& name) { return std::string(PF_TEST_DATA_DIR) + "/import/" + name; }

// The coordinates make_fixtures.sh starts from (WGS84), rings open.
const geo::GeoRing kArea = {{8.3272608, 49.0109209}, {8.3324653, 49.0108309}, {8.3327392, 49.0123597},
                            {8.3308218, 49.0125396}, {8.3305478, 49.0133489}, {8.3273978, 49.013259}};
const geo::GeoRing kWarehouse = {
    {8.3291782, 49.0118201}, {8.3297261, 49.0118201}, {8.3297261, 49.0121799}, {8.3291782, 49.0121799}};

// Same vertices within `tol` degrees, in any start vertex and orientation (formats such as the
// Shapefile impose their own ring direction).
::testing::AssertionResult sameRing(const geo::GeoRing& expected, const geo::GeoRing& actual, double tol) {
    if (expected.size() != actual.size())
        return ::testing::AssertionFailure()
               << "expected " << expected.size() << " vertices, got " << actual.size();
    for (const auto& p : expected) {
        bool found = false;
        for (const auto& q : actual)
            found = found || (std::abs(p.lon - q.lon) <= tol && std::abs(p.lat - q.lat) <= tol);
        if (!found)
            return ::testing::AssertionFailure() << "vertex " << p.lon << ", " << p.lat << " is missing";
    }
    return ::testing::AssertionSuccess();
}

const ImportedPolygon* byName(const std::vector<ImportedPolygon>& polys, const std::string& name) {
    for (const auto& p : polys)
        if (p.name == name)
            return &p;
    return nullptr;
}

// The area with the warehouse as its hole, and the warehouse, whatever the format and CRS.
void expectDemoArea(const std::string& file, double tol) {
    SCOPED_TRACE(file);
    auto r = importPolygons(fixture(file));
    ASSERT_TRUE(r) << r.error().message;
    ASSERT_EQ(r->size(), 2u);
    const auto* area = byName(*r, "Rheinhafen");
    const auto* warehouse = byName(*r, "Warehouse");
    ASSERT_TRUE(area && warehouse) << "names: " << (*r)[0].name << ", " << (*r)[1].name;
    EXPECT_TRUE(sameRing(kArea, area->polygon.outer, tol));
    ASSERT_EQ(area->polygon.holes.size(), 1u);
    EXPECT_TRUE(sameRing(kWarehouse, area->polygon.holes[0], tol));
    EXPECT_TRUE(sameRing(kWarehouse, warehouse->polygon.outer, tol));
    EXPECT_TRUE(warehouse->polygon.holes.empty());
    EXPECT_FALSE(area->layer.empty());
}

std::string errorOf(const std::string& file) {
    auto r = importPolygons(fixture(file));
    if (r)
        return "<imported>";
    std::string msg = r.error().message;
    const std::string prefix = fixture("");
    if (msg.rfind(prefix, 0) == 0)
        msg = msg.substr(prefix.size());
    return msg;
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

} // namespace

// Coordinates in WGS84 files come back as written; reprojected ones within 1e-7 deg (about 1 cm).
TEST(AreaImport, GeoJson) { expectDemoArea("area.geojson", 0.0); }
TEST(AreaImport, Kml) { expectDemoArea("area.kml", 1e-9); }
TEST(AreaImport, ShapefileInUtm32) { expectDemoArea("area_25832.shp", 1e-7); }
TEST(AreaImport, GeoPackageInWebMercator) { expectDemoArea("area_3857.gpkg", 1e-7); }
TEST(AreaImport, GmlWithLatitudeFirstAxisOrder) { expectDemoArea("area.gml", 1e-9); }
TEST(AreaImport, GmlInUtm32) { expectDemoArea("area_25832.gml", 1e-7); }
TEST(AreaImport, ShapefileWithoutPrjButLonLatCoordinates) { expectDemoArea("noprj_lonlat.shp", 1e-9); }

TEST(AreaImport, ThreeDimensionalInputIsFlattened) {
    for (const char* file : {"area_3d.geojson", "area_3d.gpkg"}) {
        SCOPED_TRACE(file);
        auto r = importPolygons(fixture(file));
        ASSERT_TRUE(r) << r.error().message;
        ASSERT_EQ(r->size(), 1u);
        EXPECT_EQ((*r)[0].name, "Rheinhafen 3D");
        EXPECT_TRUE(sameRing(kArea, (*r)[0].polygon.outer, 1e-9));
    }
}

TEST(AreaImport, MultiPolygonsAreSplitAndUnnamedFeaturesGetLayerAndId) {
    for (const char* file : {"multi.geojson", "multi.kml", "multi.shp"}) {
        SCOPED_TRACE(file);
        auto r = importPolygons(fixture(file));
        ASSERT_TRUE(r) << r.error().message;
        ASSERT_EQ(r->size(), 3u);
        const auto* p1 = byName(*r, "Two parcels (part 1)");
        const auto* p2 = byName(*r, "Two parcels (part 2)");
        ASSERT_TRUE(p1 && p2) << (*r)[0].name << " / " << (*r)[1].name;
        // Part 1 is the rectangle, part 2 the triangle.
        EXPECT_TRUE(sameRing({{8.3280, 49.0140}, {8.3290, 49.0140}, {8.3290, 49.0146}, {8.3280, 49.0146}},
                             p1->polygon.outer, 1e-9));
        EXPECT_TRUE(sameRing({{8.3300, 49.0140}, {8.3312, 49.0140}, {8.3312, 49.0147}}, p2->polygon.outer, 1e-9));
        // The third feature has no name: "<layer> #<fid>".
        const std::string third = (*r)[2].name;
        EXPECT_TRUE(startsWith(third, (*r)[2].layer + " #")) << third;
        EXPECT_EQ((*r)[2].layer, "multi");
    }
}

TEST(AreaImport, ImportsFromSeveralThreadsAtOnce) {
    // GDAL is initialised once, whichever thread comes first; each import reports its own errors.
    std::vector<std::thread> threads;
    std::vector<int> ok(8, 0);
    for (int i = 0; i < 8; ++i)
        threads.emplace_back([i, &ok] {
            const bool good = i % 2 == 0;
            auto r = importPolygons(fixture(good ? "area_25832.shp" : "corrupt.geojson"));
            ok[static_cast<std::size_t>(i)] = (r.ok() == good) ? 1 : 0;
        });
    for (auto& t : threads)
        t.join();
    for (int v : ok)
        EXPECT_EQ(v, 1);
}

TEST(AreaImport, GdalPrintsNothingOnStderr) {
    // GDAL's own "ERROR 1: ..." lines would duplicate (and precede) the product's message.
    const std::string capture = ::testing::TempDir() + "pf_import_stderr.txt";
    std::fflush(stderr);
    const int saved = ::dup(2);
    const int fd = ::open(capture.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ASSERT_GE(fd, 0);
    ::dup2(fd, 2);
    auto a = importPolygons(fixture("corrupt.geojson"));
    auto b = importPolygons(fixture("corrupt.kml"));
    auto c = importPolygons(fixture("corrupt.shp"));
    std::fflush(stderr);
    ::dup2(saved, 2);
    ::close(saved);
    ::close(fd);
    EXPECT_FALSE(a || b || c);
    std::ifstream in(capture);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str(), "");
    std::remove(capture.c_str());
}

// ---- bad input: each with the message the user sees ----

TEST(AreaImportErrors, MissingFileOrFolder) {
    EXPECT_EQ(errorOf("no_such_file.geojson"), "no_such_file.geojson: cannot import: the file does not exist");
    auto r = importPolygons(std::string(PF_TEST_DATA_DIR) + "/import");
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().message, std::string(PF_TEST_DATA_DIR) + "/import: cannot import: this is a folder, not a file");
}

TEST(AreaImportErrors, ProjectedCoordinatesWithoutCrs) {
    EXPECT_EQ(errorOf("noprj_25832.shp"),
              // UTM 32N: 8.33 deg E is 0.67 deg west of the central meridian 9 deg E, about 49 km at
              // 49 deg N, so x = 500 000 - 49 000 = 451 000 m; y = about 5 429 000 m.
              "noprj_25832.shp: layer 'noprj_25832' has no coordinate reference system and its coordinates "
              "(x 450805..451207, y 5428874..5429156) are not longitude/latitude; save the file with its CRS (for "
              "a Shapefile, the .prj file beside it)");
}

TEST(AreaImportErrors, NoPolygonInTheFile) {
    EXPECT_EQ(errorOf("points.geojson"), "points.geojson: no polygon to import: it has 2 feature(s), only points or lines");
    EXPECT_EQ(errorOf("empty.geojson"), "empty.geojson: no polygon to import: it has no features");
    EXPECT_EQ(importPolygons(fixture("points.geojson")).error().code, ErrorCode::InvalidGeometry);
}

TEST(AreaImportErrors, DamagedFiles) {
    EXPECT_EQ(errorOf("corrupt.geojson"), "corrupt.geojson: cannot read the file: it is damaged or not a valid "
                                          "GeoJSON file (At line 6, character 41: Unterminated array)");
    EXPECT_EQ(errorOf("corrupt.kml"), "corrupt.kml: cannot read the file: it is damaged or not a valid KML file "
                                      "(ERROR parsing kml " + fixture("corrupt.kml") +
                                      " :no element found on line 8 at offset 125)");
    EXPECT_TRUE(startsWith(errorOf("corrupt.shp"),
                           "corrupt.shp: cannot read the file: it is damaged or not a valid Shapefile file"))
        << errorOf("corrupt.shp");
    EXPECT_TRUE(startsWith(errorOf("corrupt.gpkg"),
                           "corrupt.gpkg: cannot read the file: it is damaged or not a valid GeoPackage file"))
        << errorOf("corrupt.gpkg");
    EXPECT_EQ(errorOf("corrupt.gml"),
              "corrupt.gml: cannot read the file: XML parsing of GML file failed : no element found at line 8, column 21");
    EXPECT_EQ(importPolygons(fixture("corrupt.geojson")).error().code, ErrorCode::ParseError);
}

TEST(AreaImportErrors, UnsupportedFormats) {
    EXPECT_EQ(errorOf("unsupported.csv"),
              "unsupported.csv: unsupported format (Comma Separated Value (.csv)); expected GeoJSON (.geojson), KML "
              "(.kml), Shapefile (.shp), GeoPackage (.gpkg) or GML (.gml)");
    EXPECT_EQ(errorOf("unsupported.txt"),
              "unsupported.txt: unsupported or unrecognised format; expected GeoJSON (.geojson), KML (.kml), "
              "Shapefile (.shp), GeoPackage (.gpkg) or GML (.gml)");
    EXPECT_EQ(importPolygons(fixture("unsupported.csv")).error().code, ErrorCode::Unsupported);
}

// An unreadable file says why it cannot be read (as root every file is readable: skipped there).
TEST(AreaImport, AnUnreadableFileSaysSo) {
    if (geteuid() == 0)
        GTEST_SKIP() << "root reads every file";
    const std::string path = testing::TempDir() + "pf_unreadable_" + std::to_string(getpid()) + ".geojson";
    {
        std::ofstream out(path);
        out << "{\"type\":\"FeatureCollection\",\"features\":[]}";
    }
    ASSERT_EQ(chmod(path.c_str(), 0), 0);
    auto r = importPolygons(path);
    std::remove(path.c_str());
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("cannot read the file: Permission denied"), std::string::npos)
        << r.error().message;
}
