#include "core/sensor/camera.h"

namespace pf::sensor {

bool operator==(const Camera& a, const Camera& b) {
    return a.name == b.name && a.sensorWidthMm == b.sensorWidthMm && a.sensorHeightMm == b.sensorHeightMm &&
           a.focalLengthMm == b.focalLengthMm && a.imageWidthPx == b.imageWidthPx &&
           a.imageHeightPx == b.imageHeightPx && a.hfovDeg == b.hfovDeg && a.vfovDeg == b.vfovDeg;
}

} // namespace pf::sensor
