// The paper's experiment: every planner started from every contour cell of sample areas, with averages.
#pragma once

#include "core/geo/types.h"
#include "core/grid/grid.h"
#include "core/plan/metrics.h"
#include "core/plan/planner.h"
#include "core/result.h"

#include <string>
#include <vector>

namespace pf::plan {

// A sample area file (resources/areas/*.geojson): a GeoJSON FeatureCollection in WGS84 with one Polygon
// feature whose property "role" is "area" and any number with role "nofly"; the cell size comes from
// the area feature's (or the collection's) "cell_size_m" property, default kDefaultEvalCellSizeM.
constexpr double kDefaultEvalCellSizeM = 20.0;
struct EvalArea {
    std::string name;
    geo::GeoPolygon area;
    std::vector<geo::GeoPolygon> noFly;
    double cellSizeM = kDefaultEvalCellSizeM;
};
Result<EvalArea> loadEvalArea(const std::string& path);

// The area's grid at angle 0 in a frame centred on the area, without safety margin (the paper's grids).
Result<grid::Grid> evalGrid(const EvalArea& area);

struct EvalRun {
    std::string area;
    PlannerKind planner = PlannerKind::Stride;
    int startCell = -1;
    int startCol = 0, startRow = 0;
    PathMetrics metrics; // planningMs set
};

struct EvalOptions {
    std::vector<PlannerKind> planners{PlannerKind::Stride, PlannerKind::Raster};
    WavefrontOptions wavefront;
    int maxStarts = 0; // 0: every contour cell; else that many, evenly spread along the cell order
    bool strideVariants = true; // false: the stride planner with the paper's rules only
};

// Runs every planner from every contour start cell of the grid.
std::vector<EvalRun> evaluateArea(const std::string& areaName, const grid::Grid& g, const EvalOptions& opt);

struct EvalSummary {
    std::string area;
    PlannerKind planner = PlannerKind::Stride;
    int runs = 0;
    int incomplete = 0; // runs that missed a cell (must be 0)
    int cells = 0;
    int turnLowerBound = -1;
    double avgTurns = 0, minTurns = 0, maxTurns = 0;
    double avgDistanceM = 0, avgJumps = 0, avgRevisits = 0, avgTimeS = 0, avgPlanningMs = 0;
};
std::vector<EvalSummary> summarise(const std::vector<EvalRun>& runs, const std::vector<int>& lowerBounds = {});

} // namespace pf::plan
