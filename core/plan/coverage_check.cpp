#include "core/plan/coverage_check.h"

#include "core/job_scope.h"

#include "core/geo/no_fly_field.h"
#include "core/geo/polygon_ops.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>

namespace pf::plan {

namespace {

// A raster over a box: pixel (i, j) has its centre at min + ((i + 0.5) r, (j + 0.5) r).
struct Raster {
    geo::Vec2 min{0, 0};
    double r = 1.0;
    int nx = 0;
    int ny = 0;
    std::size_t index(int i, int j) const { return static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(i); }
};

// Calls f(j, i0, i1) for each row j and each run [i0, i1) of pixels whose centres lie inside the
// rings, by the even-odd rule (outer rings and holes together).
template <class F> void scanRings(const Raster& ras, const std::vector<const geo::Ring*>& rings, F f) {
    double ymin = std::numeric_limits<double>::infinity(), ymax = -ymin;
    for (const auto* ring : rings)
        for (const auto& p : *ring) {
            ymin = std::min(ymin, p.y());
            ymax = std::max(ymax, p.y());
        }
    if (!(ymin <= ymax))
        return;
    const int j0 = std::max(0, static_cast<int>(std::floor((ymin - ras.min.y()) / ras.r - 0.5)));
    const int j1 = std::min(ras.ny - 1, static_cast<int>(std::ceil((ymax - ras.min.y()) / ras.r - 0.5)));
    std::vector<double> xs;
    for (int j = j0; j <= j1; ++j) {
        const double y = ras.min.y() + (j + 0.5) * ras.r;
        xs.clear();
        for (const auto* ring : rings) {
            const std::size_t n = ring->size();
            for (std::size_t k = 0; k < n; ++k) {
                const geo::Vec2& a = (*ring)[k];
                const geo::Vec2& b = (*ring)[(k + 1) % n];
                if ((a.y() > y) != (b.y() > y))
                    xs.push_back(a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
            }
        }
        std::sort(xs.begin(), xs.end());
        for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
            // Pixels whose centre x is in [xs[k], xs[k+1]).
            const int i0 = std::max(0, static_cast<int>(std::ceil((xs[k] - ras.min.x()) / ras.r - 0.5)));
            const int i1 = std::min(ras.nx, static_cast<int>(std::ceil((xs[k + 1] - ras.min.x()) / ras.r - 0.5)));
            if (i0 < i1)
                f(j, i0, i1);
        }
    }
}

// The pixel loops below are most of a check's time (a plan's photos cover their ground several
// times over): they work on eight pixels at once, in a 64-bit word.
constexpr std::uint64_t kOnes = 0x0101010101010101ULL;

// Pixels 0 <-> 1 (inside the admissible area by the even-odd rule).
void flipInside(std::uint8_t* p, int n) {
    int i = 0;
    for (; i + 8 <= n; i += 8) {
        std::uint64_t w;
        std::memcpy(&w, p + i, 8);
        w ^= kOnes;
        std::memcpy(p + i, &w, 8);
    }
    for (; i < n; ++i)
        p[i] ^= 1;
}

// Pixels 1 (admissible, uncovered) become 2 (covered); 0 (outside) and 2 stay. The pixels hold 0, 1
// or 2 here: a byte is 1 when its bit 0 is set and its bit 1 is not, and adding that bit carries
// into no other byte.
void markCovered(std::uint8_t* p, int n) {
    int i = 0;
    for (; i + 8 <= n; i += 8) {
        std::uint64_t w;
        std::memcpy(&w, p + i, 8);
        w += w & ~(w >> 1) & kOnes;
        std::memcpy(p + i, &w, 8);
    }
    for (; i < n; ++i)
        p[i] = static_cast<std::uint8_t>(p[i] + (p[i] == 1));
}

Error cancelledCheck() {
    return makeError(ErrorCode::Cancelled, "checking the coverage: cancelled");
}

// The options and footprints checked; the shortest footprint side.
Result<double> checkInput(const std::vector<PhotoFootprint>& photos,
                          const CoverageCheckOptions& opt, const std::vector<geo::Ring>* outlines) {
    if (outlines && outlines->size() != photos.size())
        return makeError(ErrorCode::Internal, "the coverage check got outlines for some photos only");
    if (opt.resolutionM < 0 || !std::isfinite(opt.resolutionM))
        return makeError(ErrorCode::InvalidInput, "The coverage check resolution must be a positive number of metres.");
    if (opt.maxPixels < 16)
        return makeError(ErrorCode::InvalidInput, "The coverage check pixel budget is too small (at least 16).");
    double shortest = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < photos.size(); ++k) {
        if (!(photos[k].acrossM > 0) || !(photos[k].alongM > 0))
            return makeError(ErrorCode::InvalidInput,
                             "Photo " + std::to_string(k + 1) + " has a footprint side that is not positive.");
        shortest = std::min({shortest, photos[k].acrossM, photos[k].alongM});
    }
    return shortest;
}

// The raster over the area's box: the resolution asked (by default a twentieth of the shortest
// footprint side, at most 0.5 m), coarser while the pixels exceed the budget.
Raster rasterOver(const geo::Box& box, const CoverageCheckOptions& opt, double shortest) {
    const double w = box.max.x() - box.min.x(), h = box.max.y() - box.min.y();
    double r = opt.resolutionM > 0 ? opt.resolutionM : std::min(0.5, std::isfinite(shortest) ? shortest / 20.0 : 0.5);
    r = std::max(r, std::sqrt(w * h / static_cast<double>(opt.maxPixels)) * 1.0001);
    Raster ras;
    ras.min = box.min;
    ras.r = r;
    ras.nx = std::max(1, static_cast<int>(std::ceil(w / r)));
    ras.ny = std::max(1, static_cast<int>(std::ceil(h / r)));
    while (static_cast<std::size_t>(ras.nx) * static_cast<std::size_t>(ras.ny) > opt.maxPixels) {
        ras.r *= 1.05;
        ras.nx = std::max(1, static_cast<int>(std::ceil(w / ras.r)));
        ras.ny = std::max(1, static_cast<int>(std::ceil(h / ras.r)));
    }
    return ras;
}

// The admissible pixels set to 1 (even-odd across separate parts too). A big area's raster takes a
// while to fill: a cancel is looked at every 256 rows and the rest skipped.
Status fillAdmissible(const Raster& ras, const geo::MultiPolygon& admissible,
                      std::vector<std::uint8_t>& px) {
    std::vector<const geo::Ring*> rings;
    for (const auto& p : admissible) {
        rings.push_back(&p.outer);
        for (const auto& hole : p.holes)
            rings.push_back(&hole);
    }
    bool stopped = false;
    scanRings(ras, rings, [&](int j, int i0, int i1) {
        if ((j & 0xFF) == 0 && !stopped)
            stopped = stopRequested();
        if (stopped)
            return;
        flipInside(px.data() + ras.index(i0, j), i1 - i0);
    });
    if (stopped)
        return cancelledCheck();
    return {};
}

// Every photo's footprint (its outline when given) marks the admissible pixels it covers 2.
Status markPhotos(const Raster& ras, const std::vector<PhotoFootprint>& photos,
                  const std::vector<geo::Ring>* outlines, std::vector<std::uint8_t>& px) {
    for (std::size_t k = 0; k < photos.size(); ++k) {
        // A cancel is looked at every 1,024 photos (16,384 took up to 0.3 s on a loaded machine
        // with footprints of 3 m: the fleet cancel benchmark), the progress moved every 16,384.
        if ((k & 0x3FF) == 0 && stopRequested())
            return cancelledCheck();
        if ((k & 0x3FFF) == 0)
            reportProgress(static_cast<double>(k) / static_cast<double>(photos.size()),
                           "coverage check");
        const geo::Ring ring = outlines ? (*outlines)[k] : footprintRing(photos[k]);
        scanRings(ras, {&ring}, [&](int j, int i0, int i1) {
            markCovered(px.data() + ras.index(i0, j), i1 - i0);
        });
    }
    return {};
}

// The 4-connected components of uncovered admissible pixels (1), largest first. A pixel found is
// marked 3 in place (no second raster); the search is depth first on a stack.
Result<std::vector<std::vector<std::size_t>>> uncoveredComponents(const Raster& ras,
                                                                  std::vector<std::uint8_t>& px) {
    constexpr std::uint8_t kSeen = 3;
    std::vector<std::vector<std::size_t>> comps;
    std::vector<std::size_t> q;
    for (std::size_t s = 0; s < px.size(); ++s) {
        if ((s & 0xFFFFF) == 0 && stopRequested())
            return cancelledCheck();
        if (px[s] != 1)
            continue;
        std::vector<std::size_t> c;
        q.assign(1, s);
        px[s] = kSeen;
        while (!q.empty()) {
            const std::size_t p = q.back();
            q.pop_back();
            c.push_back(p);
            const int i = static_cast<int>(p % static_cast<std::size_t>(ras.nx));
            const int j = static_cast<int>(p / static_cast<std::size_t>(ras.nx));
            const int nb[4][2] = {{i + 1, j}, {i - 1, j}, {i, j + 1}, {i, j - 1}};
            for (const auto& n : nb) {
                if (n[0] < 0 || n[1] < 0 || n[0] >= ras.nx || n[1] >= ras.ny)
                    continue;
                const std::size_t k = ras.index(n[0], n[1]);
                if (px[k] == 1) {
                    px[k] = kSeen;
                    q.push_back(k);
                }
            }
        }
        comps.push_back(std::move(c));
    }
    std::stable_sort(comps.begin(), comps.end(),
                     [](const auto& a, const auto& b) { return a.size() > b.size(); });
    return comps;
}

// A patch from its pixels: area, centroid, the box of the pixels' edges, the mask and (with
// patchShapes) its outline, from the runs of pixels along each row.
UncoveredPatch patchOf(const Raster& ras, std::vector<std::size_t>& pixels, bool shapes) {
    std::sort(pixels.begin(), pixels.end());
    UncoveredPatch patch;
    const double pixelArea = ras.r * ras.r;
    patch.areaM2 = static_cast<double>(pixels.size()) * pixelArea;
    geo::Vec2 sum(0, 0);
    geo::MultiPolygon rects;
    int iLo = ras.nx, iHi = -1, jLo = ras.ny, jHi = -1;
    for (std::size_t a = 0; a < pixels.size();) {
        std::size_t b = a;
        while (b + 1 < pixels.size() && pixels[b + 1] == pixels[b] + 1 &&
               pixels[b + 1] % static_cast<std::size_t>(ras.nx) != 0)
            ++b;
        const int i0 = static_cast<int>(pixels[a] % static_cast<std::size_t>(ras.nx));
        const int i1 = static_cast<int>(pixels[b] % static_cast<std::size_t>(ras.nx)) + 1;
        const int j = static_cast<int>(pixels[a] / static_cast<std::size_t>(ras.nx));
        const double x0 = ras.min.x() + i0 * ras.r, x1 = ras.min.x() + i1 * ras.r;
        const double y0 = ras.min.y() + j * ras.r, y1 = y0 + ras.r;
        iLo = std::min(iLo, i0);
        iHi = std::max(iHi, i1 - 1);
        jLo = std::min(jLo, j);
        jHi = std::max(jHi, j);
        if (shapes)
            rects.push_back(geo::Polygon{
                {geo::Vec2(x0, y0), geo::Vec2(x1, y0), geo::Vec2(x1, y1), geo::Vec2(x0, y1)}, {}});
        sum += static_cast<double>(i1 - i0) * geo::Vec2(0.5 * (x0 + x1), 0.5 * (y0 + y1));
        a = b + 1;
    }
    patch.centroid = sum / static_cast<double>(pixels.size());
    // The box of the pixels' edges, each worked out as the pixel rows above do (same rounding).
    patch.box.min = geo::Vec2(ras.min.x() + iLo * ras.r, ras.min.y() + jLo * ras.r);
    patch.box.max = geo::Vec2(ras.min.x() + (iHi + 1) * ras.r, ras.min.y() + jHi * ras.r + ras.r);
    patch.columns = iHi - iLo + 1;
    patch.mask.assign(
        static_cast<std::size_t>(patch.columns) * static_cast<std::size_t>(jHi - jLo + 1), 0);
    for (const std::size_t p : pixels) {
        const int i = static_cast<int>(p % static_cast<std::size_t>(ras.nx));
        const int j = static_cast<int>(p / static_cast<std::size_t>(ras.nx));
        patch.mask[static_cast<std::size_t>(j - jLo) * static_cast<std::size_t>(patch.columns) +
                   static_cast<std::size_t>(i - iLo)] = 1;
    }
    if (shapes)
        patch.shape = geo::unite(rects);
    return patch;
}

} // namespace

Result<CoverageReport> checkCoverage(const geo::MultiPolygon& admissible,
                                     const std::vector<PhotoFootprint>& photos,
                                     const CoverageCheckOptions& opt,
                                     const std::vector<geo::Ring>* outlines) {
    auto shortest = checkInput(photos, opt, outlines);
    if (!shortest)
        return shortest.error();
    CoverageReport rep;
    double areaTotal = 0;
    for (const auto& p : admissible)
        areaTotal += std::abs(geo::signedArea(p.outer));
    if (admissible.empty() || areaTotal <= 0) {
        rep.resolutionM = opt.resolutionM;
        return rep;
    }
    const Raster ras = rasterOver(geo::bounds(admissible), opt, *shortest);
    rep.resolutionM = ras.r;
    // 0: outside, 1: admissible uncovered, 2: admissible covered.
    std::vector<std::uint8_t> px(
        static_cast<std::size_t>(ras.nx) * static_cast<std::size_t>(ras.ny), 0);
    if (Status st = fillAdmissible(ras, admissible, px); !st)
        return st.error();
    if (Status st = markPhotos(ras, photos, outlines, px); !st)
        return st.error();
    const double pixelArea = ras.r * ras.r;
    std::size_t inside = 0, covered = 0;
    for (auto v : px) {
        inside += v != 0;
        covered += v == 2;
    }
    rep.admissibleAreaM2 = static_cast<double>(inside) * pixelArea;
    rep.coveredAreaM2 = static_cast<double>(covered) * pixelArea;
    rep.uncoveredAreaM2 = rep.admissibleAreaM2 - rep.coveredAreaM2;
    rep.coveredFraction =
        inside > 0 ? static_cast<double>(covered) / static_cast<double>(inside) : 1.0;

    auto comps = uncoveredComponents(ras, px);
    if (!comps)
        return comps.error();
    rep.patchCount = static_cast<int>(comps->size());
    for (std::size_t k = 0; k < comps->size() && k < opt.maxPatches; ++k)
        rep.patches.push_back(patchOf(ras, (*comps)[k], opt.patchShapes));
    return rep;
}

NoFlyViolations countNoFlyViolations(const std::vector<std::vector<geo::Vec2>>& paths,
                                     const std::vector<geo::Polygon>& noFly, double marginM) {
    NoFlyViolations v;
    // The final check's threshold, without the planner's slack (geo/no_fly_field.h).
    const geo::NoFlyField field = geo::NoFlyField::forCheck(noFly, marginM);
    if (field.empty())
        return v;
    for (const auto& path : paths)
        for (std::size_t i = 0; i < path.size(); ++i) {
            if (!field.pointIsSafe(path[i]))
                ++v.waypoints;
            if (i > 0 && !field.segmentIsSafe(path[i - 1], path[i]))
                ++v.segments;
        }
    return v;
}

} // namespace pf::plan
