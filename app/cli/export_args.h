// The options that shape MAVLink missions and waypoint files, shared by plan, convert and upload:
// --firmware, --end, --capture, --gimbal, --trigger, --hover-speed, --home-elevation, --altitude-frame,
// --landing-heading.
#pragma once

#include "app/cli/args.h"
#include "core/io/export_context.h"
#include "core/result.h"

#include <vector>

#define PF_CLI_EXPORT_OPTIONS_HELP \
    "  --firmware NAME       ardupilot (default) or px4: the .plan's firmwareType (an upload\n" \
    "                        follows the vehicle's heartbeat: ArduPilot gets the home as item 0)\n" \
    "  --end ACTION          rtl (default) or land: what the vehicle does after the last waypoint\n" \
    "  --capture COMMAND     image (MAV_CMD_IMAGE_START_CAPTURE, default) or digicam\n" \
    "                        (MAV_CMD_DO_DIGICAM_CONTROL): the photo command after a photo waypoint\n" \
    "  --gimbal COMMAND      mount (MAV_CMD_DO_MOUNT_CONTROL, default), manager\n" \
    "                        (MAV_CMD_DO_GIMBAL_MANAGER_PITCHYAW) or none: the camera pointed at the start\n" \
    "                        (straight down, or tilted forward by the mission's camera tilt)\n" \
    "  --trigger MODE        photo (default: a waypoint and a capture per photo) or distance: lanes of\n" \
    "                        equally spaced photos become their two ends with MAV_CMD_DO_SET_CAM_TRIGG_DIST\n" \
    "                        (.plan, .waypoints and upload)\n" \
    "  --hover-speed M/S     the .plan hoverSpeed (default: the route's cruise speed)\n" \
    "  --home-elevation M    ground elevation of the home above sea level, for the planned home of a\n" \
    "                        .plan and the home line of a .waypoints (default 0: unknown; over a\n" \
    "                        terrain model, from the DEM), and the take-off ground for --terrain follow\n" \
    "  --altitude-frame F    altitudes of .plan, .waypoints and upload: auto (amsl over a terrain model,\n" \
    "                        else relative), relative (to home, frame 3), amsl (above sea level, frame 0,\n" \
    "                        QGroundControl AltitudeMode 2), terrain (above the ground, frame 10\n" \
    "                        GLOBAL_TERRAIN_ALT, AltitudeMode 4: the vehicle follows its terrain data)\n" \
    "  --landing-heading DEG a plane's landing direction, degrees from north: into the wind (where it\n" \
    "                        blows from). Default: the first lane's heading, turned in 15-degree steps\n" \
    "                        until the 400 m approach keeps the no-fly margins\n"

namespace pf::cli {

std::vector<OptionSpec> exportOptionSpecs();
// Errors name the option and the value.
Result<io::ExportOptions> exportOptionsFromArgs(const Args& args);

} // namespace pf::cli
