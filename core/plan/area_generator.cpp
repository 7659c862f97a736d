#include "core/plan/area_generator.h"

#include "core/geo/local_frame.h"
#include "core/geo/polygon_ops.h"
#include "core/geo/validation.h"

#include <cpl_json.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace pf::plan {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kZoneClearanceM = 2.0;   // between zones that are not one pair or pocket
constexpr double kMaxZoneShare = 0.25;    // of the area
constexpr double kBoundaryClearanceM = 0.5; // zones stay this far inside the area (rounding to 1 mm)
constexpr int kAttemptsPerGroup = 120;

// The standard distributions are not the same in every standard library: draws are made from the raw
// 64-bit engine output, which the standard fixes, so a seed gives the same areas everywhere.
class Rng {
public:
    explicit Rng(std::uint64_t seed) : m_g(seed) {}
    double uniform(double lo, double hi) { return lo + (hi - lo) * (static_cast<double>(m_g() >> 11) * 0x1.0p-53); }
    int integer(int lo, int hi) { return std::min(hi, lo + static_cast<int>(uniform(0.0, 1.0) * (hi - lo + 1))); }
    bool chance(double p) { return uniform(0.0, 1.0) < p; }

private:
    std::mt19937_64 m_g;
};

// SplitMix64 of the seed and the area's index: each area has its own stream.
std::uint64_t areaSeed(std::uint64_t seed, std::uint64_t index) {
    std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (index + 1);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

geo::Ring rect(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

// Scaled about the origin, rotated counter-clockwise, then moved.
geo::Ring placed(const geo::Ring& r, double scale, double rotDeg, const geo::Vec2& at) {
    const double t = rotDeg * kPi / 180.0, c = std::cos(t), s = std::sin(t);
    geo::Ring out;
    out.reserve(r.size());
    for (const auto& p : r)
        out.push_back(at + geo::Vec2(c * p.x() - s * p.y(), s * p.x() + c * p.y()) * scale);
    return out;
}

// Moved so that its bounding box is centred on the origin, counter-clockwise.
geo::Ring centred(geo::Ring r) {
    const geo::Box b = geo::bounds(r);
    const geo::Vec2 c = 0.5 * (b.min + b.max);
    for (auto& p : r)
        p -= c;
    if (geo::signedArea(r) < 0)
        std::reverse(r.begin(), r.end());
    return r;
}

// Random positive weights scaled to sum to `total`.
std::vector<double> splits(Rng& rng, int n, double total) {
    std::vector<double> w(static_cast<std::size_t>(n));
    double sum = 0;
    for (auto& v : w)
        sum += (v = rng.uniform(0.7, 1.3));
    for (auto& v : w)
        v *= total / sum;
    return w;
}

// Vertices at sorted angles around the origin, on an ellipse of axes (aspect, 1) times the radii.
geo::Ring radial(Rng& rng, int n, double aspect, const std::vector<double>& radii) {
    const auto inc = splits(rng, n, 2 * kPi);
    double a = rng.uniform(0.0, 2 * kPi);
    geo::Ring r;
    for (int i = 0; i < n; ++i) {
        a += inc[static_cast<std::size_t>(i)];
        const double k = radii[static_cast<std::size_t>(i)];
        r.push_back({aspect * k * std::cos(a), k * std::sin(a)});
    }
    return r;
}

struct Outline {
    geo::Ring ring;
    std::string shape;
};

// An outline of about unit size; the caller scales it to the wanted area.
Outline outline(AreaFamily family, Rng& rng) {
    switch (family) {
    case AreaFamily::Rectangle:
        return {rect(0, 0, rng.uniform(1.0, 3.0), 1.0), "rectangle"};
    case AreaFamily::Rectilinear: {
        const double w = rng.uniform(1.0, 2.0), h = 1.0;
        switch (rng.integer(0, 3)) {
        case 0: {
            const double a = rng.uniform(0.35, 0.65) * w, b = rng.uniform(0.35, 0.65) * h;
            return {{{0, 0}, {w, 0}, {w, h - b}, {w - a, h - b}, {w - a, h}, {0, h}}, "L"};
        }
        case 1: {
            const double nw = rng.uniform(0.25, 0.45) * w, la = rng.uniform(0.2 * w, 0.8 * w - nw);
            const double nd = rng.uniform(0.35, 0.7) * h;
            return {{{0, 0}, {w, 0}, {w, h}, {la + nw, h}, {la + nw, h - nd}, {la, h - nd}, {la, h}, {0, h}}, "U"};
        }
        case 2: {
            const double bh = rng.uniform(0.3, 0.5) * h, sw = rng.uniform(0.3, 0.5) * w;
            const double sx = rng.uniform(0.1 * w, 0.9 * w - sw);
            return {{{sx, 0}, {sx + sw, 0}, {sx + sw, h - bh}, {w, h - bh}, {w, h}, {0, h}, {0, h - bh}, {sx, h - bh}},
                    "T"};
        }
        default: {
            const int k = rng.integer(3, 5);
            const auto dx = splits(rng, k, w), dy = splits(rng, k, h);
            geo::Ring r{{0, 0}, {w, 0}};
            double x = w, y = 0;
            for (int j = 0; j < k; ++j) {
                y += dy[static_cast<std::size_t>(j)];
                r.push_back({x, y});
                if (j + 1 < k) {
                    x -= dx[static_cast<std::size_t>(j)];
                    r.push_back({x, y});
                }
            }
            r.push_back({0, h});
            return {r, "staircase"};
        }
        }
    }
    case AreaFamily::Polygonal: {
        const double aspect = rng.uniform(1.0, 2.0);
        if (rng.chance(0.5)) {
            const int n = rng.integer(5, 10);
            return {radial(rng, n, aspect, std::vector<double>(static_cast<std::size_t>(n), 1.0)), "convex"};
        }
        const int n = rng.integer(7, 12);
        std::vector<double> radii(static_cast<std::size_t>(n));
        for (auto& v : radii)
            v = rng.uniform(0.55, 1.0);
        // At least one deep dent, so that the outline is concave whatever the radii drawn.
        radii[static_cast<std::size_t>(rng.integer(0, n - 1))] = 0.4;
        return {radial(rng, n, aspect, radii), "concave"};
    }
    }
    return {rect(0, 0, 1, 1), "rectangle"};
}

// A group of zones placed together (one zone, or the parts of a pair or pocket), centred on the origin.
struct ZoneGroup {
    std::vector<geo::Ring> rings;
    std::string kind;
};

// Kinds drawn per group: 8 % pockets, 10 % pairs, 10 % U-shaped zones, 30 % circles, 42 % rectangles
// (a pocket or pair only while that many zones remain to be placed).
ZoneGroup zoneGroup(Rng& rng, int remaining, double marginM, double size) {
    const double pick = rng.uniform(0.0, 1.0);
    if (pick < 0.08 && remaining >= 4) {
        // Four bars around a square, gaps at the corners narrower than two margins.
        const double q = rng.uniform(2.4, 6.0) * marginM, t = rng.uniform(5.0, 10.0) * size;
        const double g = rng.uniform(0.6, 2.4) * marginM;
        return {{rect(g / 2, -t, q - g / 2, 0), rect(q, g / 2, q + t, q - g / 2), rect(g / 2, q, q - g / 2, q + t),
                 rect(-t, g / 2, 0, q - g / 2)},
                "pocket"};
    }
    if (pick < 0.18 && remaining >= 2) {
        const double g = rng.uniform(0.4, 2.0) * marginM;
        const double a = rng.uniform(8.0, 40.0) * size, b = rng.uniform(8.0, 40.0) * size;
        const double c = rng.uniform(8.0, 40.0) * size;
        return {{rect(-a, 0, 0, b), rect(g, 0, g + c, b * rng.uniform(0.6, 1.4))}, "pair"};
    }
    if (pick < 0.28) {
        // A U whose opening the margin closes.
        const double g = rng.uniform(0.6, 1.6) * marginM, t = rng.uniform(5.0, 12.0) * std::max(size, 0.5);
        const double h = rng.uniform(20.0, 45.0) * size + t, tb = rng.uniform(5.0, 10.0) * std::max(size, 0.5);
        const double w = g + 2 * t;
        return {{{{0, 0}, {w, 0}, {w, h}, {w - t, h}, {w - t, tb}, {t, tb}, {t, h}, {0, h}}}, "U"};
    }
    if (pick < 0.58) {
        const double r = rng.uniform(6.0, 25.0) * size;
        geo::Ring c;
        for (int i = 0; i < 24; ++i)
            c.push_back({r * std::cos(2 * kPi * i / 24), r * std::sin(2 * kPi * i / 24)});
        return {{c}, "circle"};
    }
    return {{rect(0, 0, rng.uniform(8.0, 50.0) * size, rng.uniform(8.0, 50.0) * size)}, "rectangle"};
}

// Centres a group on the origin (the middle of its bounding box).
ZoneGroup centredGroup(ZoneGroup g) {
    geo::Box b = geo::bounds(g.rings.front());
    for (const auto& r : g.rings) {
        const geo::Box rb = geo::bounds(r);
        b.min = b.min.cwiseMin(rb.min);
        b.max = b.max.cwiseMax(rb.max);
    }
    const geo::Vec2 c = 0.5 * (b.min + b.max);
    for (auto& r : g.rings)
        for (auto& p : r)
            p -= c;
    return g;
}

// 1e-8 degree (about 1 mm) keeps the files short; the checks run on the rounded coordinates.
double rounded(double deg) { return std::round(deg * 1e8) / 1e8; }

geo::GeoPolygon toGeo(const geo::LocalFrame& frame, const geo::Ring& r) {
    geo::GeoPolygon p;
    for (const auto& q : frame.toGeo(r))
        p.outer.push_back({rounded(q.lon), rounded(q.lat)});
    return p;
}

// What the generator promises, checked on the area as written: valid polygons, zones inside the area,
// at most a quarter of it covered.
// (The zones are checked with GEOS in the local frame: geo::validatePolygon builds a planning frame per
// polygon, which would cost more than generating them.)
bool acceptable(const EvalArea& a, const geo::LocalFrame& frame) {
    if (geo::hasError(geo::validatePolygon(a.area, "the area")))
        return false;
    const geo::MultiPolygon area{frame.toLocal(a.area)};
    double zones = 0;
    for (const auto& z : a.noFly) {
        const geo::Polygon local = frame.toLocal(z);
        if (z.outer.size() < 3 || !geo::isValid(local))
            return false;
        const double za = geo::area(local);
        if (geo::area(geo::difference(local, area)) > 1e-6 * za)
            return false;
        zones += za;
    }
    return zones <= kMaxZoneShare * geo::area(area) + 1e-6;
}

Result<GeneratedArea> generateOne(const AreaGeneratorOptions& o, std::size_t index, const geo::LocalFrame& frame) {
    Rng rng(areaSeed(o.seed, index));
    const AreaFamily family = o.families[index % o.families.size()];
    int shortfalls = 0;
    for (int attempt = 0; attempt < 20; ++attempt) {
        Outline out = outline(family, rng);
        const double rotation = rng.chance(1.0 / 3.0) ? 0.0 : rng.uniform(0.0, 180.0);
        const double target = rng.uniform(o.minAreaM2, o.maxAreaM2);
        out.ring = centred(placed(out.ring, std::sqrt(target / std::fabs(geo::signedArea(out.ring))), rotation, {0, 0}));
        const geo::Polygon area{out.ring, {}};
        const geo::MultiPolygon inner = geo::buffer(area, -kBoundaryClearanceM);
        const geo::Box box = geo::bounds(area);
        const double areaM2 = geo::area(area);

        const int wanted = rng.integer(o.minZones, o.maxZones);
        std::vector<geo::Polygon> zones;
        std::vector<geo::Box> zoneBoxes;
        std::vector<std::string> kinds;
        double zoneM2 = 0;
        int tries = 0;
        while (static_cast<int>(zones.size()) < wanted && tries < 40 * kAttemptsPerGroup) {
            const int remaining = wanted - static_cast<int>(zones.size());
            // Zones shrink while they do not fit, so that the wanted number is always reached.
            const double size = std::max(0.3, 1.0 - (tries % kAttemptsPerGroup) / static_cast<double>(kAttemptsPerGroup));
            ++tries;
            const ZoneGroup g = centredGroup(zoneGroup(rng, remaining, o.marginM, size));
            const geo::Vec2 at(rng.uniform(box.min.x(), box.max.x()), rng.uniform(box.min.y(), box.max.y()));
            const double rot = rng.uniform(0.0, 360.0);
            std::vector<geo::Polygon> parts;
            double partsM2 = 0;
            bool fits = true;
            for (const auto& r : g.rings) {
                geo::Polygon p{placed(r, 1.0, rot, at), {}};
                if (geo::signedArea(p.outer) < 0)
                    std::reverse(p.outer.begin(), p.outer.end());
                const geo::Box pb = geo::bounds(p);
                // Cheap tests first: the bounding box, every vertex, then the exact difference.
                const bool verticesIn = box.contains(pb.min) && box.contains(pb.max) &&
                                        std::all_of(p.outer.begin(), p.outer.end(),
                                                    [&](const geo::Vec2& v) { return geo::contains(inner, v); });
                if (!verticesIn || geo::area(geo::difference(p, inner)) > 1e-9) {
                    fits = false;
                    break;
                }
                const geo::MultiPolygon grown = geo::buffer(p, kZoneClearanceM - 1e-6);
                const geo::Box gb = geo::bounds(grown);
                for (std::size_t k = 0; k < zones.size() && fits; ++k)
                    if (gb.intersects(zoneBoxes[k]) && !geo::intersection(grown, zones[k]).empty())
                        fits = false;
                if (!fits)
                    break;
                partsM2 += geo::area(p);
                parts.push_back(std::move(p));
            }
            if (!fits || zoneM2 + partsM2 > kMaxZoneShare * areaM2)
                continue;
            zoneM2 += partsM2;
            for (auto& p : parts) {
                zoneBoxes.push_back(geo::bounds(p));
                zones.push_back(std::move(p));
                kinds.push_back(g.kind);
            }
            tries = 0;
        }

        GeneratedArea ga;
        ga.shape = out.shape;
        ga.areaM2 = areaM2;
        ga.zoneKinds = kinds;
        char name[96];
        std::snprintf(name, sizeof name, "gen-s%llu-%03zu-%s", static_cast<unsigned long long>(o.seed), index + 1,
                      out.shape.c_str());
        ga.area.name = name;
        ga.area.area = toGeo(frame, area.outer);
        for (const auto& z : zones)
            ga.area.noFly.push_back(toGeo(frame, z.outer));
        if (static_cast<int>(zones.size()) >= o.minZones && acceptable(ga.area, frame))
            return ga;
        if (static_cast<int>(zones.size()) < o.minZones && ++shortfalls >= 3)
            break; // the zones do not fit: more outlines will not help
    }
    return makeError(ErrorCode::InvalidInput,
                     "area generator: area " + std::to_string(index + 1) + " (seed " + std::to_string(o.seed) +
                         ") cannot hold " + std::to_string(o.minZones) +
                         " no-fly zones or more within a quarter of its surface; ask for fewer zones or larger areas");
}

CPLJSONObject polygonFeature(const geo::GeoPolygon& p) {
    CPLJSONArray ring;
    geo::GeoRing closed = p.outer;
    closed.push_back(p.outer.front());
    for (const auto& q : closed) {
        CPLJSONArray pos;
        pos.Add(q.lon);
        pos.Add(q.lat);
        ring.Add(pos);
    }
    CPLJSONArray rings;
    rings.Add(ring);
    CPLJSONObject geom;
    geom.Add("type", "Polygon");
    geom.Add("coordinates", rings);
    CPLJSONObject f;
    f.Add("type", "Feature");
    f.Add("geometry", geom);
    return f;
}

} // namespace

const char* areaFamilyName(AreaFamily f) {
    switch (f) {
    case AreaFamily::Rectangle:
        return "rectangle";
    case AreaFamily::Rectilinear:
        return "rectilinear";
    case AreaFamily::Polygonal:
        return "polygonal";
    }
    return "rectangle";
}

std::vector<AreaFamily> allAreaFamilies() {
    return {AreaFamily::Rectangle, AreaFamily::Rectilinear, AreaFamily::Polygonal};
}

Result<std::vector<GeneratedArea>> generateAreas(const AreaGeneratorOptions& o) {
    if (o.count < 1)
        return makeError(ErrorCode::InvalidInput, "area generator: the number of areas must be at least 1");
    if (!(o.minAreaM2 >= 1000.0) || !(o.maxAreaM2 >= o.minAreaM2) || !std::isfinite(o.maxAreaM2) ||
        o.maxAreaM2 > 1e8)
        return makeError(
            ErrorCode::InvalidInput,
            "area generator: the area range must lie between 1,000 m² and 100 km², smallest first");
    if (o.minZones < 0 || o.maxZones < o.minZones || o.maxZones > 200)
        return makeError(ErrorCode::InvalidInput,
                         "area generator: the zone count range must lie between 0 and 200, smallest first");
    if (o.families.empty())
        return makeError(ErrorCode::InvalidInput, "area generator: give at least one family of outlines");
    if (!(o.marginM > 0) || o.marginM > 50)
        return makeError(ErrorCode::InvalidInput, "area generator: the margin must be more than 0 m and at most 50 m");
    // The smallest zone drawn (a rectangle of 8 m sides shrunk to 30 %) against a quarter of the
    // smallest area: beyond that the zones can never fit.
    if (o.minZones * (2.4 * 2.4) > kMaxZoneShare * o.minAreaM2)
        return makeError(ErrorCode::InvalidInput, "area generator: " + std::to_string(o.minZones) +
                                                      " no-fly zones cannot fit in a quarter of the smallest area; "
                                                      "ask for fewer zones or larger areas");
    auto frame = geo::LocalFrame::create(o.origin);
    if (!frame)
        return frame.error();
    std::vector<GeneratedArea> out;
    out.reserve(static_cast<std::size_t>(o.count));
    for (int i = 0; i < o.count; ++i) {
        auto a = generateOne(o, static_cast<std::size_t>(i), *frame);
        if (!a)
            return a.error();
        out.push_back(std::move(a).value());
    }
    return out;
}

std::string generatedAreaGeoJson(const GeneratedArea& a) {
    CPLJSONObject root;
    root.Add("type", "FeatureCollection");
    root.Add("name", a.area.name);
    CPLJSONArray features;
    CPLJSONObject area = polygonFeature(a.area.area);
    CPLJSONObject props;
    props.Add("role", "area");
    props.Add("name", a.area.name);
    props.Add("shape", a.shape);
    props.Add("area_m2", std::round(a.areaM2));
    props.Add("zones", static_cast<int>(a.area.noFly.size()));
    area.Add("properties", props);
    features.Add(area);
    for (std::size_t i = 0; i < a.area.noFly.size(); ++i) {
        CPLJSONObject z = polygonFeature(a.area.noFly[i]);
        CPLJSONObject zp;
        zp.Add("role", "nofly");
        zp.Add("name", "zone " + std::to_string(i + 1));
        zp.Add("kind", i < a.zoneKinds.size() ? a.zoneKinds[i] : std::string("zone"));
        z.Add("properties", zp);
        features.Add(z);
    }
    root.Add("features", features);
    return root.Format(CPLJSONObject::PrettyFormat::Pretty) + "\n";
}

std::string generatedAreaFileName(const GeneratedArea& a) { return a.area.name + ".geojson"; }

} // namespace pf::plan
