#include "ui/map/web_mercator.h"

#include <algorithm>
#include <cmath>

namespace pf::ui::mercator {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

QPointF toScene(double lonDeg, double latDeg) {
    const double lat = std::clamp(latDeg, -kMaxLatitude, kMaxLatitude) * kPi / 180.0;
    const double x = kEarthRadius * lonDeg * kPi / 180.0;
    const double y = kEarthRadius * std::log(std::tan(kPi / 4.0 + lat / 2.0));
    return {x, -y};
}

QPointF toLonLat(const QPointF& scene) {
    const double lon = scene.x() / kEarthRadius * 180.0 / kPi;
    const double lat = (2.0 * std::atan(std::exp(-scene.y() / kEarthRadius)) - kPi / 2.0) * 180.0 / kPi;
    return {lon, lat};
}

double tileSpan(int z) { return 2.0 * kHalfWorld / double(1 << z); }

QRectF tileRect(int z, int x, int y) {
    const double s = tileSpan(z);
    return {-kHalfWorld + x * s, -kHalfWorld + y * s, s, s};
}

int zoomForResolution(double metresPerPixel) {
    if (!(metresPerPixel > 0)) return kMaxZoom;
    // Round down slightly less than a full level so tiles are never magnified more than ~1.4x.
    const double z = std::log2(2.0 * kHalfWorld / (kTileSize * metresPerPixel));
    return std::clamp(int(std::lround(z)), 0, kMaxZoom);
}

double groundScale(double latDeg) { return std::cos(latDeg * kPi / 180.0); }

} // namespace pf::ui::mercator
