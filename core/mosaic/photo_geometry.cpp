#include "core/mosaic/photo_geometry.h"

#include <algorithm>
#include <cmath>

namespace pf::mosaic {

namespace {
constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr int kStepsPerSide = 16;
} // namespace

PhotoGeometry photoGeometry(const CameraModel& camera, const GroundModel& ground,
                            double maxViewAngleDeg) {
    PhotoGeometry g;
    g.camera = camera;
    g.tanMaxView = std::tan(std::clamp(maxViewAngleDeg, 1.0, 85.0) * kDeg);
    const Vec3& c = camera.centre();
    g.heightAboveGroundM = c.z() - ground.heightAt(c.x(), c.y());
    g.nadirGsdM = camera.nadirGsdM(std::max(g.heightAboveGroundM, 1e-3));
    if (!(g.heightAboveGroundM > 0))
        return g;

    const double w = camera.storedWidth(), h = camera.storedHeight();
    const double maxRadius = g.heightAboveGroundM * g.tanMaxView;
    int within = 0; // border rays inside the view angle
    auto addBorderPoint = [&](double col, double row) {
        Vec3 dir = camera.ray(col, row);
        const double horiz = std::hypot(dir.x(), dir.y());
        // Rays beyond the maximum view angle (or above the horizon) are turned down to it: the
        // footprint bounds what the seams may use, not everything the photo shows.
        if (dir.z() >= 0 || horiz > -dir.z() * g.tanMaxView) {
            if (horiz < 1e-12)
                return;
            dir = Vec3(dir.x() / horiz * g.tanMaxView, dir.y() / horiz * g.tanMaxView, -1.0)
                      .normalized();
        } else {
            ++within;
        }
        auto p = intersectGround(ground, c, dir);
        if (!p)
            return;
        // On uneven ground the turned-down ray may still reach further than the flat radius; clamp.
        const geo::Vec2 d(p->x() - c.x(), p->y() - c.y());
        const double r = d.norm();
        if (r > 1.5 * maxRadius + 1.0)
            g.footprint.push_back(geo::Vec2(c.x(), c.y()) + d / r * maxRadius);
        else
            g.footprint.push_back({p->x(), p->y()});
    };
    for (int i = 0; i < kStepsPerSide; ++i)
        addBorderPoint(w * i / kStepsPerSide, 0.0);
    for (int i = 0; i < kStepsPerSide; ++i)
        addBorderPoint(w, h * i / kStepsPerSide);
    for (int i = 0; i < kStepsPerSide; ++i)
        addBorderPoint(w - w * i / kStepsPerSide, h);
    for (int i = 0; i < kStepsPerSide; ++i)
        addBorderPoint(0.0, h - h * i / kStepsPerSide);
    if (g.footprint.size() < 3)
        return g;
    g.footprintBox = geo::bounds(g.footprint);
    // Usable if part of the border is within the view angle or the photo holds the nadir point.
    double col = 0, row = 0;
    const bool nadirInside =
        camera.project(Vec3(c.x(), c.y(), c.z() - g.heightAboveGroundM), &col, &row) &&
        camera.inside(col, row);
    g.seesGround = within > 0 || nadirInside;
    return g;
}

} // namespace pf::mosaic
