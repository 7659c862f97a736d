// A traced boundary of many thousand vertices is simplified within a tolerance far below the
// footprint, widened to hold all of the given area, and the plan says so; beyond the vertex limit
// the check and the planner refuse it with the limit.
#include "core/geo/local_frame.h"
#include "core/geo/polygon_ops.h"
#include "core/geo/simplify.h"
#include "core/io/mission_file.h"
#include "core/mission/plan_mission.h"
#include "core/mission/simplify_input.h"
#include "core/mission/validation.h"
#include "core/sensor/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

namespace {

using namespace pf;

constexpr double kLat0 = 49.0, kLon0 = 8.33;

geo::LonLat at(double x, double y) {
    return {kLon0 + x / (111'320.0 * std::cos(kLat0 * M_PI / 180.0)), kLat0 + y / 111'200.0};
}

// A field of about 300 m across traced every few centimetres, with 15 cm of tracing noise.
geo::GeoPolygon tracedField(int vertices, double radiusM = 150.0) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> jitter(-0.15, 0.15);
    geo::GeoPolygon p;
    for (int i = 0; i < vertices; ++i) {
        const double t = 2.0 * M_PI * i / vertices;
        const double r = radiusM * (1.0 + 0.12 * std::sin(3.0 * t)) + jitter(rng);
        p.outer.push_back(at(r * std::cos(t), r * std::sin(t)));
    }
    return p;
}

// A star of `spikes` teeth 5 m deep: no vertex of it lies within a tolerance of a straight line.
geo::GeoPolygon serratedField(int spikes) {
    geo::GeoPolygon p;
    for (int i = 0; i < 2 * spikes; ++i) {
        const double t = M_PI * i / spikes;
        const double r = 800.0 + (i % 2 ? 5.0 : 0.0);
        p.outer.push_back(at(r * std::cos(t), r * std::sin(t)));
    }
    return p;
}

mission::Mission demoWith(const geo::GeoPolygon& area) {
    auto demo = io::readMissionFile(std::string(PF_RESOURCES_DIR) + "/demo/demo_mission.json");
    EXPECT_TRUE(demo) << (demo ? "" : demo.error().message);
    mission::Mission m = demo ? *demo : mission::Mission{};
    m.area = area;
    m.noFlyZones.clear();
    m.home = at(-200.0, -200.0);
    m.aircraft.resize(1);
    m.options.gridAngleDeg = 0.0;
    return m;
}

TEST(SimplifyInput, TracedBoundaryIsSimplifiedWidenedAndSaidSo) {
    const mission::Mission m = demoWith(tracedField(40'000));
    const auto s = mission::simplifyInput(m);
    ASSERT_TRUE(s.simplified);
    ASSERT_TRUE(s.error.empty()) << s.error;
    // The tolerance: 5 % of the track spacing, at most 0.5 m.
    const auto& a = m.aircraft.front();
    const auto eff = sensor::effectiveFootprint(a.camera, *mission::resolvedAltitude(a), a.overlap);
    ASSERT_TRUE(eff);
    EXPECT_DOUBLE_EQ(s.toleranceM, std::min(0.5, 0.05 * eff->acrossM));
    EXPECT_EQ(s.areaVerticesBefore, 40'000u);
    EXPECT_LT(s.areaVerticesAfter, 4'000u);
    EXPECT_GT(s.areaVerticesAfter, 20u);
    // Every given vertex lies inside the simplified area: no strip of it is left out.
    auto frame = geo::LocalFrame::forArea(m.area);
    ASSERT_TRUE(frame);
    const geo::Polygon before = frame->toLocal(m.area), after = frame->toLocal(s.mission.area);
    for (const auto& p : before.outer)
        ASSERT_TRUE(geo::contains(after, p) || geo::distanceTo(after, p) < 1e-6);
    // It grew by about the perimeter times the widening, no more.
    const double perimeter = 2.0 * M_PI * 150.0 * 1.05;
    EXPECT_GT(s.areaAfterM2, s.areaBeforeM2);
    EXPECT_LT(s.areaAfterM2 - s.areaBeforeM2, 1.5 * perimeter * s.toleranceM);
    EXPECT_NEAR(geo::area(after), s.areaAfterM2, 1.0);
    // The note names the counts, the tolerance and the change in m2 and %.
    EXPECT_NE(s.note.find("40,000 vertices was simplified to"), std::string::npos) << s.note;
    char tol[32];
    std::snprintf(tol, sizeof tol, "within %.2f m", s.toleranceM);
    EXPECT_NE(s.note.find(tol), std::string::npos) << s.note;
    EXPECT_NE(s.note.find(" m2 (+"), std::string::npos) << s.note;
    EXPECT_NE(s.note.find(" %)"), std::string::npos) << s.note;
    // The check warns with the same note, and the plan carries it.
    const auto report = mission::validateMission(m);
    EXPECT_FALSE(report.hasErrors()) << report.errorSummary();
    bool warned = false;
    for (const auto& p : report.problems)
        warned = warned || (p.severity == geo::Severity::Warning && p.message == s.note);
    EXPECT_TRUE(warned);
    const auto plan = mission::planMission(m);
    ASSERT_TRUE(plan) << plan.error().message;
    ASSERT_FALSE(plan->warnings.empty());
    EXPECT_EQ(plan->warnings.front(), s.note);
    EXPECT_GT(plan->coverageRatio, 0.99);
}

TEST(SimplifyInput, OrdinaryAreasArePlannedAsGiven) {
    const mission::Mission m = demoWith(tracedField(2'000));
    const auto s = mission::simplifyInput(m);
    EXPECT_FALSE(s.simplified);
    EXPECT_TRUE(s.note.empty());
    EXPECT_TRUE(s.mission.area == m.area);
}

TEST(SimplifyInput, ZonesAreWidenedToHoldTheGivenZone) {
    mission::Mission m = demoWith(tracedField(20'000));
    mission::NoFlyZone z;
    z.name = "Pond";
    geo::GeoPolygon pond = tracedField(8'000, 30.0);
    z.polygon = pond;
    m.noFlyZones.push_back(z);
    mission::NoFlyZone hut;
    hut.name = "Hut";
    hut.polygon.outer = {at(60, 60), at(70, 60), at(70, 70), at(60, 70)};
    m.noFlyZones.push_back(hut);
    const auto s = mission::simplifyInput(m);
    ASSERT_TRUE(s.simplified);
    EXPECT_EQ(s.zoneVerticesBefore, 8'004u);
    EXPECT_LT(s.zoneVerticesAfter, 2'000u);
    EXPECT_NE(s.note.find("the no-fly zones' 8,004 vertices became"), std::string::npos) << s.note;
    auto frame = geo::LocalFrame::forArea(m.area);
    const geo::Polygon after = frame->toLocal(s.mission.noFlyZones[0].polygon);
    for (const auto& p : frame->toLocal(pond).outer)
        ASSERT_TRUE(geo::contains(after, p) || geo::distanceTo(after, p) < 1e-6);
    // A hand-drawn zone with no vertex to spare is kept exactly.
    EXPECT_TRUE(s.mission.noFlyZones[1].polygon == hut.polygon);
}

TEST(SimplifyInput, TooManyVerticesAfterSimplifyingAreRefusedWithTheLimit) {
    const mission::Mission m = demoWith(serratedField(15'000)); // 30,000 vertices, none to spare
    const auto s = mission::simplifyInput(m);
    ASSERT_FALSE(s.error.empty());
    EXPECT_EQ(s.error.rfind("the area has ", 0), 0u) << s.error;
    EXPECT_GT(s.areaVerticesAfter, 20'000u);
    EXPECT_NE(s.error.find(" vertices after simplifying to 0."), std::string::npos) << s.error;
    EXPECT_NE(s.error.find("at most 20,000 vertices"), std::string::npos) << s.error;
    EXPECT_NE(s.error.find("simplify it in a GIS first"), std::string::npos) << s.error;
    const auto report = mission::validateMission(m);
    EXPECT_NE(report.errorSummary().find(s.error), std::string::npos) << report.errorSummary();
    const auto plan = mission::planMission(m);
    ASSERT_FALSE(plan);
    EXPECT_EQ(plan.error().code, ErrorCode::TooLarge);
    EXPECT_EQ(plan.error().message, s.error);
}

} // namespace
