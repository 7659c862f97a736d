#include "core/plan/area_generator.h"

#include "core/geo/local_frame.h"
#include "core/geo/polygon_ops.h"
#include "core/geo/validation.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>

namespace pf::plan {
namespace {

std::vector<GeneratedArea> generate(int count, std::uint64_t seed, int minZones = 0, int maxZones = 20) {
    AreaGeneratorOptions o;
    o.count = count;
    o.seed = seed;
    o.minZones = minZones;
    o.maxZones = maxZones;
    auto r = generateAreas(o);
    EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().message);
    return r.ok() ? std::move(r).value() : std::vector<GeneratedArea>{};
}

TEST(AreaGenerator, SameSeedSameAreasAndALargerCountExtendsTheSet) {
    const auto a = generate(4, 42), b = generate(4, 42), c = generate(6, 42), d = generate(4, 43);
    ASSERT_EQ(a.size(), 4u);
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(generatedAreaGeoJson(a[i]), generatedAreaGeoJson(b[i])) << i;
        EXPECT_EQ(generatedAreaGeoJson(a[i]), generatedAreaGeoJson(c[i])) << i;
        EXPECT_NE(a[i].area.area, d[i].area.area) << i;
    }
}

// The set the lanes issue asks for, checked on 60 areas: valid polygons, 0.1-0.25 km2, 0-20 zones inside
// the area covering at most a quarter of it, every family and zone kind present.
TEST(AreaGenerator, SixtyAreasAreValidAndInRange) {
    const auto areas = generate(60, 7);
    ASSERT_EQ(areas.size(), 60u);
    std::set<std::string> shapes, kinds;
    std::set<std::string> names;
    int withoutZones = 0;
    for (const auto& g : areas) {
        const EvalArea& a = g.area;
        names.insert(a.name);
        shapes.insert(g.shape);
        EXPECT_FALSE(geo::hasError(geo::validatePolygon(a.area, a.name))) << a.name;
        auto frame = geo::LocalFrame::forArea(a.area);
        ASSERT_TRUE(frame.ok());
        const geo::Polygon area = frame->toLocal(a.area);
        const double m2 = geo::area(area);
        EXPECT_GE(m2, 0.999e5) << a.name;
        EXPECT_LE(m2, 2.501e5) << a.name;
        EXPECT_LE(a.noFly.size(), 20u) << a.name;
        ASSERT_EQ(g.zoneKinds.size(), a.noFly.size());
        withoutZones += a.noFly.empty();
        double zones = 0;
        for (std::size_t i = 0; i < a.noFly.size(); ++i) {
            kinds.insert(g.zoneKinds[i]);
            EXPECT_FALSE(geo::hasError(geo::validatePolygon(a.noFly[i], "zone"))) << a.name << " zone " << i;
            const geo::Polygon z = frame->toLocal(a.noFly[i]);
            EXPECT_LT(geo::area(geo::difference(z, geo::MultiPolygon{area})), 1e-6) << a.name << " zone " << i;
            zones += geo::area(z);
        }
        EXPECT_LE(zones, 0.25 * m2 + 1e-6) << a.name;
    }
    EXPECT_EQ(names.size(), areas.size());
    EXPECT_GE(withoutZones, 1);
    for (const char* s : {"rectangle", "convex", "concave"})
        EXPECT_TRUE(shapes.count(s)) << s;
    EXPECT_GE(shapes.size(), 6u); // rectangle, convex, concave and most of L, U, T, staircase
    for (const char* k : {"rectangle", "circle", "U", "pair", "pocket"})
        EXPECT_TRUE(kinds.count(k)) << k;
}

TEST(AreaGenerator, ZoneCountsFollowTheRange) {
    for (const auto& g : generate(8, 3, 0, 0))
        EXPECT_TRUE(g.area.noFly.empty()) << g.area.name;
    std::map<std::size_t, int> counts;
    for (const auto& g : generate(12, 3, 10, 15)) {
        EXPECT_GE(g.area.noFly.size(), 10u) << g.area.name;
        EXPECT_LE(g.area.noFly.size(), 15u) << g.area.name;
        ++counts[g.area.noFly.size()];
    }
    EXPECT_GE(counts.size(), 3u); // drawn, not fixed
}

// The close zones do what they are for: a pocket's margins merge into a ring around ground that no
// path reaches, and the two zones of a pair lie 2 to 10 m apart.
TEST(AreaGenerator, PocketMarginsCloseAndPairsAreClose) {
    int pockets = 0, pairs = 0;
    for (const auto& g : generate(20, 11, 8, 20)) {
        auto frame = geo::LocalFrame::forArea(g.area.area);
        ASSERT_TRUE(frame.ok());
        for (std::size_t i = 0; i < g.zoneKinds.size(); ++i) {
            if (g.zoneKinds[i] == "pocket" && i + 3 < g.zoneKinds.size()) {
                geo::MultiPolygon bars;
                for (std::size_t k = i; k < i + 4; ++k)
                    bars.push_back(frame->toLocal(g.area.noFly[k]));
                const geo::MultiPolygon ring = geo::unite(geo::buffer(bars, 5.0));
                ASSERT_EQ(ring.size(), 1u) << g.area.name;
                EXPECT_EQ(ring.front().holes.size(), 1u) << g.area.name << " pocket at zone " << i + 1;
                const geo::MultiPolygon apart = geo::unite(geo::buffer(bars, 1.0));
                EXPECT_EQ(apart.size(), 4u) << g.area.name; // 2 m or more between the bars
                ++pockets;
                i += 3;
            } else if (g.zoneKinds[i] == "pair" && i + 1 < g.zoneKinds.size()) {
                const geo::Polygon a = frame->toLocal(g.area.noFly[i]), b = frame->toLocal(g.area.noFly[i + 1]);
                EXPECT_TRUE(geo::intersection(geo::buffer(a, 0.99), b).empty()) << g.area.name;
                EXPECT_FALSE(geo::intersection(geo::buffer(a, 10.01), b).empty()) << g.area.name;
                ++pairs;
                i += 1;
            }
        }
    }
    EXPECT_GE(pockets, 2);
    EXPECT_GE(pairs, 2);
}

TEST(AreaGenerator, FilesReadBackAsEvalAreas) {
    const auto areas = generate(3, 5, 4, 8);
    const auto dir = std::filesystem::temp_directory_path() / "pf_area_generator_test";
    std::filesystem::create_directories(dir);
    for (const auto& g : areas) {
        const auto path = dir / generatedAreaFileName(g);
        std::ofstream(path) << generatedAreaGeoJson(g);
        auto back = loadEvalArea(path.string());
        ASSERT_TRUE(back.ok()) << back.error().message;
        EXPECT_EQ(back->name, g.area.name);
        ASSERT_EQ(back->noFly.size(), g.area.noFly.size());
        ASSERT_EQ(back->area.outer.size(), g.area.area.outer.size());
        for (std::size_t i = 0; i < g.area.area.outer.size(); ++i) {
            EXPECT_NEAR(back->area.outer[i].lon, g.area.area.outer[i].lon, 1e-9);
            EXPECT_NEAR(back->area.outer[i].lat, g.area.area.outer[i].lat, 1e-9);
        }
    }
    std::filesystem::remove_all(dir);
}

TEST(AreaGenerator, BadOptionsAreErrors) {
    AreaGeneratorOptions o;
    o.count = 0;
    EXPECT_FALSE(generateAreas(o).ok());
    o = {};
    o.minZones = 5;
    o.maxZones = 2;
    auto r = generateAreas(o);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("zone"), std::string::npos);
    o = {};
    o.families.clear();
    EXPECT_FALSE(generateAreas(o).ok());
    // 200 zones of at least a few metres in a 1,000 m2 site: refused with a message, not a hang.
    o = {};
    o.count = 1;
    o.minAreaM2 = o.maxAreaM2 = 1000.0;
    o.minZones = o.maxZones = 200;
    r = generateAreas(o);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("fewer zones or larger areas"), std::string::npos) << r.error().message;
}

} // namespace
} // namespace pf::plan
