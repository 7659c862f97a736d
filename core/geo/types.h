// Geometry value types: WGS84 lon/lat and local-metre polygons with holes.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace pf::geo {

// WGS84 longitude/latitude in degrees (longitude first, as in GeoJSON).
struct LonLat {
    double lon = 0.0;
    double lat = 0.0;
    friend bool operator==(const LonLat& a, const LonLat& b) { return a.lon == b.lon && a.lat == b.lat; }
    friend bool operator!=(const LonLat& a, const LonLat& b) { return !(a == b); }
};

// A point in a local metric frame: x east, y north, metres.
using Vec2 = Eigen::Vector2d;

// A ring is stored open: the first vertex is not repeated at the end.
using Ring = std::vector<Vec2>;

// A polygon with holes in local metres. The outer ring may be in either orientation.
struct Polygon {
    Ring outer;
    std::vector<Ring> holes;
};

using MultiPolygon = std::vector<Polygon>;

using GeoRing = std::vector<LonLat>;

// A polygon with holes in WGS84 lon/lat (rings open, as Ring).
struct GeoPolygon {
    GeoRing outer;
    std::vector<GeoRing> holes;
    friend bool operator==(const GeoPolygon& a, const GeoPolygon& b) {
        return a.outer == b.outer && a.holes == b.holes;
    }
    friend bool operator!=(const GeoPolygon& a, const GeoPolygon& b) { return !(a == b); }
};

} // namespace pf::geo
