#include "core/plan/lawnmower_planner.h"

#include "core/geo/polygon_ops.h"
#include "core/job_scope.h"
#include "core/plan/coverage_check.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace pf::plan {

namespace {

constexpr double kPi = 3.14159265358979323846;
// The angle search's coverage check (LawnmowerOptions::searchCoverageResolutionM, by default a coarser
// raster than the final check: 1 m pixels against 0.5 m) at most this many of the fastest candidates.
constexpr std::size_t kMaxCoverageChecks = 40;
// Transects across the area (or photos along a transect) beyond which the search would take minutes.
constexpr double kMaxTransectsAcross = 20000.0;

// One transect along +u: where its line first enters and last leaves the area.
struct Transect {
    geo::Vec2 a{0, 0};
    geo::Vec2 b{0, 0};
};

std::vector<const geo::Ring*> ringsOf(const geo::MultiPolygon& area) {
    std::vector<const geo::Ring*> rings;
    for (const auto& p : area) {
        rings.push_back(&p.outer);
        for (const auto& h : p.holes)
            rings.push_back(&h);
    }
    return rings;
}

// The transects at `angleDeg`, in order across the area (increasing offset along the normal).
std::vector<Transect> transectsAt(const std::vector<const geo::Ring*>& rings, double angleDeg, double spacing) {
    const double t = angleDeg * kPi / 180.0;
    const geo::Vec2 u(std::cos(t), std::sin(t)), n(-std::sin(t), std::cos(t));
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto* r : rings)
        for (const auto& p : *r) {
            lo = std::min(lo, n.dot(p));
            hi = std::max(hi, n.dot(p));
        }
    if (!(hi >= lo))
        return {};
    const double width = hi - lo;
    // A tolerance keeps an area exactly k spacings wide at k transects despite rounding.
    const int count = std::max(1, static_cast<int>(std::ceil(width / spacing - 1e-9)));
    const double first = lo + 0.5 * (width - (count - 1) * spacing);
    std::vector<Transect> out;
    out.reserve(static_cast<std::size_t>(count));
    for (int k = 0; k < count; ++k) {
        const double c = first + k * spacing;
        double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin;
        for (const auto* r : rings) {
            const std::size_t m = r->size();
            for (std::size_t i = 0; i < m; ++i) {
                const geo::Vec2& p = (*r)[i];
                const geo::Vec2& q = (*r)[(i + 1) % m];
                const double da = n.dot(p) - c, db = n.dot(q) - c;
                // Half-open rule: a vertex on the line belongs to the side above it, so a line through a
                // vertex is crossed once, not twice.
                if ((da > 0) == (db > 0))
                    continue;
                const geo::Vec2 x = p + (da / (da - db)) * (q - p);
                xmin = std::min(xmin, u.dot(x));
                xmax = std::max(xmax, u.dot(x));
            }
        }
        if (!(xmax > xmin))
            continue; // the line only touches the area
        out.push_back({c * n + xmin * u, c * n + xmax * u});
    }
    return out;
}

// The flown order of the transects for one of the four entry corners: `reverseOrder` starts with the
// last transect across, `reverseFirst` flies the first one against +u; then boustrophedon.
struct Entry {
    bool reverseOrder = false;
    bool reverseFirst = false;
};

std::vector<Transect> flownTransects(const std::vector<Transect>& ts, Entry e) {
    std::vector<Transect> out(ts);
    if (e.reverseOrder)
        std::reverse(out.begin(), out.end());
    for (std::size_t i = 0; i < out.size(); ++i)
        if (((i % 2) == 1) != e.reverseFirst)
            std::swap(out[i].a, out[i].b);
    return out;
}

std::vector<geo::Vec2> flightOf(const std::vector<Transect>& flown, double turnaroundM) {
    std::vector<geo::Vec2> pts;
    pts.reserve(flown.size() * 4);
    for (const auto& t : flown) {
        const geo::Vec2 d = t.b - t.a;
        const geo::Vec2 u = d / d.norm();
        if (turnaroundM > 0)
            pts.push_back(t.a - turnaroundM * u);
        pts.push_back(t.a);
        pts.push_back(t.b);
        if (turnaroundM > 0)
            pts.push_back(t.b + turnaroundM * u);
    }
    return pts;
}

std::vector<geo::Vec2> withHome(const std::vector<geo::Vec2>& flight, const std::optional<geo::Vec2>& home) {
    if (!home)
        return flight;
    std::vector<geo::Vec2> pts;
    pts.reserve(flight.size() + 2);
    pts.push_back(*home);
    pts.insert(pts.end(), flight.begin(), flight.end());
    pts.push_back(*home);
    return pts;
}

// A last trigger point closer than this to the exit is the exit photo itself.
constexpr double kSamePhotoM = 0.01;

// The Survey's trigger points: one at the entry (the trigger starts with an immediate photo), one every
// `spacing` while still on the transect, and one at the exit (the trigger stops with an immediate photo).
std::vector<geo::Vec2> triggerPoints(const geo::Vec2& a, const geo::Vec2& b, double spacing) {
    const geo::Vec2 d = b - a;
    const double len = d.norm();
    const int n = static_cast<int>(std::floor(len / spacing + 1e-9)) + 1;
    std::vector<geo::Vec2> out;
    out.reserve(static_cast<std::size_t>(n) + 1);
    for (int i = 0; i < n; ++i)
        out.push_back(a + (len > 0 ? i * spacing / len : 0.0) * d);
    if ((b - out.back()).norm() > kSamePhotoM)
        out.push_back(b);
    return out;
}

int photoCount(const std::vector<Transect>& ts, double spacing) {
    int n = 0;
    for (const auto& t : ts) {
        const double len = (t.b - t.a).norm();
        const double k = std::floor(len / spacing + 1e-9);
        n += static_cast<int>(k) + 1 + (len - k * spacing > kSamePhotoM ? 1 : 0);
    }
    return n;
}

double normalisedAngle(double deg) {
    double a = std::fmod(deg, 180.0);
    if (a < 0)
        a += 180.0;
    return a >= 180.0 ? 0.0 : a;
}

bool positiveFinite(double v) { return v > 0 && std::isfinite(v); }

Status checkOptions(const geo::MultiPolygon& area, const LawnmowerOptions& o) {
    if (!positiveFinite(o.trackSpacingM))
        return makeError(ErrorCode::InvalidInput, "lawnmower: the track spacing must be a positive number of metres");
    if (!positiveFinite(o.photoSpacingM))
        return makeError(ErrorCode::InvalidInput, "lawnmower: the trigger distance must be a positive number of metres");
    if (!(o.turnaroundM >= 0) || !std::isfinite(o.turnaroundM))
        return makeError(ErrorCode::InvalidInput, "lawnmower: the turnaround distance must be 0 m or more");
    if (!positiveFinite(o.time.speedMps) || !positiveFinite(o.time.turnRateDegS))
        return makeError(ErrorCode::InvalidInput, "lawnmower: the speed and the turn rate must be positive");
    if (o.angleDeg && !std::isfinite(*o.angleDeg))
        return makeError(ErrorCode::InvalidInput, "lawnmower: the transect angle must be a finite number of degrees");
    if (o.home && !(std::isfinite(o.home->x()) && std::isfinite(o.home->y())))
        return makeError(ErrorCode::InvalidInput, "lawnmower: the home point must be finite");
    if (!(geo::area(area) > 0))
        return makeError(ErrorCode::InvalidGeometry, "lawnmower: the area has no surface to photograph");
    const geo::Box box = geo::bounds(area);
    if ((box.max - box.min).norm() / std::min(o.trackSpacingM, o.photoSpacingM) > kMaxTransectsAcross)
        return makeError(ErrorCode::TooLarge, "lawnmower: the area is too large for the spacings (more than " +
                                                  std::to_string(static_cast<long long>(kMaxTransectsAcross)) +
                                                  " transects or photos along one)");
    return {};
}

// The transect angles searched: the one given, else every degree and every edge's direction.
std::vector<double> transectAngles(const std::vector<const geo::Ring*>& rings,
                                   const LawnmowerOptions& o) {
    std::vector<double> angles;
    if (o.angleDeg) {
        angles.push_back(normalisedAngle(*o.angleDeg));
        return angles;
    }
    for (int d = 0; d < 180; ++d)
        angles.push_back(d);
    for (const auto* r : rings)
        for (std::size_t i = 0; i < r->size(); ++i) {
            const geo::Vec2 e = (*r)[(i + 1) % r->size()] - (*r)[i];
            if (e.squaredNorm() > 0)
                angles.push_back(normalisedAngle(std::atan2(e.y(), e.x()) * 180.0 / kPi));
        }
    std::sort(angles.begin(), angles.end());
    angles.erase(
        std::unique(angles.begin(), angles.end(), [](double a, double b) { return b - a < 1e-9; }),
        angles.end());
    return angles;
}

// An angle and entry corner. Keys compare the time to the millisecond (a flight and its reverse
// take the same time), then fewer photos, then the entry nearest to home, then the order tried
// (the smaller angle).
struct Candidate {
    long long timeMs = 0;
    int photos = 0;
    long long entryUm = 0;
    int order = 0;
    std::size_t angleIndex = 0;
    Entry entry;
};

// Every angle's transects (perAngle) and every angle and entry corner, fastest first.
std::vector<Candidate> candidatesBySpeed(const std::vector<const geo::Ring*>& rings,
                                         const std::vector<double>& angles,
                                         const LawnmowerOptions& o,
                                         std::vector<std::vector<Transect>>& perAngle) {
    const double dwellS = std::max(0.0, o.time.photoDwellS);
    perAngle.assign(angles.size(), {});
    std::vector<Candidate> candidates;
    for (std::size_t ai = 0; ai < angles.size(); ++ai) {
        // Every angle's flight times take up to 0.3 s on a large area with a small footprint: a
        // cancel stops the search (planLawnmower then says so).
        if (stopRequested())
            break;
        perAngle[ai] = transectsAt(rings, angles[ai], o.trackSpacingM);
        const auto& ts = perAngle[ai];
        if (ts.empty())
            continue;
        const int photos = photoCount(ts, o.photoSpacingM);
        for (Entry e : {Entry{false, false}, Entry{false, true}, Entry{true, false}, Entry{true, true}}) {
            const auto flown = flownTransects(ts, e);
            const double t = flightTime(withHome(flightOf(flown, o.turnaroundM), o.home), o.time).totalS + photos * dwellS;
            const double entryDist = o.home ? (flown.front().a - *o.home).norm() : 0.0;
            candidates.push_back({std::llround(t * 1e3), photos, std::llround(entryDist * 1e6),
                                  static_cast<int>(candidates.size()), ai, e});
        }
    }
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
        return std::tie(a.timeMs, a.photos, a.entryUm, a.order) < std::tie(b.timeMs, b.photos, b.entryUm, b.order);
    });
    return candidates;
}

// The fastest candidate whose photos see enough of the area (minCoverage); the best-covering one if
// none does, among the first kMaxCoverageChecks checked. An angle whose fastest entry misses the
// target is not tried with its other entries (they fly the same transects; only the trigger points
// shift). `coverage`: the chosen one's covered fraction.
Result<std::size_t> fastestCovering(const geo::MultiPolygon& area,
                                    const std::vector<Candidate>& candidates,
                                    const std::vector<std::vector<Transect>>& perAngle,
                                    const LawnmowerOptions& o, double& coverage) {
    CoverageCheckOptions co;
    co.resolutionM = o.searchCoverageResolutionM;
    std::vector<char> failed(perAngle.size(), 0);
    std::size_t chosen = 0, checks = 0;
    for (std::size_t i = 0; i < candidates.size() && checks < kMaxCoverageChecks; ++i) {
        const Candidate& c = candidates[i];
        if (failed[c.angleIndex])
            continue;
        ++checks;
        std::vector<PhotoFootprint> fps;
        for (const auto& t : flownTransects(perAngle[c.angleIndex], c.entry)) {
            const double heading = makeLane(t.a, t.b, o.photoSpacingM).headingDeg;
            for (const auto& p : triggerPoints(t.a, t.b, o.photoSpacingM))
                fps.push_back({p, heading, o.footprintAcrossM, o.footprintAlongM});
        }
        auto cov = checkCoverage(area, fps, co);
        if (!cov)
            return makeError(cov.error().code, "lawnmower: " + cov.error().message);
        if (cov->coveredFraction > coverage + 1e-9) {
            coverage = cov->coveredFraction;
            chosen = i;
        }
        if (cov->coveredFraction >= o.minCoverage) {
            chosen = i;
            coverage = cov->coveredFraction;
            break;
        }
        failed[c.angleIndex] = 1;
    }
    return chosen;
}

} // namespace

std::vector<geo::Vec2> flownPath(const LawnmowerPlan& plan) {
    return withHome(plan.flight, plan.home);
}

Result<LawnmowerPlan> planLawnmower(const geo::MultiPolygon& area, const LawnmowerOptions& o) {
    if (Status st = checkOptions(area, o); !st)
        return st.error();
    const auto rings = ringsOf(area);
    const std::vector<double> angles = transectAngles(rings, o);
    std::vector<std::vector<Transect>> perAngle;
    const std::vector<Candidate> candidates = candidatesBySpeed(rings, angles, o, perAngle);
    if (stopRequested())
        return makeError(ErrorCode::Cancelled, "lawnmower: planning cancelled");
    if (candidates.empty())
        return makeError(ErrorCode::InvalidGeometry, "lawnmower: no transect crosses the area");
    std::size_t chosen = 0;
    double coverage = -1.0;
    if (!o.angleDeg && o.footprintAcrossM > 0 && o.footprintAlongM > 0) {
        auto c = fastestCovering(area, candidates, perAngle, o, coverage);
        if (!c)
            return c.error();
        chosen = *c;
    }
    const Candidate& best = candidates[chosen];

    LawnmowerPlan plan;
    plan.angleDeg = angles[best.angleIndex];
    plan.anglesTried = static_cast<int>(angles.size());
    plan.coverage = coverage;
    plan.home = o.home;
    const auto flown = flownTransects(perAngle[best.angleIndex], best.entry);
    plan.flight = flightOf(flown, o.turnaroundM);
    for (const auto& t : flown) {
        Lane lane = makeLane(t.a, t.b, o.photoSpacingM);
        lane.photos = triggerPoints(t.a, t.b, o.photoSpacingM);
        plan.photos += static_cast<int>(lane.photos.size());
        plan.transects.push_back(std::move(lane));
    }
    plan.time = flightTime(flownPath(plan), o.time);
    plan.time.totalS += plan.photos * std::max(0.0, o.time.photoDwellS);
    return plan;
}

NoFlyCrossings countNoFlyCrossings(const LawnmowerPlan& plan, const std::vector<geo::Polygon>& zones, double marginM) {
    NoFlyCrossings c;
    for (const auto& lane : plan.transects)
        for (const auto& p : lane.photos) {
            bool inside = false;
            for (const auto& z : zones)
                if (geo::contains(z, p)) {
                    inside = true;
                    break;
                }
            ++(inside ? c.photosInZones : c.photosOutsideZones);
        }
    c.legsCrossing = countNoFlyViolations({flownPath(plan)}, zones, std::max(0.0, marginM)).segments;
    return c;
}

} // namespace pf::plan
