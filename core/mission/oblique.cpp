#include "core/mission/oblique.h"

#include "core/mission/corridor.h"
#include "core/route/photo_waypoints.h"
#include "core/sensor/camera.h"

#include <cmath>

namespace pf::mission {

namespace {

geo::Vec2 backwards(double headingDeg, double aheadM) {
    const double h = headingDeg * M_PI / 180.0;
    return -aheadM * geo::Vec2(std::sin(h), std::cos(h));
}

bool sameHeading(double a, double b, double toleranceDeg = 1.0) {
    return std::abs(std::remainder(a - b, 360.0)) < toleranceDeg;
}

// Where the aircraft takes the photo planned at w (a safe point the plan reaches) when the straight
// move back to `to` crosses a zone's margin: `to`, or the nearest point outside the margin to it,
// when a safe way leads there from w (not into a pocket the margins close off); else as far back
// along the lane as the margin lets it go straight.
geo::Vec2 reachablePlace(const geo::SafePathFinder& finder, const route::LocalWaypoint& w,
                         const geo::Vec2& to) {
    const geo::Vec2 near = finder.nearestSafePoint(to);
    if (finder.detour(w.pos, near).ok())
        return near;
    double lo = 0.0, hi = (to - w.pos).norm();
    const geo::Vec2 dir = (to - w.pos) / hi;
    while (hi - lo > 0.01) {
        const double mid = 0.5 * (lo + hi);
        (finder.field().segmentIsSafe(w.pos, w.pos + mid * dir) ? lo : hi) = mid;
    }
    return w.pos + lo * dir;
}

// Whether the aircraft reaches waypoint i (a photo) along its heading: from a waypoint behind it
// on its line (within 10 degrees), not across or from ahead.
bool joinedAlongLane(const std::vector<route::LocalWaypoint>& w, std::size_t i) {
    if (i == 0)
        return false;
    const geo::Vec2 d = w[i].pos - w[i - 1].pos;
    if (d.norm() < 1e-6)
        return i > 1 && joinedAlongLane(w, i - 1);
    return sameHeading(route::headingDeg(d), w[i].headingDeg, 10.0);
}

// The heading of the photo nearest to waypoint i in the flight, looking forward first: the lane a
// turn point leads onto, else the one it leaves.
std::optional<double> neighbouringPhotoHeading(const std::vector<route::LocalWaypoint>& w,
                                               std::size_t i) {
    for (std::size_t j = i + 1; j < w.size(); ++j)
        if (w[j].kind == route::WaypointKind::Photo)
            return w[j].headingDeg;
    for (std::size_t j = i; j-- > 0;)
        if (w[j].kind == route::WaypointKind::Photo)
            return w[j].headingDeg;
    return std::nullopt;
}

} // namespace

std::string cameraTiltError(const Mission& m, const AircraftConfig& a, const std::string& who) {
    const double tilt = m.options.cameraTiltDeg;
    if (tilt == 0.0)
        return {};
    if (auto s = sensor::checkTilt(a.camera, tilt); !s)
        return who + ": " + s.error().message;
    if (fleet::fliesAsPlane(a.kind))
        return who + " flies as a plane, whose camera looks straight down: a camera tilt (oblique "
                     "photos) needs a multirotor with a gimbal; set the tilt to 0";
    if (plansCorridorLanes(m))
        return "a camera tilt is for area surveys (the double grid above all): the corridor's lanes "
               "are flown with the camera straight down; set the tilt to 0";
    return {};
}

Mission withPointedCameras(Mission m) {
    for (auto& a : m.aircraft)
        a.camera = pointedCamera(a, m.options);
    return m;
}

int moveToAircraft(std::vector<route::LocalWaypoint>& survey, double aheadM,
                   const geo::SafePathFinder* finder) {
    if (aheadM == 0.0)
        return 0;
    std::vector<geo::Vec2> moved(survey.size());
    for (std::size_t i = 0; i < survey.size(); ++i) {
        const route::LocalWaypoint& w = survey[i];
        bool onLane = w.kind == route::WaypointKind::Photo;
        if (w.kind == route::WaypointKind::Turn) {
            const auto lane = neighbouringPhotoHeading(survey, i);
            onLane = lane && sameHeading(*lane, w.headingDeg);
        }
        moved[i] = onLane ? w.pos + backwards(w.headingDeg, aheadM) : w.pos;
    }
    int outOfMargin = 0;
    for (std::size_t i = 0; i < survey.size(); ++i) {
        route::LocalWaypoint& w = survey[i];
        if (moved[i] != w.pos && finder && !finder->field().segmentIsSafe(w.pos, moved[i]) &&
            finder->field().pointIsSafe(w.pos)) {
            moved[i] = reachablePlace(*finder, w, moved[i]);
            outOfMargin += w.kind == route::WaypointKind::Photo;
        }
        w.pos = moved[i];
    }
    return outOfMargin;
}

void leadOntoLanes(std::vector<route::LocalWaypoint>& survey, const geo::NoFlyField* field) {
    std::vector<route::LocalWaypoint> out;
    out.reserve(survey.size() + survey.size() / 4);
    for (std::size_t i = 0; i < survey.size(); ++i) {
        const route::LocalWaypoint& w = survey[i];
        // Next to a zone (a detour ends at the photo) a shorter lead-in may still keep the margin.
        if (w.kind == route::WaypointKind::Photo && !joinedAlongLane(survey, i))
            for (double length : {kObliqueLeadInM, kObliqueLeadInM / 2, kObliqueLeadInM / 4}) {
                const geo::Vec2 lead = w.pos + backwards(w.headingDeg, length);
                if (field && !(field->segmentIsSafe(lead, w.pos) &&
                               (out.empty() || field->segmentIsSafe(out.back().pos, lead))))
                    continue;
                out.push_back({lead, w.headingDeg, route::WaypointKind::Turn, -1, w.pass});
                break;
            }
        out.push_back(w);
    }
    survey = std::move(out);
}

} // namespace pf::mission
