// Missions built from the sample areas (resources/areas/) and catalog aircraft, shared by the tests and
// the benchmarks that plan them end to end.
#pragma once

#include "core/io/catalog.h"
#include "core/io/mission_file.h"
#include "core/mission/mission.h"
#include "core/plan/evaluation.h"

#include <optional>
#include <string>

namespace pf::test {

// The mission of a sample area as `photoflight-cli eval` reads it: its area, its no-fly zones named
// "zone 1", "zone 2", ..., grid angle 0, and the home 30 m south of the area's southernmost vertex
// (outside the area, as a take-off point usually is). No aircraft.
inline mission::Mission sampleAreaMission(const plan::EvalArea& ea) {
    mission::Mission m;
    m.name = ea.name;
    m.area = ea.area;
    int i = 0;
    for (const auto& z : ea.noFly)
        m.noFlyZones.push_back({"zone " + std::to_string(++i), z});
    geo::LonLat south = m.area.outer.front();
    for (const auto& p : m.area.outer)
        if (p.lat < south.lat)
            south = p;
    m.home = geo::LonLat{south.lon, south.lat - 30.0 / 111320.0};
    m.options.gridAngleDeg = 0.0;
    return m;
}

// A catalog aircraft with its default camera at `altitudeM`, as `--aircraft NAME:ALT` builds it;
// nothing if the catalog lacks the aircraft or its camera.
inline std::optional<mission::AircraftConfig> catalogAircraft(const io::Catalog& cat, const std::string& name,
                                                              double altitudeM) {
    const fleet::AircraftSpec* s = cat.findAircraft(name);
    const sensor::Camera* c = s ? cat.findCamera(s->defaultCamera) : nullptr;
    if (!s || !c)
        return std::nullopt;
    mission::AircraftConfig a = mission::aircraftFromCatalog(*s, c);
    a.altitudeM = altitudeM;
    return a;
}

// The aircraft of the big-site cases (issue's camera of 60 x 45 degrees on a 4000 x 3000 sensor,
// 70 % front and 60 % side overlap) at `altitudeM`, named "Falcon 8".
inline mission::AircraftConfig bigSiteAircraft(double altitudeM, const std::string& cameraName = "test") {
    mission::AircraftConfig a;
    a.name = "Falcon 8";
    a.camera.name = cameraName;
    a.camera.hfovDeg = 60;
    a.camera.vfovDeg = 45;
    a.camera.imageWidthPx = 4000;
    a.camera.imageHeightPx = 3000;
    a.altitudeM = altitudeM;
    a.overlap = {0.7, 0.6};
    return a;
}

// The demo mission (resources/demo) with both aircraft at 3.5 m and one more no-fly zone in its
// south-west, beside where the two subareas meet: a fleet plan that spends most of its time sharing
// the area (about 60,000 photos per aircraft).
inline Result<mission::Mission> lowDemoWithZone(const std::string& resourcesDir) {
    auto m = io::readMissionFile(resourcesDir + "/demo/demo_mission.json");
    if (!m)
        return m.error();
    for (auto& a : m->aircraft)
        a.altitudeM = 3.5;
    const double lon = 8.3283, lat = 49.0113, w = 0.0003, h = 0.0002;
    m->noFlyZones.push_back(
        {"extra",
         geo::GeoPolygon{{{lon, lat}, {lon + w, lat}, {lon + w, lat + h}, {lon, lat + h}}, {}}});
    return m;
}

} // namespace pf::test
