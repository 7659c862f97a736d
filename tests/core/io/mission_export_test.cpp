// A planned mission's files (io/mission_export.h): every vehicle format writes one file per sortie
// of an aircraft needing several batteries, each one flight from take-off to return, and never a
// file flying them all; display formats draw the whole path (KML a folder per sortie); a flight
// holding more mission items than its autopilot stores gets a warning, and only then.
#include "core/geo/geodesic.h"
#include "core/io/mission_export.h"
#include "core/io/mission_items.h"
#include "core/io/trigger_lanes.h"
#include "core/mission/plan_mission.h"
#include "core/route/route_sorties.h"
#include "tests/core/io/formats_test_util.h"
#include "tests/short_battery_demo.h"

#include <cpl_json.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace pf::io {
namespace {

namespace fs = std::filesystem;

struct Planned {
    mission::Mission mission;
    std::vector<route::Route> routes;
    std::vector<std::vector<route::Route>> sorties; // per aircraft, as the plan cut them
};

const Planned& shortBattery() {
    static const Planned p = [] {
        Planned out;
        out.mission = test::shortBatteryDemo();
        auto plan = mission::planMission(out.mission);
        EXPECT_TRUE(plan.ok()) << plan.error().message;
        if (plan)
            for (const auto& a : plan->aircraft) {
                out.routes.push_back(a.route);
                out.sorties.push_back(a.sortieRoutes);
            }
        return out;
    }();
    return p;
}

std::string freshDir(const std::string& name) {
    const fs::path d = fs::path(testing::TempDir()) / ("pf_mission_export_" + name);
    fs::remove_all(d);
    fs::create_directories(d);
    return d.string();
}

std::set<std::string> filesIn(const std::string& dir) {
    std::set<std::string> out;
    for (const auto& e : fs::directory_iterator(dir))
        out.insert(e.path().filename().string());
    return out;
}

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// The MAVLink commands of a .plan (mission items) or .waypoints (lines after the home line).
std::vector<int> commandsOf(const std::string& path) {
    std::vector<int> out;
    if (path.size() > 5 && path.substr(path.size() - 5) == ".plan") {
        CPLJSONDocument doc;
        EXPECT_TRUE(doc.Load(path));
        const CPLJSONArray items = doc.GetRoot().GetArray("mission/items");
        for (int i = 0; i < items.Size(); ++i)
            out.push_back(items[i].GetInteger("command"));
        return out;
    }
    std::istringstream in(slurp(path));
    std::string line;
    std::getline(in, line); // QGC WPL 110
    std::getline(in, line); // the home, line 0
    while (std::getline(in, line)) {
        std::istringstream f(line);
        double v[4];
        for (double& x : v)
            f >> x;
        out.push_back(int(v[3]));
    }
    return out;
}

// The files of one flight: "<base><ext>" or its Litchi parts "<base>-part1<ext>", ... in order.
std::vector<std::string> flightFiles(const std::string& dir, const std::string& base,
                                     const std::string& ext) {
    if (fs::exists(dir + "/" + base + ext))
        return {dir + "/" + base + ext};
    std::vector<std::string> parts;
    for (int k = 1; fs::exists(dir + "/" + base + "-part" + std::to_string(k) + ext); ++k)
        parts.push_back(dir + "/" + base + "-part" + std::to_string(k) + ext);
    return parts;
}

TEST(MissionExport, EveryVehicleFormatWritesOneFlightPerSortieAndNoneFlyingThemAll) {
    const Planned& p = shortBattery();
    ASSERT_EQ(p.routes.size(), 2u);
    ASSERT_EQ(p.sorties[0].size(), 2u); // the Falcon 8 needs two batteries
    ASSERT_EQ(p.sorties[1].size(), 1u);
    const geo::LonLat home = *p.mission.home;
    int vehicleFormats = 0;
    for (const auto& info : waypointFormats()) {
        if (!info.vehicle)
            continue;
        ++vehicleFormats;
        const std::string dir = freshDir(info.name);
        MissionExportRequest request;
        request.formats = {info.format};
        request.folder = dir;
        auto report = exportMission(p.mission, p.routes, request);
        ASSERT_TRUE(report.ok()) << info.name << ": " << report.error().message;
        const std::string ext = info.extension;
        const auto onDisk = filesIn(dir);
        EXPECT_EQ(onDisk.size(), report->files.size()) << info.name;
        // No file of the Falcon 8 but its sorties' (and their parts).
        EXPECT_FALSE(onDisk.count("mission-Falcon_8" + ext)) << info.name;
        for (const auto& f : onDisk)
            EXPECT_TRUE(f.rfind("mission-Falcon_8-sortie", 0) == 0 ||
                        f.rfind("mission-Phantom_4_Pro", 0) == 0)
                << info.name << ": " << f;
        bool noted = false;
        for (const auto& n : report->notes)
            noted |=
                n.find("Falcon 8 needs 2 batteries: written as 2 flights") != std::string::npos;
        EXPECT_TRUE(noted) << info.name;
        EXPECT_TRUE(report->warnings.empty()) << info.name << ": " << report->warnings.front();

        struct Flight {
            std::string base;
            const route::Route* sortie;
        };
        const std::vector<Flight> flights = {{"mission-Falcon_8-sortie1", &p.sorties[0][0]},
                                             {"mission-Falcon_8-sortie2", &p.sorties[0][1]},
                                             {"mission-Phantom_4_Pro", &p.sorties[1][0]}};
        for (const auto& f : flights) {
            const auto files = flightFiles(dir, f.base, ext);
            ASSERT_FALSE(files.empty()) << info.name << ": no " << f.base;
            // One take-off and one return per MAVLink file.
            if (info.format == WaypointFormat::QgcPlan || info.format == WaypointFormat::QgcWpl) {
                const auto cmds = commandsOf(files.front());
                EXPECT_EQ(std::count(cmds.begin(), cmds.end(), mav::kNavTakeoff), 1)
                    << files.front();
                EXPECT_EQ(std::count(cmds.begin(), cmds.end(), mav::kNavReturnToLaunch), 1)
                    << files.front();
                EXPECT_EQ(cmds.front(), mav::kNavTakeoff);
                EXPECT_EQ(cmds.back(), mav::kNavReturnToLaunch);
            }
            if (!info.canImport)
                continue;
            // Read back: exactly the sortie's waypoints, never a battery change at home inside.
            std::vector<route::Waypoint> back;
            for (const auto& file : files) {
                auto imported = importWaypoints(file);
                ASSERT_TRUE(imported.ok()) << file << ": " << imported.error().message;
                ASSERT_EQ(imported->routes.size(), 1u);
                const auto& w = imported->routes.front().waypoints;
                // Litchi parts start where the previous one ended: that waypoint is flown once.
                back.insert(back.end(), w.begin() + (back.empty() ? 0 : 1), w.end());
            }
            // A format with a minimum spacing writes waypoints closer than it as one (and says so
            // in a note): the file holds the sortie with those merged, nothing more or less.
            std::size_t merged = 0;
            const auto expected =
                info.minSpacingM > 0
                    ? mergeCloseWaypoints(f.sortie->waypoints, info.minSpacingM, &merged)
                    : f.sortie->waypoints;
            if (merged > 0) {
                bool mergeNoted = false;
                for (const auto& n : report->notes)
                    mergeNoted |= n.find("merged into it") != std::string::npos;
                EXPECT_TRUE(mergeNoted) << info.name << " " << f.base;
            }
            ASSERT_EQ(back.size(), expected.size()) << info.name << " " << f.base;
            for (std::size_t i = 0; i < back.size(); ++i)
                EXPECT_LT(geo::geodesicDistance(back[i].position, expected[i].position), 0.05)
                    << info.name << " " << f.base << " #" << i;
            route::Route r;
            r.waypoints = back;
            EXPECT_EQ(route::sortieRanges(r, home).size(), 1u) << info.name << " " << f.base;
        }
    }
    EXPECT_GE(vehicleFormats, 3);
}

TEST(MissionExport, DisplayFormatsDrawTheWholePathAndKmlASortiePerFolder) {
    const Planned& p = shortBattery();
    const std::string dir = freshDir("display");
    MissionExportRequest request;
    request.formats = {WaypointFormat::Kml, WaypointFormat::Gpx, WaypointFormat::GeoJson};
    request.folder = dir;
    auto report = exportMission(p.mission, p.routes, request);
    ASSERT_TRUE(report.ok()) << report.error().message;
    EXPECT_EQ(filesIn(dir),
              (std::set<std::string>{
                  "mission-Falcon_8.kml", "mission-Phantom_4_Pro.kml", "mission.kml",
                  "mission-Falcon_8.gpx", "mission-Phantom_4_Pro.gpx", "mission.gpx",
                  "mission-Falcon_8.geojson", "mission-Phantom_4_Pro.geojson", "mission.geojson"}));
    const std::string kml = slurp(dir + "/mission-Falcon_8.kml");
    EXPECT_NE(kml.find("Falcon 8, sortie 1 of 2"), std::string::npos);
    EXPECT_NE(kml.find("Falcon 8, sortie 2 of 2"), std::string::npos);
    EXPECT_NE(kml.find("trajectory"), std::string::npos);
    EXPECT_EQ(slurp(dir + "/mission-Phantom_4_Pro.kml").find("sortie"), std::string::npos);
    // GPX and GeoJSON are read back for editing: the whole route, through home between the sorties.
    for (const char* f : {"/mission-Falcon_8.gpx", "/mission-Falcon_8.geojson"}) {
        auto back = importWaypoints(dir + f);
        ASSERT_TRUE(back.ok()) << f << ": " << back.error().message;
        ASSERT_EQ(back->routes.size(), 1u);
        EXPECT_EQ(back->routes[0].waypoints.size(), p.routes[0].waypoints.size()) << f;
        EXPECT_EQ(route::sortieRanges(back->routes[0], p.mission.home).size(), 2u) << f;
    }
}

// A straight lane of `photos` photo waypoints 2 m apart over the demo site.
route::Route lane(int photos) {
    route::Route r("Test copter", std::nullopt, 5.0, {});
    for (int i = 0; i < photos; ++i)
        r.waypoints.push_back(
            {{8.3275 + i * 2.0 / 73000.0, 49.0115}, 30.0, 90.0, route::WaypointKind::Photo});
    return r;
}

// Items of a lane mission with a photo per waypoint: take-off, speed, gimbal, a waypoint and a
// capture per photo, the return: 4 + 2 n.
TEST(MissionExport, TheItemLimitWarningFiresOnlyOverTheAutopilotsLimit) {
    const mission::Mission m = test::demoMission();
    auto warningsFor = [&](int photos, WaypointFormat format, const ExportOptions& options) {
        const std::string dir = freshDir("limit");
        MissionExportRequest request;
        request.folder = dir;
        request.options = options;
        auto r = exportFormat(makeExportContext(m, {lane(photos)}), format, request);
        EXPECT_TRUE(r.ok()) << r.error().message;
        return r.ok() ? r->warnings : std::vector<std::string>{"failed"};
    };
    ExportOptions ardupilot, px4;
    px4.firmware = QgcFirmware::PX4;
    // ArduPilot stores 650 with its home: 4 + 2 * 322 = 648 items fit, 4 + 2 * 323 = 650 do not.
    EXPECT_TRUE(warningsFor(322, WaypointFormat::QgcPlan, ardupilot).empty());
    EXPECT_TRUE(warningsFor(322, WaypointFormat::QgcWpl, ardupilot).empty());
    auto over = warningsFor(323, WaypointFormat::QgcWpl, ardupilot);
    ASSERT_EQ(over.size(), 1u);
    EXPECT_NE(over[0].find("Test copter (mission-Test_copter.waypoints): 650 mission items"),
              std::string::npos)
        << over[0];
    EXPECT_NE(over[0].find("ArduPilot 650"), std::string::npos) << over[0];
    EXPECT_NE(over[0].find("with photos by distance along lanes it takes"), std::string::npos)
        << over[0];
    // PX4 stores 500: 4 + 2 * 248 = 500 fit, 502 do not; the .plan follows the firmware chosen.
    EXPECT_TRUE(warningsFor(248, WaypointFormat::QgcPlan, px4).empty());
    over = warningsFor(249, WaypointFormat::QgcPlan, px4);
    ASSERT_EQ(over.size(), 1u);
    EXPECT_NE(over[0].find("502 mission items"), std::string::npos) << over[0];
    EXPECT_NE(over[0].find("PX4 500"), std::string::npos) << over[0];
    EXPECT_TRUE(warningsFor(249, WaypointFormat::QgcPlan, ardupilot).empty());
    // The camera triggered by distance: the lane is two waypoints, far below any limit.
    ExportOptions distance;
    distance.trigger = CameraTrigger::Distance;
    EXPECT_TRUE(warningsFor(2000, WaypointFormat::QgcPlan, distance).empty());
    // Formats without a MAVLink autopilot get none (Litchi splits at its 99 waypoints instead).
    EXPECT_TRUE(warningsFor(400, WaypointFormat::LitchiCsv, ardupilot).empty());
    EXPECT_TRUE(warningsFor(400, WaypointFormat::Kml, ardupilot).empty());
}

// An aircraft with three sorties of which the first and the last are over ArduPilot's 650: one
// warning naming both sorties, their files and counts; the sortie that fits is not named.
TEST(MissionExport, TheSortiesOverTheLimitAreNamedInOneWarning) {
    const mission::Mission m = test::demoMission();
    route::Route r = lane(323); // 650 items
    r.home = m.home;
    const route::Waypoint atHome{*m.home, 30.0, 0.0, route::WaypointKind::Transit};
    r.waypoints.push_back(atHome);
    const route::Route fits = lane(100);
    r.waypoints.insert(r.waypoints.end(), fits.waypoints.begin(), fits.waypoints.end());
    r.waypoints.push_back(atHome);
    const route::Route last = lane(330); // 664 items
    r.waypoints.insert(r.waypoints.end(), last.waypoints.begin(), last.waypoints.end());
    MissionExportRequest request;
    request.folder = freshDir("grouped");
    auto report = exportFormat(makeExportContext(m, {r}), WaypointFormat::QgcWpl, request);
    ASSERT_TRUE(report.ok()) << report.error().message;
    EXPECT_EQ(report->files.size(), 3u);
    ASSERT_EQ(report->warnings.size(), 1u);
    EXPECT_EQ(report->warnings[0].rfind(
                  "Test copter, sorties 1 and 3 (mission-Test_copter-sortie1.waypoints and "
                  "mission-Test_copter-sortie3.waypoints): 650 and 664 mission items, more "
                  "than an autopilot holds: ArduPilot 650",
                  0),
              0u)
        << report->warnings[0];
    EXPECT_NE(report->warnings[0].find("they take "), std::string::npos) << report->warnings[0];
}

TEST(MissionExport, TheLimitWarningNamesTheFlightTheCountAndTheLimit) {
    EXPECT_EQ(itemLimitWarning("A", 649, Autopilot::ArduPilot), "");
    EXPECT_NE(itemLimitWarning("A", 650, Autopilot::ArduPilot), "");
    EXPECT_EQ(itemLimitWarning("A", 500, Autopilot::PX4), "");
    const std::string w = itemLimitWarning("Falcon 8, sortie 3", 12345, Autopilot::PX4, 600);
    EXPECT_EQ(
        w.rfind("Falcon 8, sortie 3: 12,345 mission items, more than an autopilot holds: PX4 500",
                0),
        0u)
        << w;
    EXPECT_NE(w.find("it takes 600 items, still too many"), std::string::npos) << w;
    // Before the vehicle has answered: the smallest limit counts, both are named.
    EXPECT_EQ(itemLimitWarning("A", 500, std::nullopt), "");
    const std::string any = itemLimitWarning("A", 501, std::nullopt, 40);
    EXPECT_NE(any.find("PX4 500"), std::string::npos) << any;
    EXPECT_NE(any.find("ArduPilot 650"), std::string::npos) << any;
    EXPECT_NE(any.find("it takes 40 items"), std::string::npos) << any;
    EXPECT_EQ(any.find("still too many"), std::string::npos) << any;
}

TEST(MissionExport, ExportAllWritesTheSortiesToo) {
    const Planned& p = shortBattery();
    const std::string dir = freshDir("all");
    std::vector<std::string> notes;
    auto files = exportAll(makeExportContext(p.mission, p.routes), WaypointFormat::QgcPlan, dir,
                           "m", {}, &notes);
    ASSERT_TRUE(files.ok()) << files.error().message;
    EXPECT_EQ(filesIn(dir),
              (std::set<std::string>{"m-Falcon_8-sortie1.plan", "m-Falcon_8-sortie2.plan",
                                     "m-Phantom_4_Pro.plan"}));
    ASSERT_FALSE(notes.empty());
}

} // namespace
} // namespace pf::io
