// A route laid out as one WPML wayline: the waypoints the aircraft flies (a distance-triggered lane
// kept as its two ends), their heights in the mission's height frame, and the action groups that
// point the camera down and take the photos. Internal to the WPML export.
#pragma once

#include "core/fleet/aircraft.h"
#include "core/geo/types.h"
#include "core/io/export_context.h"
#include "core/result.h"
#include "core/route/waypoint.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace pf::io::wpml {

struct WaylinePoint {
    geo::LonLat position;
    double heightM = 0.0; // executeHeight / wpml:height: above take-off, or EGM96 (absolute)
    double ellipsoidHeightM =
        0.0;                 // wpml:ellipsoidHeight: the same height above the WGS84 ellipsoid
    double headingDeg = 0.0; // the plan's heading, [-180, 180] as WPML wants it
};

enum class GroupKind {
    Gimbal,           // gimbalRotate to the pitch (MissionSettings) on reaching the point
    Photo,            // takePhoto on reaching the point
    PhotosByDistance, // takePhoto every spacingM metres from `start` to `end` (multipleDistance)
};

struct ActionGroup {
    GroupKind kind = GroupKind::Photo;
    std::size_t start = 0;
    std::size_t end = 0;
    double spacingM = 0.0;
};

struct Wayline {
    std::vector<WaylinePoint> points;
    std::vector<ActionGroup> groups; // by start index, the gimbal group first
    bool absolute = false;           // EGM96 heights (template) / WGS84 ellipsoidal (waylines)
    double speedMps = 0.0;
    double highestAboveTakeOffM = 0.0;
    std::size_t photos = 0; // the photos the aircraft takes: the route's photo waypoints
};

// What the mission configuration says besides the wayline.
struct MissionSettings {
    fleet::DjiDroneType drone;
    int payloadEnum = 0;
    std::string lens = "wide";
    std::optional<geo::LonLat> home;
    double homeEllipsoidHeightM = 0.0; // 0 when the take-off point's elevation is unknown
    MissionEnd end = MissionEnd::ReturnToLaunch;
    double takeOffSecurityHeightM = 20.0;
    double transitionalSpeedMps = 10.0;
    double rthHeightM = 100.0;
    // The gimbal's pitch at every point and in the first point's gimbalRotate: -90 straight down,
    // -90 + the tilt for oblique photos (ExportContext::gimbalPitchDeg).
    double gimbalPitchDeg = -90.0;
};

// The highest speed a WPML mission flies: globalTransitionalSpeed is documented as [0, 15] m/s
// ("waylines.wpml", wpml:missionConfig); the waypoint speeds are kept within it too
// ("template.kml": wpml:autoFlightSpeed "(0, the maximum flight speed]" of the model; 15 m/s is
// within every catalog DJI aircraft's maximum).
constexpr double kMaxSpeedMps = 15.0;

// The route's wayline. `homeAmslM`: the take-off point's ground above sea level (EGM96), when
// known; `absolute`: heights above sea level instead of above take-off (needs homeAmslM). Errors:
// the EGM96 geoid is not available (PROJ's egm96_15.gtx).
Result<Wayline> layOutWayline(const route::Route& route, std::optional<double> homeAmslM,
                              bool absolute);

// The EGM96 geoid's height above the WGS84 ellipsoid (N: ellipsoidal = EGM96 height + N) at each
// point, from PROJ's EGM96 grid (proj-data's egm96_15.gtx), the geoid the terrain model's heights
// use.
Result<std::vector<double>> egm96Undulations(const std::vector<geo::LonLat>& points);

// The two documents of the .kmz (the DJI WPML pages "template.kml" and "waylines.wpml").
std::string templateKml(const MissionSettings& settings, const Wayline& wayline);
std::string waylinesWpml(const MissionSettings& settings, const Wayline& wayline);

} // namespace pf::io::wpml
