// Test helpers for the waypoint formats: seeded random routes on the demo site, tolerant
// comparisons, the rules QGroundControl's .plan loader enforces, and running ogrinfo.
#pragma once

#include "core/io/export_context.h"

#include <cpl_error.h>
#include <cpl_json.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace pf::test {

// The demo site (see docs/user-guide.md): area, two no-fly zones, home.
inline mission::Mission demoMission() {
    mission::Mission m;
    m.name = "Rheinhafen training ground";
    m.area.outer = {{8.3272608, 49.0109209}, {8.3324653, 49.0108309}, {8.3327392, 49.0123597},
                    {8.3308218, 49.0125396}, {8.3305478, 49.0133489}, {8.3273978, 49.013259}};
    m.noFlyZones.push_back({"Warehouse",
                            {{{8.3291782, 49.0118201},
                              {8.3297261, 49.0118201},
                              {8.3297261, 49.0121799},
                              {8.3291782, 49.0121799}},
                             {}}});
    mission::NoFlyZone mast{"Radio mast", {}};
    for (int i = 0; i < 16; ++i) {
        const double a = 2 * 3.14159265358979323846 * i / 16;
        mast.polygon.outer.push_back(
            {8.3316435 + 0.000274 * std::cos(a), 49.0115504 + 0.00018 * std::sin(a)});
    }
    m.noFlyZones.push_back(mast);
    m.home = geo::LonLat{8.3270554, 49.010741};
    return m;
}

// A route of 2..40 waypoints with random positions over the site, altitudes, headings and kinds.
inline route::Route randomRoute(std::mt19937& rng, const std::string& aircraft) {
    std::uniform_real_distribution<double> lon(8.3272, 8.3327), lat(49.0108, 49.0133),
        alt(15.0, 120.0), hdg(0.0, 360.0);
    std::uniform_int_distribution<int> count(2, 40), kind(0, 5);
    route::Route r;
    r.aircraft = aircraft;
    r.cruiseSpeedMps = 4.0 + (rng() % 100) / 10.0;
    const int n = count(rng);
    for (int i = 0; i < n; ++i) {
        route::Waypoint w;
        w.position = {lon(rng), lat(rng)};
        w.altitudeM = alt(rng);
        w.headingDeg = hdg(rng);
        const int k = kind(rng);
        w.kind = k < 4    ? route::WaypointKind::Photo
                 : k == 4 ? route::WaypointKind::Turn
                          : route::WaypointKind::Transit;
        r.waypoints.push_back(w);
    }
    return r;
}

// What a format that only records "photo or not" gives back (see detail::inferNonPhotoKinds).
inline std::vector<route::WaypointKind> photoOnlyKinds(const std::vector<route::Waypoint>& wps) {
    long first = -1, last = -1;
    for (std::size_t i = 0; i < wps.size(); ++i)
        if (wps[i].kind == route::WaypointKind::Photo) {
            if (first < 0)
                first = static_cast<long>(i);
            last = static_cast<long>(i);
        }
    std::vector<route::WaypointKind> out;
    for (std::size_t i = 0; i < wps.size(); ++i) {
        const long k = static_cast<long>(i);
        if (wps[i].kind == route::WaypointKind::Photo)
            out.push_back(route::WaypointKind::Photo);
        else if (first < 0 || k < first || k > last)
            out.push_back(route::WaypointKind::Transit);
        else
            out.push_back(route::WaypointKind::Turn);
    }
    return out;
}

inline double angleDiffDeg(double a, double b) {
    double d = std::fmod(std::abs(a - b), 360.0);
    return d > 180.0 ? 360.0 - d : d;
}

// The round-trip tolerances of the formats: 1e-7 degree, 1 cm, 0.01 degree of heading, same order.
inline void expectSameWaypoints(const std::vector<route::Waypoint>& expected,
                                const std::vector<route::Waypoint>& got, bool kindsExact,
                                const std::string& what) {
    ASSERT_EQ(got.size(), expected.size()) << what;
    const auto photoKinds = photoOnlyKinds(expected);
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_NEAR(got[i].position.lon, expected[i].position.lon, 1e-7) << what << " #" << i;
        EXPECT_NEAR(got[i].position.lat, expected[i].position.lat, 1e-7) << what << " #" << i;
        EXPECT_NEAR(got[i].altitudeM, expected[i].altitudeM, 0.01) << what << " #" << i;
        EXPECT_LE(angleDiffDeg(got[i].headingDeg, expected[i].headingDeg), 0.01)
            << what << " #" << i;
        EXPECT_GE(got[i].headingDeg, 0.0);
        EXPECT_LT(got[i].headingDeg, 360.0);
        EXPECT_EQ(got[i].kind, kindsExact ? expected[i].kind : photoKinds[i]) << what << " #" << i;
    }
}

// Every rule QGroundControl's .plan loader enforces on what we write; empty when the file loads.
inline std::vector<std::string> qgcPlanViolations(const std::string& json) {
    std::vector<std::string> v;
    CPLJSONDocument doc;
    CPLPushErrorHandler(CPLQuietErrorHandler);
    const bool ok = doc.LoadMemory(json);
    CPLPopErrorHandler();
    if (!ok)
        return {"not valid JSON"};
    const CPLJSONObject root = doc.GetRoot();
    using T = CPLJSONObject::Type;
    auto isNum = [](const CPLJSONObject& o) {
        const auto t = o.GetType();
        return t == T::Integer || t == T::Long || t == T::Double;
    };
    auto isInt = [](const CPLJSONObject& o) {
        return o.GetType() == T::Integer || o.GetType() == T::Long;
    };
    for (const char* k :
         {"fileType", "version", "groundStation", "mission", "geoFence", "rallyPoints"})
        if (!root.GetObj(k).IsValid())
            v.push_back(std::string("missing top-level key ") + k);
    if (root.GetString("fileType") != "Plan")
        v.push_back("fileType is not \"Plan\"");
    if (root.GetObj("version").GetType() != T::Integer || root.GetInteger("version") != 1)
        v.push_back("version is not 1");
    if (root.GetObj("groundStation").GetType() != T::String)
        v.push_back("groundStation is not a string");
    const CPLJSONObject m = root.GetObj("mission");
    if (m.GetType() != T::Object)
        return v.push_back("mission is not an object"), v;
    if (m.GetInteger("version") != 2 || !isInt(m.GetObj("version")))
        v.push_back("mission.version is not 2");
    for (const char* k : {"firmwareType", "vehicleType"})
        if (!isInt(m.GetObj(k)))
            v.push_back(std::string("mission.") + k + " is not an integer");
    for (const char* k : {"cruiseSpeed", "hoverSpeed"})
        if (!isNum(m.GetObj(k)))
            v.push_back(std::string("mission.") + k + " is not a number");
    const CPLJSONArray home = m.GetArray("plannedHomePosition");
    if (!home.IsValid() || home.Size() != 3)
        v.push_back("mission.plannedHomePosition is not [lat, lon, alt]");
    const CPLJSONArray items = m.GetArray("items");
    if (!items.IsValid())
        return v.push_back("mission.items is not an array"), v;
    int lastJump = 0;
    for (int i = 0; i < items.Size(); ++i) {
        const CPLJSONObject it = items[i];
        const std::string at = "item " + std::to_string(i) + ": ";
        if (it.GetString("type") != "SimpleItem")
            v.push_back(at + "type is not SimpleItem");
        const CPLJSONArray params = it.GetArray("params");
        if (!params.IsValid() || params.Size() != 7)
            v.push_back(at + "params does not hold exactly 7 values");
        else
            for (int p = 0; p < 7; ++p)
                if (!isNum(params[p]) && params[p].GetType() != T::Null)
                    v.push_back(at + "param " + std::to_string(p + 1) +
                                " is neither a number nor null");
        for (const char* k : {"frame", "command", "doJumpId"})
            if (!isInt(it.GetObj(k)))
                v.push_back(at + k + " is not an integer");
        if (it.GetObj("autoContinue").GetType() != T::Boolean)
            v.push_back(at + "autoContinue is not a boolean");
        const int jump = it.GetInteger("doJumpId");
        if (jump <= lastJump)
            v.push_back(at + "doJumpId does not increase");
        lastJump = jump;
        int altKeys = 0;
        for (const char* k : {"Altitude", "AltitudeMode", "AMSLAltAboveTerrain"})
            altKeys += it.GetObj(k).IsValid() ? 1 : 0;
        if (altKeys != 0 && altKeys != 3)
            v.push_back(
                at +
                "Altitude, AltitudeMode and AMSLAltAboveTerrain are not all present or all absent");
    }
    const CPLJSONObject fence = root.GetObj("geoFence");
    if (fence.GetInteger("version") != 2)
        v.push_back("geoFence.version is not 2");
    const CPLJSONArray polys = fence.GetArray("polygons");
    if (!polys.IsValid() || !fence.GetArray("circles").IsValid())
        v.push_back("geoFence needs polygons and circles arrays");
    for (int i = 0; polys.IsValid() && i < polys.Size(); ++i) {
        const CPLJSONObject p = polys[i];
        if (p.GetObj("inclusion").GetType() != T::Boolean || p.GetInteger("version") != 1)
            v.push_back("geoFence polygon " + std::to_string(i) + " lacks inclusion or version 1");
        const CPLJSONArray pts = p.GetArray("polygon");
        if (!pts.IsValid() || pts.Size() < 3)
            v.push_back("geoFence polygon " + std::to_string(i) + " has fewer than 3 vertices");
        for (int k = 0; pts.IsValid() && k < pts.Size(); ++k)
            if (pts[k].ToArray().Size() != 2)
                v.push_back("geoFence polygon " + std::to_string(i) + " vertex is not [lat, lon]");
    }
    const CPLJSONObject rally = root.GetObj("rallyPoints");
    if (rally.GetInteger("version") != 2 || !rally.GetArray("points").IsValid())
        v.push_back("rallyPoints needs version 2 and a points array");
    const CPLJSONArray pts = rally.GetArray("points");
    for (int i = 0; pts.IsValid() && i < pts.Size(); ++i)
        if (pts[i].ToArray().Size() != 3)
            v.push_back("rally point " + std::to_string(i) + " is not [lat, lon, alt]");
    return v;
}

// A fresh scratch directory for one test.
inline std::string scratchDir(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / ("pf_formats_" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir.string();
}

// Runs a command, returning its exit status and what it printed on stdout and stderr.
struct RunResult {
    int status = -1;
    std::string output;
};
inline RunResult run(const std::string& command) {
    RunResult r;
    FILE* p = popen((command + " 2>&1").c_str(), "r");
    if (!p)
        return r;
    std::array<char, 4096> buf;
    std::size_t n;
    while ((n = fread(buf.data(), 1, buf.size(), p)) > 0)
        r.output.append(buf.data(), n);
    const int st = pclose(p);
    r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    return r;
}

inline bool haveOgrinfo() {
    return run("command -v ogrinfo").status == 0;
}

} // namespace pf::test
