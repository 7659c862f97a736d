// The mosaic's output frame (see site_frame.h).
#include "core/mosaic/site_frame.h"

#include <algorithm>

namespace pf::mosaic {

geo::LonLat mosaicSite(const MosaicOptions& options, const std::vector<PlacedPhoto>& photos) {
    if (options.plan && !options.plan->area.empty()) {
        double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
        for (const auto& poly : options.plan->area)
            for (const auto& p : poly.outer) {
                x0 = std::min(x0, p.lon);
                x1 = std::max(x1, p.lon);
                y0 = std::min(y0, p.lat);
                y1 = std::max(y1, p.lat);
            }
        return {0.5 * (x0 + x1), 0.5 * (y0 + y1)};
    }
    std::vector<double> lons, lats;
    for (const auto& p : photos) {
        lons.push_back(p.position.lon);
        lats.push_back(p.position.lat);
    }
    std::nth_element(lons.begin(), lons.begin() + lons.size() / 2, lons.end());
    std::nth_element(lats.begin(), lats.begin() + lats.size() / 2, lats.end());
    return {lons[lons.size() / 2], lats[lats.size() / 2]};
}

CameraModel gridCamera(const PlacedPhoto& p, const UtmProjection& utm, double k) {
    const geo::Vec2 g = utm.toGrid(p.position);
    CameraPose pose;
    pose.position = Vec3(g.x(), g.y(), p.altitudeM * k);
    pose.yawDeg = p.yawDeg + utm.gridFromTrueDeg(p.position);
    pose.pitchDeg = p.pitchDeg;
    pose.rollDeg = p.rollDeg;
    CameraIntrinsics in;
    in.widthPx = p.meta.widthPx;
    in.heightPx = p.meta.heightPx;
    in.longSideFovDeg = p.longSideFovDeg;
    in.shortSideFovDeg = p.shortSideFovDeg;
    in.orientation = p.meta.orientation;
    return CameraModel(in, pose);
}

} // namespace pf::mosaic
