// The mosaic's output frame: the site whose UTM zone holds the output grid, the ground in grid units
// and each placed photo's camera in that grid.
#pragma once

#include "core/mosaic/camera_model.h"
#include "core/mosaic/ground_model.h"
#include "core/mosaic/mosaic_types.h"
#include "core/mosaic/pose_resolver.h"
#include "core/mosaic/utm_projection.h"

#include <memory>
#include <optional>
#include <vector>

namespace pf::mosaic {

// The ground model in grid units: UTM stretches horizontal distances by its point scale, and the
// heights are stretched alike so that view angles stay true.
class ScaledGround : public GroundModel {
public:
    ScaledGround(std::shared_ptr<const GroundModel> base, double k)
        : m_base(std::move(base)), m_k(k) {}
    double heightAt(double x, double y) const override { return m_k * m_base->heightAt(x, y); }
    std::optional<double> levelHeight() const override {
        const auto h = m_base->levelHeight();
        return h ? std::optional<double>(m_k * *h) : std::nullopt;
    }

private:
    std::shared_ptr<const GroundModel> m_base;
    double m_k;
};

// The point whose UTM zone the mosaic uses: the centre of the plan's area when a plan is given, else
// the median of the photos' positions.
geo::LonLat mosaicSite(const MosaicOptions& options, const std::vector<PlacedPhoto>& photos);

// A placed photo's camera in the grid: its position and heights scaled by the point scale k, its yaw
// turned from true north to grid north.
CameraModel gridCamera(const PlacedPhoto& p, const UtmProjection& utm, double k);

} // namespace pf::mosaic
