#include "core/plan/raster_planner.h"

#include "core/plan/metrics.h"
#include "core/plan/stride_planner.h"

#include <cstdlib>
#include <vector>

namespace pf::plan {

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
    CellPath rows = rasterSweep(g, *start, false);
    CellPath cols = rasterSweep(g, *start, true);
    const PathMetrics mr = computeMetrics(g, rows, mo), mc = computeMetrics(g, cols, mo);
    const bool useCols = mc.turns < mr.turns || (mc.turns == mr.turns && mc.distanceM < mr.distanceM);
    CellPath body = useCols ? std::move(cols) : std::move(rows);
    CellPath path;
    if (req.takeoff >= 0 && req.takeoff != *start) {
        path.cells.push_back(req.takeoff);
        path.revisit.push_back(true);
        appendTransit(g, path, *start);
        path.cells.pop_back();
        path.revisit.pop_back();
    }
    path.jumps += body.jumps;
    path.cells.insert(path.cells.end(), body.cells.begin(), body.cells.end());
    path.revisit.insert(path.revisit.end(), body.revisit.begin(), body.revisit.end());
    if (req.landing >= 0)
        appendTransit(g, path, req.landing);
    return path;
}

} // namespace pf::plan
