#include "app/cli/export_args.h"

#include <cmath>

namespace pf::cli {

std::vector<OptionSpec> exportOptionSpecs() {
    return {{"firmware"}, {"end"}, {"capture"}, {"gimbal"}, {"trigger"}, {"hover-speed"}, {"home-elevation"}, {"altitude-frame"}, {"landing-heading"}};
}

namespace {

Error badChoice(const std::string& option, const std::string& expected, const std::string& got) {
    return makeError(ErrorCode::InvalidInput, "--" + option + ": expected " + expected + " but got '" + got + "'");
}

} // namespace

Result<io::ExportOptions> exportOptionsFromArgs(const Args& args) {
    io::ExportOptions opt;
    if (auto f = args.value("firmware")) {
        if (*f == "px4")
            opt.firmware = io::QgcFirmware::PX4;
        else if (*f != "ardupilot")
            return badChoice("firmware", "ardupilot or px4", *f);
    }
    if (auto e = args.value("end")) {
        if (*e == "land")
            opt.end = io::MissionEnd::Land;
        else if (*e != "rtl")
            return badChoice("end", "rtl or land", *e);
    }
    if (auto c = args.value("capture")) {
        if (*c == "digicam")
            opt.capture = io::CaptureCommand::DigicamControl;
        else if (*c != "image")
            return badChoice("capture", "image or digicam", *c);
    }
    if (auto g = args.value("gimbal")) {
        if (*g == "manager")
            opt.gimbal = io::GimbalCommand::GimbalManagerPitchYaw;
        else if (*g == "none")
            opt.gimbal = io::GimbalCommand::None;
        else if (*g != "mount")
            return badChoice("gimbal", "mount, manager or none", *g);
    }
    if (auto t = args.value("trigger")) {
        if (*t == "distance")
            opt.trigger = io::CameraTrigger::Distance;
        else if (*t != "photo")
            return badChoice("trigger", "photo or distance", *t);
    }
    auto hover = args.number("hover-speed");
    if (!hover)
        return hover.error();
    if (*hover) {
        if (!(**hover > 0))
            return makeError(ErrorCode::InvalidInput, "--hover-speed: the speed must be positive");
        opt.hoverSpeedMps = **hover;
    }
    auto elevation = args.number("home-elevation");
    if (!elevation)
        return elevation.error();
    if (*elevation) {
        if (!(std::abs(**elevation) <= 9000))
            return makeError(ErrorCode::InvalidInput,
                             "--home-elevation: expected metres above sea level between -9000 and 9000");
        opt.homeElevationM = **elevation;
    }
    auto heading = args.number("landing-heading");
    if (!heading)
        return heading.error();
    if (*heading) {
        if (!(**heading >= 0 && **heading < 360))
            return makeError(ErrorCode::InvalidInput,
                             "--landing-heading: expected degrees from north, from 0 to less than 360");
        opt.landingHeadingDeg = **heading;
    }
    if (auto f = args.value("altitude-frame")) {
        if (*f == "relative")
            opt.altitudeFrame = io::AltitudeFrame::RelativeToHome;
        else if (*f == "amsl")
            opt.altitudeFrame = io::AltitudeFrame::AboveSeaLevel;
        else if (*f == "terrain")
            opt.altitudeFrame = io::AltitudeFrame::AboveTerrain;
        else if (*f != "auto")
            return badChoice("altitude-frame", "auto, relative, amsl or terrain", *f);
    }
    return opt;
}

} // namespace pf::cli
