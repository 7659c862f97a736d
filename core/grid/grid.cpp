// Grid construction (the admissible area and the buffered no-fly zones rasterised onto cells, see
// cell_raster.h), flight positions and the grid's cell and safety queries.
#include "core/grid/grid.h"

#include "core/grid/cell_raster.h"

#include "core/job_scope.h"

#include "core/geo/ogr_adapter.h"

#include <ogr_geometry.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>

namespace pf::grid {

using geo::Vec2;
using detail::Frame;
using detail::kEdge;
using detail::kIn;
using detail::kOut;
using detail::makeURings;
using detail::rasterise;
using detail::resolveEdgeCells;
using detail::URing;

namespace {

// Shifted flight positions are moved this far away from the zone's boundary when the cell allows it, so
// that they are strictly outside even for callers using an exact point-in-polygon test.
constexpr double kNudgeM = 1e-3;

geo::Box rotatedBounds(const geo::MultiPolygon& region, double c, double s) {
    geo::Box b{Vec2(std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()),
               Vec2(-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity())};
    for (const auto& poly : region)
        for (const auto& p : poly.outer) { // holes lie inside the outer ring
            const Vec2 q(c * p.x() + s * p.y(), -s * p.x() + c * p.y());
            b.min = b.min.cwiseMin(q);
            b.max = b.max.cwiseMax(q);
        }
    return b;
}

long long cellsAlong(double extent, double cellSize) {
    // The small slack keeps an extent that is an exact multiple of the cell size from gaining a column.
    const double n = std::ceil(extent / cellSize - 1e-9);
    // Absurd ratios (a cell size of a micrometre over a continent) saturate instead of overflowing;
    // the budget check rejects them anyway.
    return n >= 1e15 ? static_cast<long long>(1e15) : std::max(1LL, static_cast<long long>(n));
}

std::string fmtCount(double n) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.0f", n);
    std::string s = buf, out;
    const int len = static_cast<int>(s.size());
    for (int i = 0; i < len; ++i) {
        out += s[i];
        if ((len - i - 1) % 3 == 0 && i + 1 < len)
            out += ',';
    }
    return out;
}

double nearestOnSegment(const Vec2& p, const Vec2& a, const Vec2& b, Vec2* q) {
    const Vec2 ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    *q = a + t * ab;
    return (*q - p).squaredNorm();
}

// The nearest point to `centre` of the cell (its corners, a square) outside the zones' interiors,
// by squared distance into `best` / `bestP` (unchanged when there is none). The region's boundary
// is made of pieces of the cell's and the zones' edges, and the nearest point of a piece is the
// foot of the perpendicular from `centre` or one of its ends: a vertex, or where a zone edge
// crosses a cell edge. Each such candidate that `valid` accepts is measured.
template <class Valid>
void nearestFreePoint(const std::vector<Vec2>& corners, const Vec2& centre,
                      const geo::MultiPolygon& zones, const std::vector<geo::Box>& zoneBoxes,
                      const geo::Box& cellBox, Valid valid, double& best, Vec2& bestP) {
    auto offer = [&](const Vec2& q) {
        const double d = (q - centre).squaredNorm();
        if (d < best && valid(q)) {
            best = d;
            bestP = q;
        }
    };
    const std::size_t nc = corners.size();
    for (std::size_t k = 0; k < nc; ++k) {
        offer(corners[k]);
        Vec2 q;
        nearestOnSegment(centre, corners[k], corners[(k + 1) % nc], &q);
        offer(q);
    }
    auto scan = [&](const geo::Ring& ring) {
        const std::size_t n = ring.size();
        for (std::size_t k = 0; k < n; ++k) {
            const Vec2& a = ring[k];
            const Vec2& b = ring[k + 1 < n ? k + 1 : 0];
            const geo::Box eb{a.cwiseMin(b), a.cwiseMax(b)};
            if (!eb.intersects(cellBox))
                continue;
            offer(a);
            Vec2 q;
            nearestOnSegment(centre, a, b, &q);
            offer(q);
            const Vec2 d = b - a;
            for (std::size_t c = 0; c < nc; ++c) {
                const Vec2& p = corners[c];
                const Vec2 e = corners[(c + 1) % nc] - p;
                const double den = d.x() * e.y() - d.y() * e.x();
                if (den == 0.0)
                    continue;
                const Vec2 ap = p - a;
                const double t = (ap.x() * e.y() - ap.y() * e.x()) / den;
                const double s = (ap.x() * d.y() - ap.y() * d.x()) / den;
                if (t >= 0.0 && t <= 1.0 && s >= 0.0 && s <= 1.0)
                    offer(a + t * d);
            }
        }
    };
    for (std::size_t z = 0; z < zones.size(); ++z) {
        if (!zoneBoxes[z].intersects(cellBox))
            continue;
        scan(zones[z].outer);
        for (const auto& h : zones[z].holes)
            scan(h);
    }
}

// The error for a safety margin that is not a number of metres >= 0, if it is not.
std::optional<Error> marginError(double marginM) {
    if (std::isfinite(marginM) && marginM >= 0)
        return std::nullopt;
    char buf[128];
    std::snprintf(buf, sizeof buf, "the safety margin must be zero or a positive number of metres (got %g)",
                  marginM);
    return makeError(ErrorCode::InvalidInput, buf);
}

} // namespace

class GridBuilder {
public:
    static std::optional<Error> checkOptions(const GridOptions& opt);
    static Result<GridGround> prepare(const geo::MultiPolygon& area,
                                      const std::vector<geo::Polygon>& noFly, double safetyMarginM);
    static Result<Grid> build(const GridGround& ground, const GridOptions& opt);
};

Grid::Size Grid::sizeFor(const geo::MultiPolygon& region, double cellSize, double angleDeg) {
    const double a = angleDeg * M_PI / 180.0;
    const geo::Box b = rotatedBounds(region, std::cos(a), std::sin(a));
    if (region.empty() || !(cellSize > 0))
        return {};
    return Size{cellsAlong(b.max.x() - b.min.x(), cellSize), cellsAlong(b.max.y() - b.min.y(), cellSize)};
}

double Grid::cellSizeToFit(const geo::MultiPolygon& region, double cellSize, double angleDeg,
                           std::size_t maxCells) {
    const double budget = static_cast<double>(std::max<std::size_t>(1, maxCells));
    auto fits = [&](double s) { return sizeFor(region, s, angleDeg).cells() <= budget; };
    if (fits(cellSize))
        return cellSize;
    // The cell count never grows with the cell size, so a binary search over whole centimetres finds the
    // smallest size that fits.
    const double now = sizeFor(region, cellSize, angleDeg).cells();
    long long lo = static_cast<long long>(std::floor(cellSize * 100.0));
    long long hi = static_cast<long long>(std::ceil(cellSize * std::sqrt(now / budget) * 100.0)) + 1;
    while (!fits(hi / 100.0))
        hi *= 2;
    while (hi - lo > 1) { // invariant: lo does not fit, hi fits
        const long long mid = lo + (hi - lo) / 2;
        (fits(mid / 100.0) ? hi : lo) = mid;
    }
    return hi / 100.0;
}

Result<Grid> Grid::build(const geo::Polygon& area, const std::vector<geo::Polygon>& noFly, const GridOptions& opt) {
    return build(geo::MultiPolygon{area}, noFly, opt);
}

Result<Grid> Grid::build(const geo::MultiPolygon& area, const std::vector<geo::Polygon>& noFly,
                         const GridOptions& opt) {
    if (auto e = GridBuilder::checkOptions(opt))
        return *e;
    auto ground = GridBuilder::prepare(area, noFly, opt.safetyMarginM);
    if (!ground)
        return ground.error();
    return GridBuilder::build(*ground, opt);
}

Result<Grid> Grid::build(const GridGround& ground, const GridOptions& opt) {
    return GridBuilder::build(ground, opt);
}

std::optional<Error> Grid::checkOptions(const GridOptions& opt) {
    return GridBuilder::checkOptions(opt);
}

Result<GridGround> GridGround::prepare(const geo::MultiPolygon& area,
                                       const std::vector<geo::Polygon>& noFly,
                                       double safetyMarginM) {
    return GridBuilder::prepare(area, noFly, safetyMarginM);
}

std::optional<Error> GridBuilder::checkOptions(const GridOptions& opt) {
    char buf[512];
    if (!std::isfinite(opt.cellSize) || opt.cellSize <= 0) {
        std::snprintf(buf, sizeof buf, "the grid cell size must be a positive number of metres (got %g)",
                      opt.cellSize);
        return makeError(ErrorCode::InvalidInput, buf);
    }
    if (!std::isfinite(opt.angleDeg))
        return makeError(ErrorCode::InvalidInput, "the grid angle must be a finite number of degrees");
    return marginError(opt.safetyMarginM);
}

Result<GridGround> GridBuilder::prepare(const geo::MultiPolygon& area,
                                        const std::vector<geo::Polygon>& noFly,
                                        double safetyMarginM) {
    if (auto e = marginError(safetyMarginM))
        return *e;
    if (area.empty())
        return makeError(ErrorCode::InvalidGeometry, "the area is empty: there is nothing to photograph");
    for (const auto& p : area) {
        std::string reason;
        if (!geo::isValid(p, &reason)) // the rasterisation and GEOS's booleans need valid polygons
            return makeError(ErrorCode::InvalidGeometry,
                             "the area is not a valid polygon (" + reason + "): check it with the validate command");
    }
    if (geo::area(area) <= 0)
        return makeError(ErrorCode::InvalidGeometry, "the area is empty: there is nothing to photograph");

    const geo::MultiPolygon zones(noFly.begin(), noFly.end());
    // Several area polygons are united first: the even-odd rasterisation below would cancel overlaps.
    const geo::MultiPolygon whole = area.size() > 1 ? geo::unite(area) : area;
    // The zones are united once, for both the admissible area and the buffer.
    const geo::MultiPolygon zoneUnion = zones.empty() ? geo::MultiPolygon{} : geo::unite(zones);
    geo::MultiPolygon admissible = whole;
    // Only the zones that reach the area's box can change it (a subarea of a fleet split touches a
    // few of the mission's zones): the difference is asked of those.
    const geo::Box wholeBox = geo::bounds(whole);
    geo::MultiPolygon nearZones;
    for (const auto& z : zoneUnion)
        if (geo::bounds(z).intersects(wholeBox))
            nearZones.push_back(z);
    if (!nearZones.empty()) {
        const auto wa = geo::detail::toOgr(whole);
        const auto zu = geo::detail::toOgr(nearZones);
        geo::detail::OgrGeomPtr d(wa->Difference(zu.get()));
        admissible = geo::detail::fromOgr(d.get());
    }
    admissible.erase(std::remove_if(admissible.begin(), admissible.end(),
                                    [](const geo::Polygon& p) { return p.outer.size() < 3; }),
                     admissible.end());
    if (admissible.empty() || geo::area(admissible) <= 0)
        return makeError(ErrorCode::InvalidGeometry,
                         "the no-fly zones cover the whole area: nothing admissible is left to photograph");

    GridGround gr;
    gr.m_safetyMarginM = safetyMarginM;
    gr.m_areaBox = geo::bounds(area);
    gr.m_admissible = std::move(admissible);
    // GEOS approximates the buffer's round corners by chords inscribed in the true offset curve (8
    // per quarter circle), which would cut up to 0.5 % off the margin there; buffering a little
    // more makes the polygonal zone contain the true offset, so the margin is always honoured in
    // full.
    geo::MultiPolygon buffered;
    if (!zoneUnion.empty())
        buffered = safetyMarginM > 0
                       ? geo::buffer(zoneUnion, safetyMarginM / std::cos(M_PI / 16), 8)
                       : zoneUnion;
    // Pockets: ground enclosed by margins that merge round it (zones a few metres apart, a U-shaped
    // zone whose margin closes the U) is a hole of the buffered zones. No safe path leads into it,
    // so it is flown like a margin: never entered, its ground photographed from outside as far as
    // the footprints reach. The holes are filled; what they held of the admissible area is kept for
    // reports.
    {
        geo::MultiPolygon pockets;
        for (auto& z : buffered) {
            for (auto& h : z.holes)
                pockets.push_back(geo::Polygon{std::move(h), {}});
            z.holes.clear();
        }
        if (!pockets.empty()) {
            for (const auto& p : pockets)
                for (const auto& part : geo::intersection(gr.m_admissible, p))
                    gr.m_pockets.push_back(part);
            buffered.insert(buffered.end(), pockets.begin(), pockets.end());
            buffered = geo::unite(buffered);
        }
    }
    // The grid's safety questions go to the no-fly model, asked of these zones.
    gr.m_noFly = geo::NoFlyField::ofGrownZones(std::move(buffered));
    for (const auto& z : gr.m_noFly.zones()) {
        gr.m_zoneBoxes.push_back(geo::bounds(z));
    }
    return gr;
}

Result<Grid> GridBuilder::build(const GridGround& ground, const GridOptions& opt) {
    char buf[512];
    if (auto e = checkOptions(opt))
        return *e;
    if (opt.safetyMarginM != ground.m_safetyMarginM)
        return makeError(ErrorCode::Internal,
                         "a grid was asked of ground prepared for another safety margin");
    const geo::MultiPolygon& admissible = ground.m_admissible;

    // Budget check before any per-cell allocation.
    const Grid::Size size = Grid::sizeFor(admissible, opt.cellSize, opt.angleDeg);
    const double budget = static_cast<double>(std::min<std::size_t>(opt.maxCells, INT_MAX));
    if (size.cells() > budget) {
        const double fit = Grid::cellSizeToFit(admissible, opt.cellSize, opt.angleDeg,
                                               static_cast<std::size_t>(budget));
        std::snprintf(buf, sizeof buf,
                      "the area is too large for the cell budget: at a cell size of %.2f m its grid would need "
                      "%s x %s = %s cells, more than the budget of %s; a cell size of at least %.2f m would fit",
                      opt.cellSize, fmtCount(static_cast<double>(size.cols)).c_str(),
                      fmtCount(static_cast<double>(size.rows)).c_str(), fmtCount(size.cells()).c_str(),
                      fmtCount(budget).c_str(), fit);
        return makeError(ErrorCode::TooLarge, buf);
    }

    Grid g;
    g.m_cols = static_cast<int>(size.cols);
    g.m_rows = static_cast<int>(size.rows);
    g.m_cellSize = opt.cellSize;
    g.m_angleDeg = opt.angleDeg;
    const double rad = opt.angleDeg * M_PI / 180.0;
    g.m_cos = std::cos(rad);
    g.m_sin = std::sin(rad);

    // The grid is rotated about the centre of the area's bounding box and centred on the admissible
    // area's rotated bounding box; origin is corner (col 0, row 0) in the local frame.
    const geo::Box& areaBox = ground.m_areaBox;
    const Vec2 pivot = 0.5 * (areaBox.min + areaBox.max);
    geo::MultiPolygon centred = admissible;
    for (auto& poly : centred)
        for (auto& p : poly.outer)
            p -= pivot;
    const geo::Box rb = rotatedBounds(centred, g.m_cos, g.m_sin);
    const Vec2 slack = 0.5 * (Vec2(g.m_cols, g.m_rows) * opt.cellSize - (rb.max - rb.min));
    const Vec2 umin = rb.min - slack;
    g.m_origin = pivot + Vec2(g.m_cos * umin.x() - g.m_sin * umin.y(), g.m_sin * umin.x() + g.m_cos * umin.y());

    Frame frame;
    frame.origin = g.m_origin;
    frame.c = g.m_cos;
    frame.s = g.m_sin;
    frame.size = opt.cellSize;

    g.m_admissible = admissible;
    g.m_pockets = ground.m_pockets;
    g.m_noFly = ground.m_noFly;
    const geo::MultiPolygon& bufferedZones = g.m_noFly.zones();
    const std::vector<geo::Box>& zoneBoxes =
        ground.m_zoneBoxes; // to skip far zones fast when cutting cells

    // Which cells overlap the admissible area.
    const std::vector<URing> admRings = makeURings(g.m_admissible, frame);
    std::vector<std::uint8_t> inArea = rasterise(admRings, g.m_cols, g.m_rows);
    resolveEdgeCells(inArea, admRings, g.m_cols, g.m_rows);

    // Which cells are entirely clear of, entirely inside, or crossed by a buffered no-fly zone.
    const std::vector<URing> flyRings = makeURings(bufferedZones, frame);
    const std::vector<std::uint8_t> fly =
        flyRings.empty() ? std::vector<std::uint8_t>(inArea.size(), kOut) : rasterise(flyRings, g.m_cols, g.m_rows);

    const int n = g.m_cols * g.m_rows;
    g.m_state.assign(static_cast<std::size_t>(n), static_cast<std::uint8_t>(CellState::Outside));
    g.m_moves.assign(static_cast<std::size_t>(n), 0);
    for (int i = 0; i < n; ++i) {
        if ((i & 0x3FFF) == 0 && stopRequested())
            return makeError(ErrorCode::Cancelled, "building the grid: cancelled");
        if (inArea[i] != kIn)
            continue;
        CellState st = CellState::Free;
        if (fly[i] == kIn) {
            st = CellState::Unflyable;
        } else if (fly[i] == kEdge && !g.pointIsSafe(g.cellCenter(i))) {
            // The centre is unsafe: look for the nearest safe point of the cell (cell minus zones).
            const auto corners = g.cellCorners(i);
            const Vec2 centre = g.cellCenter(i);
            const geo::Box cellBox = geo::bounds(corners);
            const int cc = g.col(i), cr = g.row(i);
            double best = std::numeric_limits<double>::infinity();
            Vec2 bestP = centre;
            nearestFreePoint(
                corners, centre, bufferedZones, zoneBoxes, cellBox,
                [&](const Vec2& q) {
                    // In the closed cell (its edges up to rounding) and outside every zone's
                    // interior.
                    const Vec2 u = frame.toGrid(q);
                    const double eps = 1e-9;
                    return u.x() >= cc - eps && u.x() <= cc + 1 + eps && u.y() >= cr - eps &&
                           u.y() <= cr + 1 + eps && g.pointIsSafe(q);
                },
                best, bestP);
            st = CellState::Unflyable;
            if (std::isfinite(best) && g.pointIsSafe(bestP)) {
                st = CellState::Shifted;
                const Vec2 dir = bestP - centre;
                if (dir.norm() > 0) {
                    const Vec2 nudged = bestP + kNudgeM * dir.normalized();
                    const Vec2 u = frame.toGrid(nudged);
                    const int c = g.col(i), r = g.row(i);
                    if (u.x() >= c && u.x() <= c + 1 && u.y() >= r && u.y() <= r + 1 &&
                        !geo::contains(bufferedZones, nudged))
                        bestP = nudged;
                }
                g.m_shifts.emplace_back(i, bestP);
            }
        }
        g.m_state[i] = static_cast<std::uint8_t>(st);
        if (st == CellState::Free || st == CellState::Shifted)
            ++g.m_visitCount;
    }

    // Allowed moves: between two visitable 4-neighbours when the segment between flight positions is
    // safe. Two Free cells clear of every buffered zone are joined by a segment inside their own squares.
    for (int i = 0; i < n; ++i) {
        if ((i & 0xFFFF) == 0 && stopRequested())
            return makeError(ErrorCode::Cancelled, "building the grid: cancelled");
        if (!g.needsVisit(i))
            continue;
        for (Dir d : {Dir::East, Dir::North}) {
            const int j = g.neighbour(i, d);
            if (j < 0 || !g.needsVisit(j))
                continue;
            const bool clear = fly[i] == kOut && fly[j] == kOut;
            if (clear || g.segmentIsSafe(g.flightPosition(i), g.flightPosition(j))) {
                g.m_moves[i] |= static_cast<std::uint8_t>(1u << static_cast<int>(d));
                g.m_moves[j] |= static_cast<std::uint8_t>(1u << static_cast<int>(opposite(d)));
            }
        }
    }
    return g;
}

Grid Grid::fromMask(int cols, int rows, const std::vector<std::uint8_t>& mask, double cellSize) {
    Grid g;
    g.m_cols = std::max(0, cols);
    g.m_rows = std::max(0, rows);
    g.m_cellSize = cellSize;
    const int n = g.m_cols * g.m_rows;
    g.m_state.assign(static_cast<std::size_t>(n), static_cast<std::uint8_t>(CellState::Outside));
    g.m_moves.assign(static_cast<std::size_t>(n), 0);
    for (int i = 0; i < n && i < static_cast<int>(mask.size()); ++i)
        if (mask[i]) {
            g.m_state[i] = static_cast<std::uint8_t>(CellState::Free);
            ++g.m_visitCount;
        }
    for (int i = 0; i < n; ++i) {
        if (!g.needsVisit(i))
            continue;
        for (Dir d : kDirs) {
            const int j = g.neighbour(i, d);
            if (j >= 0 && g.needsVisit(j))
                g.m_moves[i] |= static_cast<std::uint8_t>(1u << static_cast<int>(d));
        }
    }
    return g;
}

int Grid::neighbour(int i, Dir d) const {
    const int c = col(i) + kDirDx[static_cast<int>(d)];
    const int r = row(i) + kDirDy[static_cast<int>(d)];
    return inBounds(c, r) ? index(c, r) : -1;
}

bool Grid::onContour(int i) const {
    if (!needsVisit(i))
        return false;
    for (Dir d : kDirs) {
        const int j = neighbour(i, d);
        if (j < 0 || !needsVisit(j))
            return true;
    }
    return false;
}

geo::Vec2 Grid::cellCenter(int i) const {
    const double u = (col(i) + 0.5) * m_cellSize, v = (row(i) + 0.5) * m_cellSize;
    return m_origin + Vec2(m_cos * u - m_sin * v, m_sin * u + m_cos * v);
}

geo::Vec2 Grid::flightPosition(int i) const {
    if (state(i) == CellState::Shifted) {
        auto it = std::lower_bound(m_shifts.begin(), m_shifts.end(), i,
                                   [](const std::pair<int, Vec2>& e, int k) { return e.first < k; });
        if (it != m_shifts.end() && it->first == i)
            return it->second;
    }
    return cellCenter(i);
}

std::vector<geo::Vec2> Grid::cellCorners(int i) const {
    std::vector<Vec2> out;
    out.reserve(4);
    const int c = col(i), r = row(i);
    const int dc[4] = {0, 1, 1, 0}, dr[4] = {0, 0, 1, 1};
    for (int k = 0; k < 4; ++k) {
        const double u = (c + dc[k]) * m_cellSize, v = (r + dr[k]) * m_cellSize;
        out.push_back(m_origin + Vec2(m_cos * u - m_sin * v, m_sin * u + m_cos * v));
    }
    return out;
}

std::optional<int> Grid::cellAt(const geo::Vec2& p) const {
    const Vec2 d = p - m_origin;
    const double u = (m_cos * d.x() + m_sin * d.y()) / m_cellSize;
    const double v = (-m_sin * d.x() + m_cos * d.y()) / m_cellSize;
    if (!(u >= 0 && v >= 0 && u <= m_cols && v <= m_rows))
        return std::nullopt;
    const int c = std::min(m_cols - 1, static_cast<int>(std::floor(u)));
    const int r = std::min(m_rows - 1, static_cast<int>(std::floor(v)));
    return index(c, r);
}

int Grid::nearestVisitable(const geo::Vec2& p) const {
    if (m_visitCount == 0)
        return -1;
    const Vec2 d = p - m_origin;
    const double u = (m_cos * d.x() + m_sin * d.y()) / m_cellSize;
    const double v = (-m_sin * d.x() + m_cos * d.y()) / m_cellSize;
    const int c0 = std::clamp(static_cast<int>(std::floor(u)), 0, m_cols - 1);
    const int r0 = std::clamp(static_cast<int>(std::floor(v)), 0, m_rows - 1);
    int best = -1;
    double bestD = std::numeric_limits<double>::infinity();
    const int maxK = std::max(m_cols, m_rows);
    // Rings of growing Chebyshev radius k around the start cell: every point of a cell on ring k is at
    // least (k - 1) cells away from p, so the search stops once that exceeds the best distance found.
    for (int k = 0; k <= maxK; ++k) {
        if (best >= 0 && (k - 1) * m_cellSize > bestD)
            break;
        for (int r = r0 - k; r <= r0 + k; ++r) {
            if (r < 0 || r >= m_rows)
                continue;
            const bool edgeRow = (r == r0 - k || r == r0 + k);
            for (int c = c0 - k; c <= c0 + k; c += edgeRow ? 1 : 2 * std::max(k, 1)) {
                if (c < 0 || c >= m_cols)
                    continue;
                const int i = index(c, r);
                if (!needsVisit(i))
                    continue;
                const double dist = (flightPosition(i) - p).norm();
                if (dist < bestD) {
                    bestD = dist;
                    best = i;
                }
            }
        }
    }
    return best;
}

std::size_t Grid::memoryBytes() const {
    auto polyBytes = [](const geo::MultiPolygon& mp) {
        std::size_t b = mp.capacity() * sizeof(geo::Polygon);
        for (const auto& p : mp) {
            b += p.outer.capacity() * sizeof(Vec2) + p.holes.capacity() * sizeof(geo::Ring);
            for (const auto& h : p.holes)
                b += h.capacity() * sizeof(Vec2);
        }
        return b;
    };
    return m_state.capacity() + m_moves.capacity() + m_shifts.capacity() * sizeof(m_shifts[0]) +
           polyBytes(m_admissible) + polyBytes(m_noFly.zones()) + polyBytes(m_pockets) +
           m_noFly.zones().size() * 2 * sizeof(geo::Box); // the field's boxes and circles
}

} // namespace pf::grid
