// Photo waypoints from a cell path: straight lanes with photos at the trigger distance, or paper 001's
// several photos per cell (section IV).
#pragma once

#include "core/geo/no_fly_field.h"
#include "core/grid/grid.h"
#include "core/plan/cell_path.h"
#include "core/route/waypoint.h"
#include "core/sensor/camera.h"

#include <vector>

namespace pf::route {

// How many photos a cell needs: along the track, cell side / effective short side; across the track,
// cell side / effective long side (1 unless the overlaps make the long side the shorter one), each
// rounded up.
struct PhotosPerCell {
    int along = 1;
    int across = 1;
};
PhotosPerCell photosPerCell(double cellSizeM, const sensor::EffectiveFootprint& fp);

// Heading of a direction in the local frame, clockwise from north (local +y), in [0, 360).
double headingDeg(const geo::Vec2& dir);

// Which rule places the photos of a cell path.
enum class PhotoRule {
    // Straight lanes (route/lanes.h): each straight run of photographed cells is one lane with photos at
    // the trigger distance from one exact end to the other; cells next to a no-fly margin keep the
    // per-cell photos. What every planner flies.
    Lanes,
    // Paper 001's rule alone: every cell gets its own photos around its flight position.
    PerCell,
};

// The waypoints of a cell path, in flight order:
// - lanes (PhotoRule::Lanes): see cellPathGroups; a lane's photos carry the cell under them. The way
//   from a lane's end to the next waypoint, and onto a lane, is straight when safe, else through the
//   centre of the lane's end cell (on the lane's safe line), from where the cell path's moves lead on.
// - a photographed cell outside a lane (and every cell under PhotoRule::PerCell) gets its photos (kind
//   Photo) with the sensor's long side across the direction of flight into the cell (out of it for the
//   first cell): `along` photos spaced by cell / along <= the effective short side, centred on the cell's
//   flight position so that together they cover the whole cell (the middle one sits on the flight
//   position when `along` is odd). At a turn the aircraft turns at the cell's last photo.
// - a revisited cell gets no second photo: a Transit waypoint where the path changes direction there,
//   and at the path's ends, keeps the transit on its safe cell-to-cell legs.
// - a cell flown over before it is photographed (the way from the take-off cell to the start) gets a
//   Turn waypoint where the path changes direction there: a turn point without a photo.
// Every waypoint carries the cell it belongs to.
//
// Safe placement: every waypoint, and the straight leg to it from the previous one, keeps out of the
// grid's buffered no-fly zones (Grid::pointIsSafe / segmentIsSafe), so the later no-fly stage has no
// waypoint to move. A photo whose place along the track is unsafe slides back along the straight line
// to its cell's flight position (safe by construction) up to the last point where the photo, the way
// to it from the flight position, and its legs to the waypoints before and after are safe; a slid photo
// that lands on another photo of its cell is dropped (it would take the same picture). Legs the
// planner could not fly straight anyway (jumps between parts of the area) are left to the detours.
// See photo_waypoints.cpp for why the cell stays covered. When the real footprint (fp.real) is shorter
// than the cell (a side overlap below about 25 %), a slid photo may no longer see all of its share of
// the cell's admissible ground: then one extra photo is taken at the safe point nearest to the planned
// one if it sees some of it; it is safe too, but the legs to and from it may need the no-fly stage's
// detours. With fp.real unset (zero sides) no extra photo is considered. Lane photos lie on their lane's
// safe line and never slide.
struct PhotoPlacement {
    int slid = 0;         // photos slid back along the track out of a no-fly margin
    int merged = 0;       // slid photos dropped because they coincided with another photo of the cell
    int added = 0;        // extra photos beside a margin for ground the slid photos no longer see
    double maxSlideM = 0; // the longest slide
};
std::vector<LocalWaypoint> photoWaypoints(const grid::Grid& g, const plan::CellPath& path,
                                          const sensor::EffectiveFootprint& fp, PhotoPlacement* placement = nullptr,
                                          PhotoRule rule = PhotoRule::Lanes);

// Turn and transit waypoints closer than this to a neighbouring waypoint are dropped: they would only
// add a leg of no length (the 0.1 m most formats merge anyway).
constexpr double kMinWaypointGapM = 0.1;
// Drops those waypoints, and a photo repeating the one before it. Dropping a waypoint joins its
// neighbours straight, which can cut a corner: a detour's corner 1 cm before a photo beside a margin,
// dropped, once left a 2.4 m leg 4.96 m from a zone (margin 5 m). With `field` (a planner's field, as
// after the no-fly stage, where nothing repairs a leg any more), a waypoint is dropped only when the
// leg that replaces it keeps the margin; else the pair is merged at its position (the neighbour, a
// photo moved by less than the gap: the same picture) when the leg that makes is safe; else both stay.
void dropNearDuplicates(std::vector<LocalWaypoint>& waypoints, const geo::NoFlyField* field = nullptr);

// The cell path flies back through photographed cells over grid moves (a dead end's way out, a lead-in
// to where the photos begin). Between two waypoints with nothing to photograph in between, the
// aircraft flies straight instead whenever the straight leg keeps out of every no-fly margin and passes
// only over cells of the area: shorter and with fewer turns. Missions apply it after photoWaypoints.
void straightenTransits(const grid::Grid& g, std::vector<LocalWaypoint>& waypoints);

} // namespace pf::route
