// Oblique photos (PlannerOptions::cameraTiltDeg): a camera tilted forward photographs the ground
// ahead of the aircraft. The planners place the photos' centres as they place nadir photos (the
// tilted footprint, sensor::footprintAt, gives the overlaps); then each photo's waypoint is moved
// back along its lane by the footprint's aheadM, so that the aircraft flies where it must to see
// that ground, and the no-fly stage keeps the aircraft out of the zones' margins as for any plan
// (a photo that would be taken from within one is taken from outside it, a leg across one flown
// round it); the coverage check then measures the photos as taken. See docs/corridors.md
// ("Oblique photos").
#pragma once

#include "core/mission/mission.h"
#include "core/route/waypoint.h"

#include <vector>

namespace pf::mission {

// The mission as planned: every aircraft's camera pointed as the options say (pointedCamera).
Mission withPointedCameras(Mission m);

// How far before a lane's first oblique photo the aircraft joins the lane's line (a turn point),
// so that it arrives along the lane, facing where the camera must look, whatever its autopilot's
// yaw rule (facing the next waypoint, its course, or the waypoint's yaw): 10 m gives a multirotor
// turning at 90 degrees/s and accelerating at 2.5 m/s2 the 2 s a reversal takes.
constexpr double kObliqueLeadInM = 10.0;

// The photo waypoints of a survey planned for the photos' centres moved back along their heading by
// aheadM, to where the aircraft takes them; a turn point on a lane's line (facing as the photo next
// to it in the flight does) moves with its lane; other turn and transit points stay. A lane the
// aircraft does not already join along its line gets a turn point kObliqueLeadInM before its first
// photo. Every point lies within aheadM + kObliqueLeadInM of a point planned.
void moveToAircraft(std::vector<route::LocalWaypoint>& survey, double aheadM);

} // namespace pf::mission
