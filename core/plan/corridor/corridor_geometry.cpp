#include "core/plan/corridor/corridor_geometry.h"

#include "core/geo/polygon_ops.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace pf::plan {

namespace {

using geo::Vec2;

constexpr double kSamePointM = 0.01;
constexpr double kStraightRad = 0.01 * M_PI / 180.0;
// Beyond this turn a lane on the inside of the bend is joined by a bevel, not a mitre (the mitre
// point lies at offset / cos(turn / 2) from the vertex: 3.9 times the offset at 150 degrees).
constexpr double kMaxMitreRad = 150.0 * M_PI / 180.0;

double cross(const Vec2& a, const Vec2& b) {
    return a.x() * b.y() - a.y() * b.x();
}
Vec2 leftNormal(const Vec2& u) {
    return Vec2(-u.y(), u.x());
}
Vec2 rotate(const Vec2& v, double a) {
    const double c = std::cos(a), s = std::sin(a);
    return Vec2(c * v.x() - s * v.y(), s * v.x() + c * v.y());
}

// The signed angle from direction u to direction v, (-pi, pi].
double signedAngle(const Vec2& u, const Vec2& v) {
    return std::atan2(cross(u, v), u.dot(v));
}

// Where the lines p + t u and q + s v meet (nullopt when they are parallel).
std::optional<Vec2> meet(const Vec2& p, const Vec2& u, const Vec2& q, const Vec2& v) {
    const double d = cross(u, v);
    if (std::abs(d) < 1e-12)
        return std::nullopt;
    return p + (cross(q - p, v) / d) * u;
}

geo::Polygon rectangleAlong(const Vec2& a, const Vec2& b, double half) {
    const Vec2 n = half * leftNormal((b - a).normalized());
    return geo::Polygon{{a - n, b - n, b + n, a + n}, {}};
}

geo::Polygon disc(const Vec2& c, double r, int quadrantSegments) {
    const int n = 4 * std::max(1, quadrantSegments);
    geo::Polygon p;
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * M_PI * i / n;
        p.outer.push_back(c + r * Vec2(std::cos(a), std::sin(a)));
    }
    return p;
}

// The offset line of one segment of the centre line, and where its flown part starts and ends.
struct OffsetSegment {
    std::size_t index = 0; // the centre line's segment
    Vec2 origin{0, 0};     // its first point moved sideways
    Vec2 dir{0, 0};
    Vec2 start{0, 0}, end{0, 0};
};

// The points of the join between two consecutive kept segments a and c (c after a), and where a
// ends and c starts; `vertex` is the centre line's point the lane turns round.
std::vector<Vec2> join(OffsetSegment& a, OffsetSegment& c, const Vec2& vertex, double offset,
                       double tol) {
    const double turn = signedAngle(a.dir, c.dir);
    const Vec2 capA = vertex + offset * leftNormal(a.dir),
               capC = vertex + offset * leftNormal(c.dir);
    if (std::abs(turn) < kStraightRad || std::abs(offset) < 1e-9) {
        a.end = c.start = capC; // the vertex itself on the centre line
        return {capC};
    }
    if (offset * turn > 0) { // the inside of the bend
        const auto x = meet(a.origin, a.dir, c.origin, c.dir);
        if (x && std::abs(turn) <= kMaxMitreRad) {
            a.end = c.start = *x;
            return {*x};
        }
        a.end = capA;
        c.start = capC;
        return {capA, capC};
    }
    // The outside: straight legs tangent to the circle of radius |offset| round the vertex, each
    // turning by phi, whose corners lie at r / cos(phi / 2) <= r + tol from the vertex.
    const double r = std::abs(offset);
    const double phiMax = 2.0 * std::acos(r / (r + std::max(tol, 1e-3)));
    const int m = std::max(1, static_cast<int>(std::ceil(std::abs(turn) / phiMax - 1e-9)));
    const double phi = turn / m;
    const Vec2 w0 = (capA - vertex) / r;
    std::vector<Vec2> pts;
    for (int j = 1; j <= m; ++j)
        pts.push_back(vertex + (r / std::cos(0.5 * phi)) * rotate(w0, (j - 0.5) * phi));
    a.end = pts.front();
    c.start = pts.back();
    return pts;
}

} // namespace

Polyline cleanLine(const Polyline& line) {
    Polyline out;
    for (const auto& p : line)
        if (out.empty() || (p - out.back()).norm() >= kSamePointM)
            out.push_back(p);
    // Vertices the line runs straight through are no bends.
    for (std::size_t i = 1; i + 1 < out.size();) {
        if (std::abs(signedAngle(out[i] - out[i - 1], out[i + 1] - out[i])) < kStraightRad)
            out.erase(out.begin() + static_cast<std::ptrdiff_t>(i));
        else
            ++i;
    }
    return out;
}

std::vector<double> lineStations(const Polyline& line) {
    std::vector<double> s(line.size(), 0.0);
    for (std::size_t i = 1; i < line.size(); ++i)
        s[i] = s[i - 1] + (line[i] - line[i - 1]).norm();
    return s;
}

double lineLength(const Polyline& line) {
    return line.empty() ? 0.0 : lineStations(line).back();
}

double turnAt(const Polyline& line, std::size_t i) {
    if (i == 0 || i + 1 >= line.size())
        return 0.0;
    return signedAngle(line[i] - line[i - 1], line[i + 1] - line[i]);
}

geo::MultiPolygon corridorGround(const Polyline& raw, double widthM, int quadrantSegments) {
    const Polyline line = cleanLine(raw);
    if (line.size() < 2 || !(widthM > 0) || !std::isfinite(widthM))
        return {};
    const double half = 0.5 * widthM;
    geo::MultiPolygon parts;
    for (std::size_t i = 0; i + 1 < line.size(); ++i)
        parts.push_back(rectangleAlong(line[i], line[i + 1], half));
    for (std::size_t i = 1; i + 1 < line.size(); ++i)
        parts.push_back(disc(line[i], half, quadrantSegments));
    if (parts.size() == 1)
        return parts;
    return geo::unite(parts);
}

Vec2 pointAt(const Polyline& line, const std::vector<double>& st, double s, Vec2* dir) {
    if (line.size() < 2) {
        if (dir)
            *dir = Vec2(1, 0);
        return line.empty() ? Vec2(0, 0) : line.front();
    }
    const auto it = std::upper_bound(st.begin(), st.end(), s);
    std::size_t i = it == st.begin() ? 0 : static_cast<std::size_t>(it - st.begin()) - 1;
    i = std::min(i, line.size() - 2);
    const Vec2 d = line[i + 1] - line[i];
    const double len = st[i + 1] - st[i];
    if (dir)
        *dir = len > 0 ? Vec2(d / len) : Vec2(1, 0);
    const double t = len > 0 ? std::clamp((s - st[i]) / len, 0.0, 1.0) : 0.0;
    return line[i] + t * d;
}

Polyline subLine(const Polyline& line, double a, double b) {
    const std::vector<double> st = lineStations(line);
    Polyline out{pointAt(line, st, a)};
    for (std::size_t i = 1; i + 1 < line.size(); ++i)
        if (st[i] > a && st[i] < b)
            out.push_back(line[i]);
    out.push_back(pointAt(line, st, b));
    return out;
}

OffsetLine offsetLine(const Polyline& raw, double offset, double tol) {
    OffsetLine out;
    const Polyline line = cleanLine(raw);
    if (line.size() < 2)
        return out;
    const std::vector<double> st = lineStations(line);
    std::vector<OffsetSegment> segs;
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        OffsetSegment s;
        s.index = i;
        s.dir = (line[i + 1] - line[i]).normalized();
        s.origin = line[i] + offset * leftNormal(s.dir);
        s.start = s.origin;
        s.end = line[i + 1] + offset * leftNormal(s.dir);
        segs.push_back(s);
    }
    // Joins computed, then any segment they make run backwards dropped, until none does.
    std::vector<std::vector<Vec2>> joins;
    for (std::size_t guard = 0; guard <= line.size(); ++guard) {
        joins.clear();
        segs.front().start = segs.front().origin;
        segs.back().end = line[segs.back().index + 1] + offset * leftNormal(segs.back().dir);
        for (std::size_t k = 0; k + 1 < segs.size(); ++k)
            joins.push_back(join(segs[k], segs[k + 1], line[segs[k + 1].index], offset, tol));
        std::size_t worst = segs.size();
        double worstLen = -1e-6;
        for (std::size_t k = 0; k < segs.size() && segs.size() > 1; ++k) {
            const double len = (segs[k].end - segs[k].start).dot(segs[k].dir);
            if (len < worstLen) {
                worstLen = len;
                worst = k;
            }
        }
        if (worst == segs.size())
            break;
        segs.erase(segs.begin() + static_cast<std::ptrdiff_t>(worst));
    }
    out.points.push_back(segs.front().start);
    out.stations.push_back(st[segs.front().index]);
    for (std::size_t k = 0; k < joins.size(); ++k)
        for (const auto& p : joins[k]) {
            if ((p - out.points.back()).norm() < kSamePointM)
                continue;
            out.points.push_back(p);
            out.stations.push_back(st[segs[k + 1].index]);
        }
    if ((segs.back().end - out.points.back()).norm() >= kSamePointM || out.points.size() == 1) {
        out.points.push_back(segs.back().end);
        out.stations.push_back(st[segs.back().index + 1]);
    }
    return out;
}

int laneCount(double widthM, double trackSpacingM) {
    if (!(trackSpacingM > 0) || !(widthM > 0))
        return 1;
    return std::max(1, static_cast<int>(std::ceil(widthM / trackSpacingM - 1e-9)));
}

std::vector<double> laneOffsets(double widthM, double trackSpacingM, int count) {
    if (count <= 1)
        return {0.0};
    const double first = -0.5 * widthM + 0.5 * trackSpacingM;
    const double step = std::max(0.0, (widthM - trackSpacingM) / (count - 1));
    std::vector<double> out;
    for (int j = 0; j < count; ++j)
        out.push_back(first + j * step);
    return out;
}

} // namespace pf::plan
