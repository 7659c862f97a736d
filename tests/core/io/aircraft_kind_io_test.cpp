// The aircraft's kind and plane figures through the catalog and the mission file: the bundled
// planes, round trips, version 5 only when needed, older files still read, and errors that name the
// field.
#include "core/io/catalog.h"
#include "core/io/mission_file.h"
#include "core/mission/mission.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>

using namespace pf;
using namespace pf::io;

namespace {

const std::string kBundled = std::string(PF_RESOURCES_DIR) + "/catalog.json";

std::string catalogErrorOf(const std::string& aircraft) {
    const std::string path = ::testing::TempDir() + "pf_kind_catalog.json";
    {
        std::ofstream out(path, std::ios::binary);
        out << R"({"format": "photoflight-catalog", "version": 1, "cameras": [], "aircraft": [)"
            << aircraft << "]}";
    }
    auto r = loadCatalog(path);
    std::remove(path.c_str());
    if (r)
        return "<loaded>";
    const std::string msg = r.error().message;
    return msg.rfind(path, 0) == 0 ? "c.json" + msg.substr(path.size()) : msg;
}

mission::Mission minimalMission() {
    mission::Mission m;
    m.name = "kinds";
    m.area.outer = {{8.0, 49.0}, {8.001, 49.0}, {8.001, 49.001}};
    mission::AircraftConfig a;
    a.name = "A";
    a.camera.hfovDeg = 60;
    a.camera.vfovDeg = 45;
    a.camera.imageWidthPx = 4000;
    a.camera.imageHeightPx = 3000;
    a.altitudeM = 80;
    m.aircraft.push_back(a);
    m.options.planner = mission::PlannerKind::Stride; // a planner version 1 knows
    return m;
}

int versionOf(const std::string& text) {
    const auto at = text.find("\"version\":");
    return at == std::string::npos ? -1 : std::atoi(text.c_str() + at + 10);
}

} // namespace

// The bundled planes, their kinds and the radius their bank limits give at their cruise speeds, by
// hand: ArduPlane 12^2 / (9.80665 tan 45) = 14.684 m; DeltaQuad 16^2 / (9.80665 tan 50) = 21.904 m.
// A plane without a turn rate gets that of its tightest turn: 12 / 14.684 rad/s = 46.82 deg/s.
// Every multirotor entry still reads as a multirotor.
TEST(CatalogKinds, BundledPlanesAndTheirTurns) {
    auto cat = loadCatalog(kBundled);
    ASSERT_TRUE(cat) << cat.error().message;
    const auto* ardu = cat->findAircraft("ArduPlane (default parameters)");
    const auto* ebee = cat->findAircraft("senseFly eBee X");
    const auto* dq = cat->findAircraft("DeltaQuad Pro");
    ASSERT_TRUE(ardu && ebee && dq);
    EXPECT_EQ(ardu->kind, fleet::AircraftKind::FixedWing);
    EXPECT_EQ(ebee->kind, fleet::AircraftKind::FixedWing);
    EXPECT_EQ(dq->kind, fleet::AircraftKind::Vtol);
    EXPECT_NEAR(fleet::minTurnRadiusM(ardu->plane, ardu->cruiseSpeedMps), 14.684, 1e-3);
    EXPECT_NEAR(fleet::minTurnRadiusM(dq->plane, dq->cruiseSpeedMps), 21.904, 1e-3);
    EXPECT_NEAR(ardu->turnRateDegS, 12.0 / 14.684 * 180.0 / M_PI, 0.01);
    EXPECT_EQ(dq->plane.stallSpeedMps, 13.0);
    EXPECT_EQ(ebee->defaultCamera, "senseFly S.O.D.A. 3D");
    ASSERT_NE(cat->findCamera("senseFly S.O.D.A. 3D"), nullptr);
    // 122 m x 13.2 mm / (10.6 mm x 5472 px) = 2.776 cm/px.
    EXPECT_NEAR(*sensor::gsdCmAt(*cat->findCamera("senseFly S.O.D.A. 3D"), 122.0), 2.776, 1e-3);
    EXPECT_EQ(cat->findAircraft("Falcon 8")->kind, fleet::AircraftKind::Multirotor);
    EXPECT_EQ(cat->findAircraft("DJI Mavic 3 Enterprise")->kind, fleet::AircraftKind::Multirotor);
    for (const auto& a : cat->aircraft) {
        if (fleet::fliesAsPlane(a.kind)) {
            EXPECT_NE(a.notes.find("("), std::string::npos)
                << a.name << ": the note names no source";
        }
    }
}

// The catalog writer keeps kinds and plane figures: what it writes reads back equal.
TEST(CatalogKinds, JsonRoundTripKeepsKindsAndPlanes) {
    auto cat = loadCatalog(kBundled);
    ASSERT_TRUE(cat);
    const std::string path = ::testing::TempDir() + "pf_kind_roundtrip.json";
    {
        std::ofstream out(path, std::ios::binary);
        out << catalogToJson(*cat);
    }
    auto back = loadCatalog(path);
    std::remove(path.c_str());
    ASSERT_TRUE(back) << back.error().message;
    ASSERT_EQ(back->aircraft.size(), cat->aircraft.size());
    for (std::size_t i = 0; i < cat->aircraft.size(); ++i)
        EXPECT_TRUE(back->aircraft[i] == cat->aircraft[i]) << cat->aircraft[i].name;
}

TEST(CatalogKinds, ErrorsNameTheEntryAndTheField) {
    const std::string base =
        R"({"name": "P", "kind": "fixed_wing", "cruise_speed_mps": 15, "endurance_min": 60,
      "max_altitude_m": 120)";
    EXPECT_EQ(catalogErrorOf(base + "}"), "<loaded>");
    EXPECT_EQ(catalogErrorOf(
                  R"({"name": "P", "kind": "glider", "cruise_speed_mps": 15, "turn_rate_deg_s": 10,
      "endurance_min": 60, "max_altitude_m": 120})"),
              "c.json: aircraft[0] (\"P\"): kind: unknown kind \"glider\" (expected multirotor, "
              "fixed_wing or vtol)");
    EXPECT_EQ(catalogErrorOf(base + R"(, "plane": {"turn_radius_m": 0}})"),
              "c.json: aircraft[0] (\"P\"): plane: turn_radius_m: must be greater than 0");
    EXPECT_EQ(catalogErrorOf(base + R"(, "plane": {"bank_deg": 95}})"),
              "c.json: aircraft[0] (\"P\"): plane: bank_deg: must lie between 0 and 90 degrees");
    EXPECT_EQ(catalogErrorOf(base + R"(, "plane": {"climb_rate_mps": -1}})"),
              "c.json: aircraft[0] (\"P\"): plane: climb_rate_mps: must be greater than 0");
    EXPECT_EQ(catalogErrorOf(base + R"(, "plane": {"turn_radius": 30}})"),
              "c.json: aircraft[0] (\"P\"): plane: turn_radius: unknown field (known here: "
              "turn_radius_m, bank_deg, "
              "climb_rate_mps, sink_rate_mps, run_in_m, stall_speed_mps)");
    // A multirotor still needs its turn rate.
    EXPECT_EQ(
        catalogErrorOf(
            R"({"name": "M", "cruise_speed_mps": 10, "endurance_min": 20, "max_altitude_m": 120})"),
        "c.json: aircraft[0] (\"M\"): turn_rate_deg_s: missing required field");
}

// A mission with planes: version 5, every figure read back exactly; a mission of multirotors keeps
// the oldest version that holds it, without "kind" or "plane".
TEST(MissionFileKinds, PlanesRoundTripAsVersion5) {
    mission::Mission m = minimalMission();
    std::string text = missionToJson(m);
    EXPECT_EQ(versionOf(text), 1) << text;
    EXPECT_EQ(text.find("\"kind\""), std::string::npos);
    EXPECT_EQ(text.find("\"plane\""), std::string::npos);

    mission::AircraftConfig plane = m.aircraft[0];
    plane.name = "W";
    plane.kind = fleet::AircraftKind::Vtol;
    plane.cruiseSpeedMps = 16;
    plane.plane.minTurnRadiusM = 35.5;
    plane.plane.maxBankDeg = 40;
    plane.plane.climbRateMps = 3.5;
    plane.plane.sinkRateMps = 2.25;
    plane.plane.runInM = 80;
    plane.plane.stallSpeedMps = 11;
    m.aircraft.push_back(plane);
    text = missionToJson(m);
    EXPECT_EQ(versionOf(text), 5) << text;
    auto back = parseMissionJson(text, "x.json");
    ASSERT_TRUE(back) << back.error().message;
    EXPECT_TRUE(*back == m);
    EXPECT_EQ(back->aircraft[1].kind, fleet::AircraftKind::Vtol);
    EXPECT_EQ(back->aircraft[1].plane.minTurnRadiusM, 35.5);
    EXPECT_EQ(back->aircraft[0].kind, fleet::AircraftKind::Multirotor);

    // A multirotor that keeps plane figures from before its kind was changed keeps them too.
    m.aircraft[1].kind = fleet::AircraftKind::Multirotor;
    back = parseMissionJson(missionToJson(m), "x.json");
    ASSERT_TRUE(back) << back.error().message;
    EXPECT_TRUE(*back == m);
}

// Random plane figures (optional ones set or not) read back exactly.
TEST(MissionFileKinds, RandomPlaneFiguresRoundTripExactly) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> pos(0.01, 1e4);
    for (int i = 0; i < 50; ++i) {
        mission::Mission m = minimalMission();
        auto& a = m.aircraft[0];
        a.kind = static_cast<fleet::AircraftKind>(rng() % 3);
        if (rng() % 2)
            a.plane.minTurnRadiusM = pos(rng);
        if (rng() % 2)
            a.plane.maxBankDeg = pos(rng) / 200;
        a.plane.climbRateMps = pos(rng);
        a.plane.sinkRateMps = pos(rng);
        a.plane.runInM = pos(rng);
        if (rng() % 2)
            a.plane.stallSpeedMps = pos(rng);
        auto back = parseMissionJson(missionToJson(m), "x.json");
        ASSERT_TRUE(back) << back.error().message;
        EXPECT_TRUE(*back == m) << i;
    }
}

// A file written by a version 4 release (tests/data/missions/version4_multirotor.json:
// acceleration, terrain and an edited route, no kind) still reads, as multirotors; saved again it
// stays version 4.
TEST(MissionFileKinds, OldVersionFixtureReadsAsMultirotor) {
    auto m = readMissionFile(std::string(PF_TEST_DATA_DIR) + "/missions/version4_multirotor.json");
    ASSERT_TRUE(m) << m.error().message;
    ASSERT_EQ(m->aircraft.size(), 1u);
    EXPECT_EQ(m->aircraft[0].kind, fleet::AircraftKind::Multirotor);
    EXPECT_TRUE(m->aircraft[0].plane == fleet::PlanePerformance{});
    EXPECT_EQ(m->aircraft[0].accelerationMps2, 3.0);
    EXPECT_EQ(m->terrain.minClearanceM, 15.0);
    EXPECT_EQ(m->editedRoutes.size(), 1u);
    EXPECT_EQ(mission::flightModel(m->aircraft[0]).dynamics, plan::FlightDynamics::Multirotor);
    EXPECT_EQ(versionOf(missionToJson(*m)), 4);
}

// A file claiming an older version cannot hold a kind (older releases refuse the field); unknown
// kinds and misspelt plane fields are refused with the field's path.
TEST(MissionFileKinds, ErrorsNameTheField) {
    mission::Mission m = minimalMission();
    m.aircraft[0].kind = fleet::AircraftKind::FixedWing;
    const std::string text = missionToJson(m);
    const auto replace = [&](const std::string& from, const std::string& to) {
        std::string t = text;
        const auto at = t.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        if (at != std::string::npos)
            t.replace(at, from.size(), to);
        auto r = parseMissionJson(t, "x.json");
        return r ? std::string("<parsed>") : r.error().message;
    };
    EXPECT_EQ(replace("\"version\":5", "\"version\":4"),
              "x.json: aircraft[0].kind: the aircraft's kind and plane figures need version 5 of "
              "the mission file, "
              "but the file says version 4");
    EXPECT_EQ(replace("\"fixed_wing\"", "\"glider\""),
              "x.json: aircraft[0].kind: unknown kind \"glider\" (expected multirotor, fixed_wing "
              "or vtol)");
    EXPECT_EQ(replace("\"run_in_m\"", "\"run_in\""),
              "x.json: aircraft[0].plane.run_in: unknown field (known here: turn_radius_m, "
              "bank_deg, climb_rate_mps, "
              "sink_rate_mps, run_in_m, stall_speed_mps)");
    EXPECT_EQ(replace("\"climb_rate_mps\":5.0", "\"climb_rate_mps\":\"fast\""),
              "x.json: aircraft[0].plane.climb_rate_mps: expected a number but found a string");
    // The writer refuses what could not be read back.
    m.aircraft[0].plane.runInM = std::nan("");
    EXPECT_FALSE(checkWritable(m, "x.json"));
}

// A catalog plane becomes a mission aircraft with its kind, figures and the fixed-wing flight
// model.
TEST(MissionFileKinds, CatalogPlaneInAMission) {
    auto cat = loadCatalog(kBundled);
    ASSERT_TRUE(cat);
    const auto* spec = cat->findAircraft("DeltaQuad Pro");
    ASSERT_TRUE(spec);
    const auto a = mission::aircraftFromCatalog(*spec, cat->findCamera(spec->defaultCamera));
    EXPECT_EQ(a.kind, fleet::AircraftKind::Vtol);
    EXPECT_TRUE(a.plane == spec->plane);
    const plan::FlightTimeModel m = mission::flightModel(a);
    EXPECT_TRUE(m.fixedWing());
    EXPECT_EQ(m.speedMps, 16.0);
    EXPECT_EQ(m.climbRateMps, 5.0);
}
