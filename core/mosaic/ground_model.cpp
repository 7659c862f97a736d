#include "core/mosaic/ground_model.h"

#include <cmath>

namespace pf::mosaic {

std::optional<Vec3> intersectGround(const GroundModel& ground, const Vec3& origin,
                                    const Vec3& dir) {
    if (dir.z() >= -1e-6)
        return std::nullopt;
    if (auto h = ground.levelHeight()) {
        const double t = (*h - origin.z()) / dir.z();
        if (t <= 0)
            return std::nullopt;
        return Vec3(origin + t * dir);
    }
    // Terrain: move along the ray to the height of the ground under the current point until the
    // point stays put. This settles wherever the ground is less steep than the ray, which holds for
    // photos looking down at a survey site.
    double h = ground.heightAt(origin.x(), origin.y());
    Vec3 p = origin;
    for (int i = 0; i < 50; ++i) {
        const double t = (h - origin.z()) / dir.z();
        if (t <= 0)
            return std::nullopt;
        p = origin + t * dir;
        const double next = ground.heightAt(p.x(), p.y());
        if (!std::isfinite(next))
            return std::nullopt;
        if (std::abs(next - h) < 0.01)
            return Vec3(p.x(), p.y(), next);
        h = next;
    }
    return std::abs(ground.heightAt(p.x(), p.y()) - p.z()) < 0.05 ? std::optional<Vec3>(p)
                                                                  : std::nullopt;
}

} // namespace pf::mosaic
