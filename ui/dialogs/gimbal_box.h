// The "Gimbal" choice of the Export and the Connect and Upload dialogs: one box, one wording, the
// pitch the MAVLink missions will point the camera at (io::ExportContext::gimbalPitchDeg).
#pragma once

class QComboBox;
class QString;

namespace pf::ui {

// DO_MOUNT_CONTROL, DO_GIMBAL_MANAGER_PITCHYAW or no gimbal command (io::GimbalCommand as item
// data), each saying where the camera will look: straight down, or tilted `tiltDeg` forward (the
// mission's camera tilt, oblique photos).
QComboBox* makeGimbalBox(const QString& objectName, double tiltDeg);

} // namespace pf::ui
