// PhotoGeometry: one photo's camera in the output grid and the ground it sees (its footprint), and
// the rule that picks, for a ground point, the photo that sees it most from above.
#pragma once

#include "core/geo/polygon_ops.h"
#include "core/geo/types.h"
#include "core/mosaic/camera_model.h"
#include "core/mosaic/ground_model.h"

namespace pf::mosaic {

struct PhotoGeometry {
    CameraModel camera;
    geo::Ring footprint; // grid metres: the ground seen within the maximum view angle
    geo::Box footprintBox;
    double heightAboveGroundM = 0.0; // under the camera
    double nadirGsdM = 0.0;
    double tanMaxView = 0.0; // tan of the maximum angle from the vertical a ground point is used at
    double edgeMarginPx = 1.0; // pixels this close to the image edge are not used
    bool seesGround =
        false; // false: nothing within the maximum view angle (a photo of the horizon)

    // The squared tangent of the angle between the vertical and the line from the camera to ground
    // point (x, y, z): the seam rule keeps, at every ground point, the photo where this is
    // smallest.
    double viewScore2(double x, double y, double z) const {
        const Vec3& c = camera.centre();
        const double dz = c.z() - z;
        if (dz <= 0)
            return 1e300;
        return ((x - c.x()) * (x - c.x()) + (y - c.y()) * (y - c.y())) / (dz * dz);
    }
    // True if the photo holds a usable pixel for ground point (x, y, z).
    bool sees(double x, double y, double z) const {
        if (viewScore2(x, y, z) > tanMaxView * tanMaxView)
            return false;
        double col = 0, row = 0;
        return camera.project(Vec3(x, y, z), &col, &row) && camera.inside(col, row, edgeMarginPx);
    }
};

// The photo's footprint on `ground`, from rays along its border (those steeper than the maximum
// view angle are shortened to it).
PhotoGeometry photoGeometry(const CameraModel& camera, const GroundModel& ground,
                            double maxViewAngleDeg);

} // namespace pf::mosaic
