#include "core/plan/planner.h"

#include "core/plan/grid/raster_planner.h"
#include "core/plan/grid/stride_planner.h"
#include "core/plan/grid/wavefront_planner.h"

#include <cstdlib>
#include <string>

namespace pf::plan {

namespace {

Status checkCell(const grid::Grid& g, int cell, const char* what) {
    if (cell < 0)
        return {};
    if (cell >= g.cellCount())
        return makeError(ErrorCode::InvalidInput, std::string("the ") + what + " cell " + std::to_string(cell) +
                                                      " is outside the grid of " +
                                                      std::to_string(g.cellCount()) + " cells");
    if (!g.needsVisit(cell))
        return makeError(ErrorCode::InvalidInput,
                         std::string("the ") + what + " cell (column " + std::to_string(g.col(cell)) + ", row " +
                             std::to_string(g.row(cell)) + ") is not part of the area to photograph");
    return {};
}

} // namespace

Result<int> resolveStart(const grid::Grid& g, const CoverageRequest& req) {
    if (g.visitCount() <= 0)
        return makeError(ErrorCode::InvalidInput, "the grid has no cell to photograph (the area is empty or "
                                                  "entirely covered by no-fly zones)");
    for (auto [cell, what] : {std::pair{req.start, "start"}, std::pair{req.takeoff, "take-off"},
                              std::pair{req.landing, "landing"}}) {
        Status st = checkCell(g, cell, what);
        if (!st)
            return st.error();
    }
    if (req.start >= 0)
        return req.start;
    if (req.takeoff >= 0)
        return req.takeoff;
    for (int i = 0; i < g.cellCount(); ++i)
        if (g.needsVisit(i))
            return i;
    return makeError(ErrorCode::Internal, "no visitable cell found although the grid counts some");
}

CellPath withTakeoffAndLanding(const grid::Grid& g, const CoverageRequest& req, int start, CellPath body) {
    CellPath path;
    if (req.takeoff >= 0 && req.takeoff != start) {
        path.cells.push_back(req.takeoff);
        path.revisit.push_back(true);
        appendTransit(g, path, start);
        // The transit ends on the start cell, which the body photographs: drop the duplicate.
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

Result<CellPath> planCoverage(const grid::Grid& g, const CoverageRequest& req, const PlanOptions& opt) {
    switch (opt.kind) {
    case PlannerKind::Stride:
        if (!opt.strideVariants)
            return planStrideVariant(g, req, StrideVariant{});
        return planStride(g, req, nullptr, opt.stride);
    case PlannerKind::Raster:
        return planRaster(g, req);
    case PlannerKind::Wavefront:
        return planWavefront(g, req, opt.wavefront);
    }
    return makeError(ErrorCode::Internal, "unknown planner");
}

bool isAllowedStep(const grid::Grid& g, int a, int b, bool diagonal) {
    if (a == b)
        return false;
    const int dc = g.col(b) - g.col(a), dr = g.row(b) - g.row(a);
    if (std::abs(dc) + std::abs(dr) == 1) {
        const grid::Dir d = dc == 1 ? grid::Dir::East : dc == -1 ? grid::Dir::West : dr == 1 ? grid::Dir::North
                                                                                              : grid::Dir::South;
        return g.canMove(a, d);
    }
    if (!diagonal || std::abs(dc) != 1 || std::abs(dr) != 1)
        return false;
    if (!g.needsVisit(a) || !g.needsVisit(b))
        return false;
    return g.bufferedNoFly().empty() || g.segmentIsSafe(g.flightPosition(a), g.flightPosition(b));
}

} // namespace pf::plan
