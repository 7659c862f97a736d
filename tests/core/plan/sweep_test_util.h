// Test helpers for the sweep planner: seeded areas with no-fly zones like the unseen sites of the
// issues, a plain one-direction boustrophedon yardstick that ignores the zones, the checks every sweep
// plan must pass, and a GeoJSON dump for looking at plans.
#pragma once

#include "core/geo/polygon_ops.h"
#include "core/plan/coverage_check.h"
#include "core/plan/flight_time.h"
#include "core/plan/sweep/sweep_planner.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace pf::plan::sweeptest {

using geo::Vec2;

// The camera: 60 x 45 degrees at 30 m, 20 % overlap both ways.
struct Camera {
    double realAcross = 2 * 30 * std::tan(30 * M_PI / 180);
    double realAlong = 2 * 30 * std::tan(22.5 * M_PI / 180);
    double track() const { return 0.8 * realAcross; }
    double photo() const { return 0.8 * realAlong; }
};

struct Area {
    std::string name;
    geo::MultiPolygon region;
    std::vector<geo::Polygon> zones;
};

inline geo::Polygon rect(double x0, double y0, double x1, double y1) {
    return geo::Polygon{{Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)}, {}};
}

inline geo::Polygon rotated(const geo::Polygon& p, const Vec2& c, double deg) {
    const double a = deg * M_PI / 180, cs = std::cos(a), sn = std::sin(a);
    geo::Polygon out;
    for (const auto& q : p.outer) {
        const Vec2 d = q - c;
        out.outer.emplace_back(c.x() + cs * d.x() - sn * d.y(), c.y() + sn * d.x() + cs * d.y());
    }
    return out;
}

inline geo::Polygon circle(const Vec2& c, double r, int n = 24) {
    geo::Polygon p;
    for (int k = 0; k < n; ++k)
        p.outer.push_back(c + r * Vec2(std::cos(2 * M_PI * k / n), std::sin(2 * M_PI * k / n)));
    return p;
}

// A seeded area of 0.1-0.25 km2: a rectangle, a rectilinear site (L, U, T, staircase) or a polygon
// (convex or star-shaped), with `zones` no-fly zones: rectangles (8-50 m, any rotation), circles
// (6-25 m), U shapes whose opening the margin closes, close pairs (2-10 m apart) and pockets (four
// bars around a square), at least 2 m apart otherwise, all inside the area.
inline Area generateArea(unsigned seed, int zones) {
    std::mt19937 rng(seed * 7919u + 17u);
    auto uni = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
    Area a;
    const double target = uni(100'000, 250'000);
    const int family = static_cast<int>(seed % 3);
    geo::Polygon outline;
    if (family == 0) {
        const double aspect = uni(1, 3), w = std::sqrt(target * aspect), h = target / w;
        outline = rect(-w / 2, -h / 2, w / 2, h / 2);
        a.name = "rectangle";
    } else if (family == 1) {
        const int kind = pick(4);
        const double w = std::sqrt(target * uni(1.2, 2.0)), h = w * uni(0.6, 1.0);
        const double x0 = -w / 2, x1 = w / 2, y0 = -h / 2, y1 = h / 2;
        const double cx = uni(0.3, 0.6), cy = uni(0.3, 0.6);
        if (kind == 0) { // L
            outline.outer = {Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y0 + cy * h), Vec2(x0 + cx * w, y0 + cy * h),
                             Vec2(x0 + cx * w, y1), Vec2(x0, y1)};
            a.name = "L";
        } else if (kind == 1) { // U
            const double l = x0 + cx * 0.6 * w, r = x1 - cx * 0.5 * w;
            outline.outer = {Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(r, y1), Vec2(r, y0 + cy * h),
                             Vec2(l, y0 + cy * h), Vec2(l, y1), Vec2(x0, y1)};
            a.name = "U";
        } else if (kind == 2) { // T
            const double l = x0 + cx * 0.5 * w, r = x1 - cx * 0.5 * w, m = y1 - cy * 0.8 * h;
            outline.outer = {Vec2(l, y0), Vec2(r, y0), Vec2(r, m), Vec2(x1, m), Vec2(x1, y1), Vec2(x0, y1), Vec2(x0, m),
                             Vec2(l, m)};
            a.name = "T";
        } else { // staircase
            const int steps = 3 + pick(3);
            outline.outer.push_back(Vec2(x0, y0));
            outline.outer.push_back(Vec2(x1, y0));
            for (int k = 0; k < steps; ++k) {
                const double x = x1 - k * w / steps, y = y0 + (k + 1) * h / steps;
                outline.outer.push_back(Vec2(x, y));
                outline.outer.push_back(Vec2(x - w / steps, y));
            }
            outline.outer.pop_back();
            outline.outer.push_back(Vec2(x0, y1));
            a.name = "staircase";
        }
        // scale to the target area
        const double f = std::sqrt(target / geo::area(outline));
        for (auto& p : outline.outer)
            p *= f;
    } else {
        const bool star = pick(2) == 1;
        const int n = star ? 7 + pick(6) : 5 + pick(6);
        std::vector<double> ang;
        for (int k = 0; k < n; ++k)
            ang.push_back(uni(0, 2 * M_PI));
        std::sort(ang.begin(), ang.end());
        for (int k = 0; k < n; ++k) {
            const double r = star && k % 2 ? uni(0.55, 0.8) : uni(0.9, 1.1);
            outline.outer.push_back(Vec2(r * std::cos(ang[static_cast<std::size_t>(k)]), r * std::sin(ang[static_cast<std::size_t>(k)])));
        }
        if (!star) { // convex hull of the points (gift wrapping) keeps it convex
            auto pts = outline.outer;
            std::sort(pts.begin(), pts.end(), [](const Vec2& p, const Vec2& q) { return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y()); });
            std::vector<Vec2> hull;
            for (int pass = 0; pass < 2; ++pass) {
                const std::size_t base = hull.size();
                for (const auto& p : pts) {
                    while (hull.size() >= base + 2) {
                        const Vec2 u = hull[hull.size() - 1] - hull[hull.size() - 2], v = p - hull[hull.size() - 1];
                        if (u.x() * v.y() - u.y() * v.x() > 0)
                            break;
                        hull.pop_back();
                    }
                    hull.push_back(p);
                }
                hull.pop_back();
                std::reverse(pts.begin(), pts.end());
            }
            outline.outer = hull;
        }
        const double f = std::sqrt(target / geo::area(outline));
        for (auto& p : outline.outer)
            p *= f;
        a.name = star ? "concave" : "convex";
    }
    a.region = {outline};
    // Zones: kinds drawn in turn, kept when inside the area (2 m in) and 2 m from the others.
    const geo::MultiPolygon inner = geo::buffer(outline, -2.0);
    geo::MultiPolygon placed;
    double zoneArea = 0;
    const geo::Box b = geo::bounds(outline);
    int attempts = 0;
    while (static_cast<int>(a.zones.size()) < zones && attempts++ < 4000) {
        const Vec2 c(uni(b.min.x(), b.max.x()), uni(b.min.y(), b.max.y()));
        const double rot = uni(0, 180);
        std::vector<geo::Polygon> group;
        const int kind = pick(10);
        if (kind < 4) {
            group.push_back(rotated(rect(c.x() - uni(4, 25), c.y() - uni(4, 25), c.x() + uni(4, 25), c.y() + uni(4, 25)), c, rot));
        } else if (kind < 7) {
            group.push_back(circle(c, uni(6, 25)));
        } else if (kind == 7) { // U: opening narrower than two margins
            const double w = uni(20, 40), h = uni(20, 40), t = uni(4, 8), gap = uni(3, 8);
            const double inW = std::max(gap, w - 2 * t);
            geo::Polygon u;
            u.outer = {Vec2(0, 0), Vec2(w, 0), Vec2(w, h), Vec2(w - t, h), Vec2(w - t, t), Vec2(t, t), Vec2(t, h), Vec2(0, h)};
            (void)inW;
            // close the U's mouth to `gap` with two lugs at its top
            geo::Polygon lugL = rect(t, h - t, (w - gap) / 2, h), lugR = rect((w + gap) / 2, h - t, w - t, h);
            auto un = geo::unite({u, lugL, lugR});
            if (un.size() != 1)
                continue;
            geo::Polygon z = un.front();
            for (auto& p : z.outer)
                p += c - Vec2(w / 2, h / 2);
            group.push_back(rotated(z, c, rot));
        } else if (kind == 8) { // a close pair
            const double w1 = uni(10, 30), h1 = uni(10, 30), gap = uni(2, 10);
            group.push_back(rotated(rect(c.x() - w1, c.y() - h1 / 2, c.x(), c.y() + h1 / 2), c, rot));
            group.push_back(rotated(rect(c.x() + gap, c.y() - h1 / 2, c.x() + gap + uni(10, 30), c.y() + h1 / 2), c, rot));
        } else { // a pocket: four bars around a square, gaps at the corners
            const double side = uni(12, 30), t = uni(4, 7), g = uni(2, 8.5), h = side / 2;
            group.push_back(rotated(rect(c.x() - h + g, c.y() - h - t, c.x() + h - g, c.y() - h), c, rot));
            group.push_back(rotated(rect(c.x() - h + g, c.y() + h, c.x() + h - g, c.y() + h + t), c, rot));
            group.push_back(rotated(rect(c.x() - h - t, c.y() - h + g, c.x() - h, c.y() + h - g), c, rot));
            group.push_back(rotated(rect(c.x() + h, c.y() - h + g, c.x() + h + t, c.y() + h - g), c, rot));
        }
        bool ok = true;
        double ga = 0;
        for (const auto& z : group) {
            ga += geo::area(z);
            for (const auto& q : z.outer)
                if (!geo::contains(inner, q))
                    ok = false;
        }
        if (!ok || zoneArea + ga > 0.25 * geo::area(outline))
            continue;
        if (!placed.empty()) {
            geo::MultiPolygon g(group.begin(), group.end());
            const geo::MultiPolygon near = geo::buffer(g, 2.0);
            bool clash = false;
            for (const auto& q : geo::unite(placed))
                clash = clash || geo::area(geo::intersection(near, q)) > 0;
            if (clash)
                continue;
        }
        for (const auto& z : group) {
            a.zones.push_back(z);
            placed.push_back(z);
        }
        zoneArea += ga;
    }
    char buf[64];
    std::snprintf(buf, sizeof buf, "%s-%u-z%zu", a.name.c_str(), seed, a.zones.size());
    a.name = buf;
    return a;
}

// The yardstick: what a ground station's Survey flies over the whole area, ignoring the zones: parallel
// transects at one angle, centred, each from the first to the last crossing of the outline and 10 m
// beyond at both ends, boustrophedon order, floor(length / spacing) + 1 photos; the fastest angle of
// every 2 degrees and every edge direction.
struct Yardstick {
    double timeS = 0;
    int photos = 0;
    int photosOutsideZones = 0;
    double angleDeg = 0;
};

inline Yardstick yardstick(const Area& area, const Camera& cam, const FlightTimeModel& model) {
    Yardstick best;
    best.timeS = 1e300;
    std::vector<double> angles;
    for (double a = 0; a < 180; a += 2)
        angles.push_back(a);
    for (const auto& r : area.region)
        for (std::size_t i = 0; i < r.outer.size(); ++i) {
            const Vec2 d = r.outer[(i + 1) % r.outer.size()] - r.outer[i];
            angles.push_back(std::atan2(d.y(), d.x()) * 180 / M_PI);
        }
    const double s = cam.track(), p = cam.photo();
    for (double deg : angles) {
        const double t = deg * M_PI / 180;
        const Vec2 u(std::cos(t), std::sin(t)), n(-std::sin(t), std::cos(t));
        double lo = 1e300, hi = -1e300;
        for (const auto& r : area.region)
            for (const auto& q : r.outer) {
                lo = std::min(lo, q.dot(n));
                hi = std::max(hi, q.dot(n));
            }
        const int lines = std::max(1, static_cast<int>(std::ceil((hi - lo) / s - 1e-9)));
        const double off = lo + 0.5 * ((hi - lo) - (lines - 1) * s);
        std::vector<Vec2> path;
        int photos = 0, outside = 0;
        bool flip = false;
        for (int k = 0; k < lines; ++k) {
            const double c = off + k * s;
            double a0 = 1e300, a1 = -1e300;
            for (const auto& r : area.region)
                for (std::size_t i = 0; i < r.outer.size(); ++i) {
                    const Vec2 &A = r.outer[i], &B = r.outer[(i + 1) % r.outer.size()];
                    const double da = A.dot(n) - c, db = B.dot(n) - c;
                    if ((da > 0) == (db > 0))
                        continue;
                    const Vec2 X = A + (da / (da - db)) * (B - A);
                    a0 = std::min(a0, X.dot(u));
                    a1 = std::max(a1, X.dot(u));
                }
            if (a0 > a1)
                continue;
            Vec2 s0 = a0 * u + c * n, s1 = a1 * u + c * n;
            if (flip)
                std::swap(s0, s1);
            flip = !flip;
            const Vec2 dir = (s1 - s0).norm() > 0 ? Vec2((s1 - s0).normalized()) : u;
            path.push_back(s0 - 10 * dir);
            path.push_back(s1 + 10 * dir);
            const int np = static_cast<int>(std::floor((s1 - s0).norm() / p)) + 1;
            photos += np;
            for (int i = 0; i < np; ++i) {
                const Vec2 q = s0 + (i * p) * dir;
                bool in = false;
                for (const auto& z : area.zones)
                    in = in || geo::contains(z, q);
                outside += in ? 0 : 1;
            }
        }
        const double time = flightTime(path, model).totalS;
        if (time < best.timeS) {
            best.timeS = time;
            best.photos = photos;
            best.photosOutsideZones = outside;
            best.angleDeg = deg;
        }
    }
    return best;
}

inline SweepOptions options(const Camera& cam) {
    SweepOptions o;
    o.trackSpacingM = cam.track();
    o.photoSpacingM = cam.photo();
    o.realAcrossM = cam.realAcross;
    o.realAlongM = cam.realAlong;
    o.safetyMarginM = 5.0;
    return o;
}

// The admissible ground: the area minus the un-buffered zones.
inline geo::MultiPolygon admissible(const Area& a) {
    geo::MultiPolygon z(a.zones.begin(), a.zones.end());
    return a.zones.empty() ? a.region : geo::difference(a.region, z);
}

inline int photoCount(const SweepPlan& plan) {
    int n = 0;
    for (const auto& l : plan.lanes)
        n += static_cast<int>(l.photos.size());
    return n;
}

inline double coverage(const Area& a, const SweepPlan& plan, const Camera& cam, double* uncoveredM2 = nullptr,
                       std::vector<UncoveredPatch>* patches = nullptr) {
    std::vector<PhotoFootprint> fps;
    for (const auto& l : plan.lanes)
        for (const auto& p : l.photos)
            fps.push_back(PhotoFootprint{p, l.headingDeg, cam.realAcross, cam.realAlong});
    CoverageCheckOptions co;
    co.resolutionM = 0.5;
    auto r = checkCoverage(admissible(a), fps, co);
    if (!r.ok())
        return -1;
    if (uncoveredM2)
        *uncoveredM2 = r->uncoveredAreaM2;
    if (patches)
        *patches = r->patches;
    return r->coveredFraction;
}

// A GeoJSON FeatureCollection (local metres) with the area, the zones, the cells, the lanes and the
// flown path, for plotting.
inline void writeGeoJson(const std::string& path, const Area& a, const SweepPlan& plan, const SweepOptions& o,
                         const std::vector<UncoveredPatch>& holes = {}) {
    std::ofstream f(path);
    auto ring = [&](const geo::Ring& r) {
        std::string s = "[";
        for (std::size_t i = 0; i <= r.size(); ++i) {
            const Vec2& p = r[i % r.size()];
            char b[64];
            std::snprintf(b, sizeof b, "%s[%.2f,%.2f]", i ? "," : "", p.x(), p.y());
            s += b;
        }
        return s + "]";
    };
    auto line = [&](const std::vector<Vec2>& pts) {
        std::string s = "[";
        for (std::size_t i = 0; i < pts.size(); ++i) {
            char b[64];
            std::snprintf(b, sizeof b, "%s[%.2f,%.2f]", i ? "," : "", pts[i].x(), pts[i].y());
            s += b;
        }
        return s + "]";
    };
    std::vector<std::string> feats;
    auto poly = [&](const geo::Polygon& p, const char* role) {
        std::string s = "{\"type\":\"Feature\",\"properties\":{\"role\":\"" + std::string(role) +
                        "\"},\"geometry\":{\"type\":\"Polygon\",\"coordinates\":[" + ring(p.outer);
        for (const auto& h : p.holes)
            s += "," + ring(h);
        feats.push_back(s + "]}}");
    };
    for (const auto& r : a.region)
        poly(r, "area");
    for (const auto& z : a.zones)
        poly(z, "zone");
    for (const auto& c : plan.cells)
        poly(c, "cell");
    for (const auto& h : holes)
        for (const auto& p : h.shape)
            poly(p, "hole");
    for (const auto& l : plan.lanes)
        feats.push_back("{\"type\":\"Feature\",\"properties\":{\"role\":\"photos\"},\"geometry\":{\"type\":\"MultiPoint\",\"coordinates\":" +
                        line(l.photos) + "}}");
    feats.push_back("{\"type\":\"Feature\",\"properties\":{\"role\":\"path\"},\"geometry\":{\"type\":\"LineString\",\"coordinates\":" +
                    line(sweepFlightPath(plan, o.home, o.landing)) + "}}");
    f << "{\"type\":\"FeatureCollection\",\"features\":[";
    for (std::size_t i = 0; i < feats.size(); ++i)
        f << (i ? ",\n" : "\n") << feats[i];
    f << "]}\n";
}

} // namespace pf::plan::sweeptest
