// GroundModel: the height of the ground under the photos, the surface footprints are projected on.
// Flat at the take-off height today; a terrain model (DEM) plugs in through the same interface.
#pragma once

#include "core/mosaic/camera_model.h"

#include <optional>

namespace pf::mosaic {

// Heights are in the vertical datum of the camera positions (for photos placed by their altitude
// above take-off, the take-off point is at 0). Implementations must be safe to call from several
// threads at once.
class GroundModel {
public:
    virtual ~GroundModel() = default;
    // Ground height at grid position (x, y), metres.
    virtual double heightAt(double x, double y) const = 0;
    // The height when the ground is a level plane (which allows exact footprints and fast paths).
    virtual std::optional<double> levelHeight() const { return std::nullopt; }
};

// A level plane: the flat-ground model (at the take-off height, 0, by default).
class FlatGround : public GroundModel {
public:
    explicit FlatGround(double height = 0.0) : m_height(height) {}
    double heightAt(double, double) const override { return m_height; }
    std::optional<double> levelHeight() const override { return m_height; }

private:
    double m_height;
};

// Where the ray from `origin` along `dir` first meets the ground; nothing if it points above the
// horizon or (on terrain) the iteration does not settle within 5 cm.
std::optional<Vec3> intersectGround(const GroundModel& ground, const Vec3& origin, const Vec3& dir);

} // namespace pf::mosaic
