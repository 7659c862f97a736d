// Tests of plan.geojson: compact, streamed, readable back, footprints on request.
#include "core/mission/plan_geojson.h"
#include "core/mission/plan_mission.h"

#include <gtest/gtest.h>

#include <cpl_json.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace pf;
using namespace pf::mission;

namespace {

// A 300 m x 200 m field with one zone, flown low (many photos), one aircraft with a quoted name.
Mission fieldMission() {
    const geo::LocalFrame frame = *geo::LocalFrame::create({8.33, 49.01});
    Mission m;
    m.area = frame.toGeo(geo::Polygon{{{-150, -100}, {150, -100}, {150, 100}, {-150, 100}}, {}});
    m.noFlyZones.push_back({"Shed", frame.toGeo(geo::Polygon{{{-10, -10}, {10, -10}, {10, 10}, {-10, 10}}, {}})});
    m.home = frame.toGeo(geo::Vec2{-160, -110});
    AircraftConfig a;
    a.name = "Falcon \"8\"";
    a.camera.name = "test";
    a.camera.hfovDeg = 60;
    a.camera.vfovDeg = 45;
    a.camera.imageWidthPx = 4000;
    a.camera.imageHeightPx = 3000;
    a.altitudeM = 15;
    a.overlap = {0.7, 0.6};
    m.aircraft.push_back(a);
    m.options.planner = PlannerKind::Stride;
    m.options.gridAngleDeg = 0.0;
    return m;
}

} // namespace

TEST(PlanGeoJson, CompactAndReadableBack) {
    const Mission m = fieldMission();
    auto plan = planMission(m);
    ASSERT_TRUE(plan.ok()) << plan.error().message;
    const AircraftPlan& a = plan->aircraft.front();
    ASSERT_GT(a.metrics.photos, 500);
    std::ostringstream out;
    ASSERT_TRUE(writePlanGeoJson(*plan, out));
    const std::string text = out.str();
    // The budget: at most about 300 bytes per photo, everything included.
    EXPECT_LE(static_cast<double>(text.size()) / a.metrics.photos, 300.0);
    CPLJSONDocument doc;
    ASSERT_TRUE(doc.LoadMemory(text));
    const CPLJSONArray features = doc.GetRoot().GetArray("features");
    int photos = 0, paths = 0, footprints = 0;
    for (int i = 0; i < features.Size(); ++i) {
        const CPLJSONObject f = features[i];
        const std::string kind = f.GetString("properties/kind");
        if (kind == "path") {
            ++paths;
            EXPECT_EQ(f.GetString("properties/aircraft"), "Falcon \"8\"");
            EXPECT_NEAR(f.GetDouble("properties/footprint_across_m"), a.footprint.real.longSideM, 1e-3);
        } else if (kind == "photo") {
            ++photos;
            EXPECT_EQ(f.GetInteger("properties/seq"), photos);
            EXPECT_NEAR(f.GetDouble("properties/alt_m"), 15.0, 1e-9);
        } else if (kind == "footprint") {
            ++footprints;
        }
    }
    EXPECT_EQ(paths, 1);
    EXPECT_EQ(photos, a.metrics.photos);
    EXPECT_EQ(footprints, 0);
    // Every photo's position, to the written 7 decimals, in flight order.
    int k = 0;
    for (int i = 0; i < features.Size(); ++i) {
        const CPLJSONObject f = features[i];
        if (f.GetString("properties/kind") != "photo")
            continue;
        while (a.route.waypoints[static_cast<std::size_t>(k)].kind != route::WaypointKind::Photo)
            ++k;
        const auto& w = a.route.waypoints[static_cast<std::size_t>(k++)];
        const CPLJSONArray c = f.GetArray("geometry/coordinates");
        EXPECT_NEAR(c[0].ToDouble(), w.position.lon, 0.51e-7);
        EXPECT_NEAR(c[1].ToDouble(), w.position.lat, 0.51e-7);
        EXPECT_NEAR(f.GetDouble("properties/heading_deg"), w.headingDeg, 0.051);
    }
}

TEST(PlanGeoJson, FootprintsOnRequestAndAtomicFile) {
    const Mission m = fieldMission();
    auto plan = planMission(m);
    ASSERT_TRUE(plan.ok()) << plan.error().message;
    const auto dir = std::filesystem::temp_directory_path() / "pf_plan_geojson_test";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "plan.geojson").string();
    PlanGeoJsonOptions opt;
    opt.footprints = true;
    ASSERT_TRUE(writePlanGeoJsonFile(*plan, path, opt).ok());
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()), 1)
        << "no temporary file left";
    CPLJSONDocument doc;
    ASSERT_TRUE(doc.Load(path));
    const CPLJSONArray features = doc.GetRoot().GetArray("features");
    int footprints = 0;
    const AircraftPlan& a = plan->aircraft.front();
    for (int i = 0; i < features.Size(); ++i) {
        const CPLJSONObject f = features[i];
        if (f.GetString("properties/kind") != "footprint")
            continue;
        ++footprints;
        const CPLJSONArray ring = f.GetArray("geometry/coordinates")[0].ToArray();
        ASSERT_EQ(ring.Size(), 5); // closed rectangle
        // Its long side is the real footprint across the track (1 cm for the 7 decimals).
        const double dLon = (ring[1].ToArray()[0].ToDouble() - ring[0].ToArray()[0].ToDouble()) * 111320.0 *
                            std::cos(49.01 * M_PI / 180.0);
        const double dLat = (ring[1].ToArray()[1].ToDouble() - ring[0].ToArray()[1].ToDouble()) * 111320.0;
        EXPECT_NEAR(std::hypot(dLon, dLat), a.footprint.real.longSideM, 0.05);
    }
    EXPECT_EQ(footprints, a.metrics.photos);
    // A directory that does not exist: an error naming the file, nothing crashes.
    const auto bad = writePlanGeoJsonFile(*plan, (dir / "missing" / "plan.geojson").string());
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message.find("plan.geojson"), std::string::npos);
    std::filesystem::remove_all(dir);
}
