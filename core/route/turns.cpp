// Dubins paths from the geometry of the turning circles: for CSC words the tangent between the
// start and end circles, for CCC words a third circle touching both.
#include "core/route/turns.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace pf::route {

namespace {

using geo::Vec2;

constexpr double kTwoPi = 2.0 * M_PI;
// An arc this close to a full turn is a rounding artefact of an empty one (a full circle ends where
// it began, so dropping it never changes where the path goes).
constexpr double kAngleEps = 1e-9;

double mod2pi(double a) {
    double r = std::fmod(a, kTwoPi);
    if (r < 0)
        r += kTwoPi;
    return r > kTwoPi - kAngleEps ? 0.0 : r;
}

double angleOf(const Vec2& v) {
    return std::atan2(v.y(), v.x());
}
Vec2 unit(double a) {
    return Vec2(std::cos(a), std::sin(a));
}

// Centres of the circles of radius r the pose turns on: left (counter-clockwise) and right.
Vec2 leftCentre(const Pose& p, double r) {
    return p.pos + r * Vec2(-std::sin(p.headingRad), std::cos(p.headingRad));
}
Vec2 rightCentre(const Pose& p, double r) {
    return p.pos + r * Vec2(std::sin(p.headingRad), -std::cos(p.headingRad));
}

// The direction of the line between two circle centres; when they coincide, the start heading (the
// straight between them is then empty and the arcs alone turn the pose).
double lineAngle(const Vec2& d, double fallback) {
    return d.squaredNorm() > 0 ? angleOf(d) : fallback;
}

using Segments = std::array<double, 3>;

// Same-side words: the straight is parallel to the line of centres.
Segments lsl(const Pose& a, const Pose& b, double r) {
    const Vec2 d = leftCentre(b, r) - leftCentre(a, r);
    const double psi = lineAngle(d, a.headingRad);
    return {mod2pi(psi - a.headingRad), d.norm(), mod2pi(b.headingRad - psi)};
}

Segments rsr(const Pose& a, const Pose& b, double r) {
    const Vec2 d = rightCentre(b, r) - rightCentre(a, r);
    const double psi = lineAngle(d, a.headingRad);
    return {mod2pi(a.headingRad - psi), d.norm(), mod2pi(psi - b.headingRad)};
}

// Crossing words: the straight is an inner tangent of length sqrt(D^2 - 4r^2). Leaving a left
// circle with heading psi at p = c0 + r(sin psi, -cos psi) and joining a right circle at q = c1 +
// r(-sin psi, cos psi), c1 - c0 is the straight along psi plus 2r to its right: psi = angle(c1 -
// c0) + atan2(2r, L).
std::optional<Segments> lsr(const Pose& a, const Pose& b, double r) {
    const Vec2 d = rightCentre(b, r) - leftCentre(a, r);
    const double dd = d.squaredNorm() - 4 * r * r;
    if (dd < 0)
        return std::nullopt;
    const double len = std::sqrt(dd);
    const double psi = lineAngle(d, a.headingRad) + std::atan2(2 * r, len);
    return Segments{mod2pi(psi - a.headingRad), len, mod2pi(psi - b.headingRad)};
}

// The mirror image: c1 - c0 is the straight plus 2r to its left.
std::optional<Segments> rsl(const Pose& a, const Pose& b, double r) {
    const Vec2 d = leftCentre(b, r) - rightCentre(a, r);
    const double dd = d.squaredNorm() - 4 * r * r;
    if (dd < 0)
        return std::nullopt;
    const double len = std::sqrt(dd);
    const double psi = lineAngle(d, a.headingRad) - std::atan2(2 * r, len);
    return Segments{mod2pi(a.headingRad - psi), len, mod2pi(b.headingRad - psi)};
}

// CCC words: a middle circle of radius r touching both end circles (its centre 2r from each), the
// touching points halfway between the centres. `firstLeft`: LRL (else RLR).
std::optional<Segments> ccc(const Pose& a, const Pose& b, double r, bool firstLeft) {
    if (!(r > 0))
        return std::nullopt;
    const Vec2 c0 = firstLeft ? leftCentre(a, r) : rightCentre(a, r);
    const Vec2 c1 = firstLeft ? leftCentre(b, r) : rightCentre(b, r);
    const Vec2 d = c1 - c0;
    const double dist = d.norm();
    if (dist > 4 * r)
        return std::nullopt;
    const double h = std::sqrt(std::max(0.0, 4 * r * r - dist * dist / 4));
    const Vec2 along = dist > 0 ? Vec2(d / dist) : unit(a.headingRad);
    const Vec2 perp(-along.y(), along.x());
    // The heading at a point of a circle: the radius turned a quarter forwards (left circles) or
    // back.
    const auto heading = [](const Vec2& point, const Vec2& centre, bool left) {
        return angleOf(point - centre) + (left ? M_PI / 2 : -M_PI / 2);
    };
    std::optional<Segments> best;
    for (const double side : {1.0, -1.0}) {
        const Vec2 c2 = (c0 + c1) / 2 + side * h * perp;
        const double psi1 = heading((c0 + c2) / 2, c0, firstLeft);
        const double psi2 = heading((c2 + c1) / 2, c2, !firstLeft);
        const Segments s = firstLeft ? Segments{mod2pi(psi1 - a.headingRad), mod2pi(psi1 - psi2),
                                                mod2pi(b.headingRad - psi2)}
                                     : Segments{mod2pi(a.headingRad - psi1), mod2pi(psi2 - psi1),
                                                mod2pi(psi2 - b.headingRad)};
        if (!best || s[0] + s[1] + s[2] < (*best)[0] + (*best)[1] + (*best)[2])
            best = s;
    }
    return best;
}

std::optional<Segments> segmentsOf(const Pose& a, const Pose& b, double r, DubinsWord w) {
    switch (w) {
    case DubinsWord::LSL:
        return lsl(a, b, r);
    case DubinsWord::RSR:
        return rsr(a, b, r);
    case DubinsWord::LSR:
        return lsr(a, b, r);
    case DubinsWord::RSL:
        return rsl(a, b, r);
    case DubinsWord::RLR:
        return ccc(a, b, r, false);
    case DubinsWord::LRL:
        return ccc(a, b, r, true);
    }
    return std::nullopt;
}

double lengthOf(const Segments& s, DubinsWord w, double r) {
    const bool ccc = w == DubinsWord::RLR || w == DubinsWord::LRL;
    return r * (s[0] + s[2]) + (ccc ? r * s[1] : s[1]);
}

// Moves `p` along one segment by `len` metres (an arc of radius r > 0; with r = 0 an arc turns on
// the spot by `turnRad`).
void advance(Pose& p, SegmentKind k, double len, double r, double turnRad) {
    if (k == SegmentKind::Straight) {
        p.pos += len * unit(p.headingRad);
        return;
    }
    const double sign = k == SegmentKind::Left ? 1.0 : -1.0;
    if (!(r > 0)) {
        p.headingRad += sign * turnRad;
        return;
    }
    const Vec2 c = k == SegmentKind::Left ? leftCentre(p, r) : rightCentre(p, r);
    p.headingRad += sign * len / r;
    p.pos = c + r * Vec2(sign * std::sin(p.headingRad), -sign * std::cos(p.headingRad));
}

} // namespace

double headingFromCompassDeg(double compassDeg) {
    return (90.0 - compassDeg) * M_PI / 180.0;
}

double compassFromHeadingRad(double headingRad) {
    double d = std::fmod(90.0 - headingRad * 180.0 / M_PI, 360.0);
    if (d < 0)
        d += 360.0;
    return d >= 360.0 ? 0.0 : d;
}

const char* dubinsWordName(DubinsWord w) {
    switch (w) {
    case DubinsWord::LSL:
        return "LSL";
    case DubinsWord::RSR:
        return "RSR";
    case DubinsWord::LSR:
        return "LSR";
    case DubinsWord::RSL:
        return "RSL";
    case DubinsWord::RLR:
        return "RLR";
    case DubinsWord::LRL:
        return "LRL";
    }
    return "?";
}

SegmentKind DubinsPath::kind(int i) const {
    static constexpr SegmentKind k[6][3] = {
        {SegmentKind::Left, SegmentKind::Straight, SegmentKind::Left},   // LSL
        {SegmentKind::Right, SegmentKind::Straight, SegmentKind::Right}, // RSR
        {SegmentKind::Left, SegmentKind::Straight, SegmentKind::Right},  // LSR
        {SegmentKind::Right, SegmentKind::Straight, SegmentKind::Left},  // RSL
        {SegmentKind::Right, SegmentKind::Left, SegmentKind::Right},     // RLR
        {SegmentKind::Left, SegmentKind::Right, SegmentKind::Left},      // LRL
    };
    return k[static_cast<int>(word)][i];
}

double DubinsPath::segmentLengthM(int i) const {
    return kind(i) == SegmentKind::Straight ? segment[static_cast<std::size_t>(i)]
                                            : radiusM * segment[static_cast<std::size_t>(i)];
}

Pose DubinsPath::poseAt(double s) const {
    Pose p = start;
    double left = std::clamp(s, 0.0, lengthM());
    for (int i = 0; i < 3; ++i) {
        const double len = segmentLengthM(i);
        if (left < len) {
            advance(p, kind(i), left, radiusM, 0.0);
            return p;
        }
        advance(p, kind(i), len, radiusM, segment[static_cast<std::size_t>(i)]);
        left -= len;
    }
    return p;
}

std::optional<DubinsPath> dubinsPath(const Pose& from, const Pose& to, double radiusM,
                                     DubinsWord word) {
    assert(radiusM >= 0);
    const auto s = segmentsOf(from, to, std::max(0.0, radiusM), word);
    if (!s)
        return std::nullopt;
    return DubinsPath{from, std::max(0.0, radiusM), word, *s};
}

DubinsPath shortestDubinsPath(const Pose& from, const Pose& to, double radiusM) {
    const double r = std::max(0.0, radiusM);
    DubinsPath best{from, r, DubinsWord::LSL, lsl(from, to, r)};
    double bestLen = best.lengthM();
    for (DubinsWord w : kDubinsWords) {
        const auto s = segmentsOf(from, to, r, w);
        if (s && lengthOf(*s, w, r) < bestLen) {
            best = DubinsPath{from, r, w, *s};
            bestLen = best.lengthM();
        }
    }
    return best;
}

double dubinsDistanceM(const Pose& from, const Pose& to, double radiusM) {
    const double r = std::max(0.0, radiusM);
    double best = std::numeric_limits<double>::infinity();
    for (DubinsWord w : kDubinsWords)
        if (const auto s = segmentsOf(from, to, r, w))
            best = std::min(best, lengthOf(*s, w, r));
    return best;
}

std::vector<Pose> samplePath(const DubinsPath& path, double stepM) {
    assert(stepM > 0);
    const double len = path.lengthM();
    const int n = std::max(1, static_cast<int>(std::ceil(len / stepM - 1e-9)));
    std::vector<Pose> out;
    out.reserve(static_cast<std::size_t>(n) + 1);
    for (int k = 0; k < n; ++k)
        out.push_back(path.poseAt(len * k / n));
    out.push_back(path.end());
    return out;
}

void appendSampledPoints(const DubinsPath& path, double stepM, std::vector<geo::Vec2>& out,
                         bool skipFirst) {
    const auto poses = samplePath(path, stepM);
    for (std::size_t i = skipFirst ? 1 : 0; i < poses.size(); ++i)
        out.push_back(poses[i].pos);
}

double maxCurvature(const std::vector<geo::Vec2>& polyline) {
    std::vector<Vec2> p;
    p.reserve(polyline.size());
    for (const auto& q : polyline)
        if (p.empty() || q != p.back())
            p.push_back(q);
    double best = 0.0;
    for (std::size_t i = 1; i + 1 < p.size(); ++i) {
        const Vec2 a = p[i] - p[i - 1], b = p[i + 1] - p[i], c = p[i + 1] - p[i - 1];
        const double cNorm = c.norm();
        if (cNorm == 0.0)
            return std::numeric_limits<double>::infinity(); // back along the same leg
        const double twiceArea = std::abs(a.x() * b.y() - a.y() * b.x());
        best = std::max(best, 2.0 * twiceArea / (a.norm() * b.norm() * cNorm));
    }
    return best;
}

namespace {

struct LaneGeometry {
    Pose runIn; // where the lane's straight begins, heading along it
    Vec2 end;
    double lengthM = 0.0; // run-in included
};

std::vector<LaneGeometry> laneGeometry(const std::vector<DirectedLane>& lanes, double runInM) {
    std::vector<LaneGeometry> out;
    for (const auto& l : lanes) {
        const Vec2 d = l.end - l.start;
        const double len = d.norm();
        if (len == 0.0)
            continue;
        const double heading = angleOf(d);
        out.push_back({Pose{l.start - std::max(0.0, runInM) * d / len, heading}, l.end,
                       len + std::max(0.0, runInM)});
    }
    return out;
}

} // namespace

PlaneLanesEstimate planeLanesEstimate(const std::vector<DirectedLane>& lanes, double radiusM,
                                      double runInM, const plan::FlightTimeModel& model) {
    PlaneLanesEstimate e;
    const auto g = laneGeometry(lanes, runInM);
    for (std::size_t i = 0; i < g.size(); ++i) {
        e.lanesM += g[i].lengthM;
        if (i > 0)
            e.connectionsM +=
                dubinsDistanceM(Pose{g[i - 1].end, g[i - 1].runIn.headingRad}, g[i].runIn, radiusM);
    }
    e.timeS = model.speedMps > 0 ? e.lengthM() / model.speedMps : 0.0;
    return e;
}

std::vector<geo::Vec2> planeLanesPath(const std::vector<DirectedLane>& lanes, double radiusM,
                                      double runInM, double stepM) {
    std::vector<Vec2> out;
    const auto g = laneGeometry(lanes, runInM);
    for (std::size_t i = 0; i < g.size(); ++i) {
        if (i == 0)
            out.push_back(g[i].runIn.pos);
        else
            appendSampledPoints(shortestDubinsPath(Pose{g[i - 1].end, g[i - 1].runIn.headingRad},
                                                   g[i].runIn, radiusM),
                                stepM, out, true);
        out.push_back(g[i].end);
    }
    return out;
}

} // namespace pf::route
