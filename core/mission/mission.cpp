#include "core/mission/mission.h"

namespace pf::mission {

AircraftConfig aircraftFromCatalog(const fleet::AircraftSpec& spec, const sensor::Camera* camera) {
    AircraftConfig a;
    a.name = spec.name;
    a.model = spec.name;
    a.kind = spec.kind;
    a.plane = spec.plane;
    if (camera)
        a.camera = *camera;
    a.cruiseSpeedMps = spec.cruiseSpeedMps;
    a.turnRateDegS = spec.turnRateDegS;
    a.accelerationMps2 = spec.accelerationMps2;
    a.enduranceMin = spec.enduranceMin;
    a.maxAltitudeM = spec.maxAltitudeM;
    a.dji = spec.dji;
    return a;
}

plan::FlightTimeModel flightModel(const AircraftConfig& a) {
    plan::FlightTimeModel m;
    m.speedMps = a.cruiseSpeedMps;
    m.turnRateDegS = a.turnRateDegS;
    m.accelerationMps2 = a.accelerationMps2;
    if (fleet::fliesAsPlane(a.kind)) {
        m.dynamics = plan::FlightDynamics::FixedWing;
        m.climbRateMps = a.plane.climbRateMps;
        m.sinkRateMps = a.plane.sinkRateMps;
    }
    return m;
}


bool operator==(const AircraftConfig& a, const AircraftConfig& b) {
    return a.name == b.name && a.model == b.model && a.kind == b.kind && a.camera == b.camera &&
           a.altitudeM == b.altitudeM && a.plane == b.plane && a.gsdCm == b.gsdCm &&
           a.overlap.front == b.overlap.front && a.overlap.side == b.overlap.side &&
           a.cruiseSpeedMps == b.cruiseSpeedMps && a.turnRateDegS == b.turnRateDegS &&
           a.accelerationMps2 == b.accelerationMps2 && a.enduranceMin == b.enduranceMin &&
           a.maxAltitudeM == b.maxAltitudeM && a.colour == b.colour && a.home == b.home &&
           a.dji == b.dji;
}

bool operator==(const PlannerOptions& a, const PlannerOptions& b) {
    return a.planner == b.planner && a.gridAngleDeg == b.gridAngleDeg &&
           a.safetyMarginM == b.safetyMarginM && a.keepInsideArea == b.keepInsideArea &&
           a.insideMarginM == b.insideMarginM && a.altitudeSeparationM == b.altitudeSeparationM &&
           a.batteryReserve == b.batteryReserve && a.maxCells == b.maxCells &&
           a.doubleGrid == b.doubleGrid && a.cameraTiltDeg == b.cameraTiltDeg;
}

sensor::Camera pointedCamera(const AircraftConfig& a, const PlannerOptions& options) {
    sensor::Camera c = a.camera;
    c.tiltDeg = options.cameraTiltDeg;
    return c;
}

bool sameRoute(const route::Route& a, const route::Route& b) {
    return a.aircraft == b.aircraft && a.home == b.home && a.cruiseSpeedMps == b.cruiseSpeedMps &&
           a.homeElevationM == b.homeElevationM && a.waypoints == b.waypoints;
}

bool operator==(const Mission& a, const Mission& b) {
    if (a.editedRoutes.size() != b.editedRoutes.size())
        return false;
    for (std::size_t i = 0; i < a.editedRoutes.size(); ++i)
        if (!sameRoute(a.editedRoutes[i], b.editedRoutes[i]))
            return false;
    return a.name == b.name && a.area == b.area && a.corridor == b.corridor &&
           a.noFlyZones == b.noFlyZones && a.home == b.home && a.landing == b.landing &&
           a.aircraft == b.aircraft && a.options == b.options && a.terrain == b.terrain;
}

} // namespace pf::mission
