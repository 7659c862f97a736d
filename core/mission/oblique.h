// Oblique photos (PlannerOptions::cameraTiltDeg): a camera tilted forward photographs the ground
// ahead of the aircraft. The planners place the photos' centres as they place nadir photos (the
// tilted footprint, sensor::footprintAt, gives the overlaps); then each photo's waypoint is moved
// back along its lane by the footprint's aheadM, so that the aircraft flies where it must to see
// that ground, and the no-fly stage keeps the aircraft out of the zones' margins as for any plan
// (a photo that would be taken from within one is taken from outside it, a leg across one flown
// round it); the coverage check then measures the photos as taken. See docs/corridors.md
// ("Oblique photos").
#pragma once

#include "core/geo/no_fly_field.h" // NoFlyField, SafePathFinder
#include "core/mission/mission.h"
#include "core/route/waypoint.h"

#include <string>
#include <vector>

namespace pf::mission {

// What keeps aircraft `a` from taking the mission's oblique photos (PlannerOptions::cameraTiltDeg):
// a tilt out of range or too close to the horizon for its camera (sensor::checkTilt), a plane
// (its camera is fixed looking down), lanes along a corridor (the tilt is for area surveys).
// Empty for nadir photos or when none applies; planning refuses what validation reports
// (mission/validation.h).
std::string cameraTiltError(const Mission& m, const AircraftConfig& a, const std::string& who);

// The mission as planned: every aircraft's camera pointed as the options say (pointedCamera).
Mission withPointedCameras(Mission m);

// How far before a lane's first oblique photo the aircraft joins the lane's line (a turn point),
// so that it arrives along the lane, facing where the camera must look, whatever its autopilot's
// yaw rule (facing the next waypoint, its course, or the waypoint's yaw): 10 m gives a multirotor
// turning at 90 degrees/s and accelerating at 2.5 m/s2 the 2 s a reversal takes.
constexpr double kObliqueLeadInM = 10.0;

// The photo waypoints of a survey planned for the photos' centres moved back along their heading by
// aheadM, to where the aircraft takes them; a turn point on a lane's line (facing as the photo next
// to it in the flight does) moves with its lane; other turn and transit points stay. Every point
// moves by at most aheadM. A point whose straight move would cross a zone's margin (`finder`; none:
// no zones) goes to the nearest point outside the margin instead (a photo just past a zone, looking
// away from it; the coverage check measures the photos as taken), if a safe way leads there (not
// into a pocket the margins close off), else as far back along its lane as the margin allows. Of the three ways tried on 8 generated areas with
// 1-6 zones (double grid, 30 degrees), this one kept the most coverage: lowest pass 0.9972, against
// 0.9891 moving such a photo back along its lane only as far as the margin allows and 0.9743
// leaving it out. Returns the number of photos so placed.
int moveToAircraft(std::vector<route::LocalWaypoint>& survey, double aheadM,
                   const geo::SafePathFinder* finder = nullptr);

// After the no-fly stage: a turn point kObliqueLeadInM before every photo the aircraft does not
// already reach along its heading (a lane's first photo, one moved out of a margin), where that
// point and its two legs keep the zones' margins (`field`; none: anywhere), else a half or a
// quarter as far; where none keeps them (a detour round a zone ends at the photo) the photo is
// reached across, its heading (the waypoint's yaw) still the lane's.
void leadOntoLanes(std::vector<route::LocalWaypoint>& survey, const geo::NoFlyField* field);

} // namespace pf::mission
