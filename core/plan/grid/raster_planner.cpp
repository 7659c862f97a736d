#include "core/plan/grid/raster_planner.h"

#include "core/job_scope.h"

#include "core/plan/grid/stride_planner.h"
#include "core/plan/metrics.h"

#include "core/plan/grid/grid_search.h"
#include "core/plan/grid/nearest_cell.h"

#include <climits>
#include <cstdlib>
#include <vector>

namespace pf::plan {

namespace {

} // namespace

CellPath rasterWalk(const grid::Grid& g, int start, bool byColumns) {
    using grid::Dir;
    const int n = g.cellCount();
    std::vector<std::uint8_t> done(static_cast<std::size_t>(n), 0);
    // Lines with visitable cells before and after the start's line decide the progress direction,
    // as in rasterSweep.
    const int nLines = byColumns ? g.cols() : g.rows();
    std::vector<std::uint8_t> lineUsed(static_cast<std::size_t>(nLines), 0);
    for (int i = 0; i < n; ++i)
        if (g.needsVisit(i))
            lineUsed[byColumns ? g.col(i) : g.row(i)] = 1;
    const int sLine = byColumns ? g.col(start) : g.row(start);
    int before = 0, after = 0;
    for (int l = 0; l < nLines; ++l) {
        if (lineUsed[l] && l < sLine)
            ++before;
        else if (lineUsed[l] && l > sLine)
            ++after;
    }
    const int alongPos = byColumns ? static_cast<int>(Dir::North) : static_cast<int>(Dir::East);
    const int fwd = byColumns ? static_cast<int>(after >= before ? Dir::East : Dir::West)
                              : static_cast<int>(after >= before ? Dir::North : Dir::South);
    const int back = (fwd + 2) % 4;

    auto isFree = [&](int c, int d) { return g.canMove(c, static_cast<Dir>(d)) && !done[c + dirOffset(g, d)]; };
    // Along the line, the side with more free cells in a row first (the positive side on a tie).
    auto longerSide = [&](int c) {
        int run[2] = {0, 0};
        for (int k = 0; k < 2; ++k) {
            const int d = (alongPos + 2 * k) % 4;
            for (int x = c; isFree(x, d); x += dirOffset(g, d))
                ++run[k];
        }
        return run[1] > run[0] ? (alongPos + 2) % 4 : alongPos;
    };

    CellPath path;
    int remaining = g.visitCount();
    auto visit = [&](int c) {
        if (!path.cells.empty() && !isAllowedStep(g, path.cells.back(), c, false))
            ++path.jumps;
        path.cells.push_back(c);
        path.revisit.push_back(false);
        done[c] = 1;
        --remaining;
    };
    visit(start);
    int cur = start;
    int heading = longerSide(cur);
    while (remaining > 0 && !stopRequested()) { // a cancelled job drops the partial path
        const int reverse = (heading + 2) % 4;
        int d = -1;
        if (isFree(cur, heading)) {
            d = heading;
        } else if (isFree(cur, reverse)) {
            d = heading = reverse;
        } else if (isFree(cur, fwd)) {
            d = fwd; // end of the line: the next line, flown the other way
            heading = reverse;
        } else if (isFree(cur, back)) {
            d = back;
            heading = reverse;
        }
        if (d >= 0) {
            cur += dirOffset(g, d);
            visit(cur);
            continue;
        }
        // Dead end: every neighbour is visited. The original algorithm had no safe path to the next
        // free cell and jumped to it.
        cur = nearestCell(g, cur, [&](int i) { return !done[i]; }, NearestBy::CellCentre);
        if (cur < 0)
            break; // cannot happen: remaining > 0 means a free cell exists
        visit(cur);
        heading = longerSide(cur);
    }
    return path;
}

CellPath rasterSweep(const grid::Grid& g, int start, bool byColumns) {
    // Lines in "sweep coordinates": line = row (or column), pos = column (or row).
    const int nLines = byColumns ? g.cols() : g.rows();
    const int nPos = byColumns ? g.rows() : g.cols();
    auto cellAt = [&](int line, int pos) { return byColumns ? g.index(line, pos) : g.index(pos, line); };
    std::vector<std::vector<int>> lines(static_cast<std::size_t>(nLines)); // positions of visitable cells
    for (int l = 0; l < nLines; ++l)
        for (int p = 0; p < nPos; ++p)
            if (g.needsVisit(cellAt(l, p)))
                lines[l].push_back(p);
    const int sLine = byColumns ? g.col(start) : g.row(start);
    const int sPos = byColumns ? g.row(start) : g.col(start);

    int before = 0, after = 0;
    for (int l = 0; l < nLines; ++l) {
        if (lines[l].empty())
            continue;
        if (l < sLine)
            ++before;
        else if (l > sLine)
            ++after;
    }
    const int step = after >= before ? 1 : -1;

    CellPath path;
    auto emit = [&](int line, int pos) {
        const int c = cellAt(line, pos);
        if (!path.cells.empty() && !isAllowedStep(g, path.cells.back(), c, false))
            ++path.jumps;
        path.cells.push_back(c);
        path.revisit.push_back(false);
    };
    // The start line: the longer side of the start first, then the rest outwards from the start.
    {
        const auto& ps = lines[sLine];
        std::size_t k = 0;
        while (k < ps.size() && ps[k] != sPos)
            ++k;
        const std::size_t right = ps.size() - 1 - k, left = k;
        if (right >= left) {
            for (std::size_t j = k; j < ps.size(); ++j)
                emit(sLine, ps[j]);
            for (std::size_t j = k; j-- > 0;)
                emit(sLine, ps[j]);
        } else {
            for (std::size_t j = k + 1; j-- > 0;)
                emit(sLine, ps[j]);
            for (std::size_t j = k + 1; j < ps.size(); ++j)
                emit(sLine, ps[j]);
        }
    }
    auto sweepLine = [&](int l) {
        const auto& ps = lines[l];
        if (ps.empty())
            return;
        const int cur = byColumns ? g.row(path.cells.back()) : g.col(path.cells.back());
        if (std::abs(ps.front() - cur) <= std::abs(ps.back() - cur)) {
            for (int p : ps)
                emit(l, p);
        } else {
            for (std::size_t j = ps.size(); j-- > 0;)
                emit(l, ps[j]);
        }
    };
    for (int l = sLine + step; l >= 0 && l < nLines; l += step)
        sweepLine(l);
    for (int l = sLine - step; l >= 0 && l < nLines; l -= step)
        sweepLine(l);
    return path;
}

Result<CellPath> planRaster(const grid::Grid& g, const CoverageRequest& req) {
    auto start = resolveStart(g, req);
    if (!start)
        return start.error();
    MetricsOptions mo;
    mo.turnLowerBound = false;
    CellPath rows = rasterWalk(g, *start, false);
    CellPath cols = rasterWalk(g, *start, true);
    const PathMetrics mr = computeMetrics(g, rows, mo), mc = computeMetrics(g, cols, mo);
    const bool useCols = mc.turns < mr.turns || (mc.turns == mr.turns && mc.distanceM < mr.distanceM);
    return withTakeoffAndLanding(g, req, *start, useCols ? std::move(cols) : std::move(rows));
}

} // namespace pf::plan
