#include "core/plan/evaluation.h"

#include "core/geo/local_frame.h"

#include <cpl_json.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>

namespace pf::plan {

namespace {

Result<geo::GeoPolygon> polygonFrom(const CPLJSONObject& geom, const std::string& what) {
    if (geom.GetString("type") != "Polygon")
        return makeError(ErrorCode::ParseError, what + " is not a Polygon");
    const CPLJSONArray rings = geom.GetArray("coordinates");
    if (!rings.IsValid() || rings.Size() == 0)
        return makeError(ErrorCode::ParseError, what + " has no coordinates");
    geo::GeoPolygon poly;
    for (int r = 0; r < rings.Size(); ++r) {
        const CPLJSONArray ring = rings[r].ToArray();
        geo::GeoRing out;
        for (int k = 0; k < ring.Size(); ++k) {
            const CPLJSONArray pt = ring[k].ToArray();
            if (pt.Size() < 2)
                return makeError(ErrorCode::ParseError, what + ": a position needs a longitude and a latitude");
            out.push_back({pt[0].ToDouble(), pt[1].ToDouble()});
        }
        if (out.size() > 1 && out.front() == out.back())
            out.pop_back();
        if (out.size() < 3)
            return makeError(ErrorCode::ParseError, what + ": a ring needs at least three positions");
        if (r == 0)
            poly.outer = std::move(out);
        else
            poly.holes.push_back(std::move(out));
    }
    return poly;
}

} // namespace

Result<EvalArea> loadEvalArea(const std::string& path) {
    CPLJSONDocument doc;
    if (!doc.Load(path))
        return makeError(ErrorCode::IoError, "cannot read the area file " + path + " (missing or not JSON)");
    const CPLJSONObject root = doc.GetRoot();
    if (root.GetString("type") != "FeatureCollection")
        return makeError(ErrorCode::ParseError, path + ": not a GeoJSON FeatureCollection");
    EvalArea a;
    a.name = root.GetString("name");
    a.cellSizeM = root.GetDouble("cell_size_m", kDefaultEvalCellSizeM);
    const CPLJSONArray features = root.GetArray("features");
    bool haveArea = false;
    for (int i = 0; i < features.Size(); ++i) {
        const CPLJSONObject f = features[i];
        const CPLJSONObject props = f.GetObj("properties");
        const std::string role = props.GetString("role");
        const std::string what = path + ": feature " + std::to_string(i + 1);
        auto poly = polygonFrom(f.GetObj("geometry"), what);
        if (!poly)
            return poly.error();
        if (role == "area") {
            if (haveArea)
                return makeError(ErrorCode::ParseError, path + ": more than one feature has the role \"area\"");
            haveArea = true;
            a.area = std::move(*poly);
            if (props.GetString("name").size())
                a.name = props.GetString("name");
            a.cellSizeM = props.GetDouble("cell_size_m", a.cellSizeM);
        } else if (role == "nofly") {
            a.noFly.push_back(std::move(*poly));
        } else {
            return makeError(ErrorCode::ParseError,
                             what + ": the property \"role\" must be \"area\" or \"nofly\" (got \"" + role + "\")");
        }
    }
    if (!haveArea)
        return makeError(ErrorCode::ParseError, path + ": no feature has the role \"area\"");
    if (!(a.cellSizeM > 0))
        return makeError(ErrorCode::InvalidInput, path + ": cell_size_m must be a positive number of metres");
    if (a.name.empty())
        a.name = path;
    return a;
}

Result<grid::Grid> evalGrid(const EvalArea& area) {
    auto frame = geo::LocalFrame::forArea(area.area);
    if (!frame)
        return frame.error();
    std::vector<geo::Polygon> zones;
    for (const auto& z : area.noFly)
        zones.push_back(frame->toLocal(z));
    grid::GridOptions opt;
    opt.cellSize = area.cellSizeM;
    opt.angleDeg = 0;
    opt.safetyMarginM = 0;
    return grid::Grid::build(frame->toLocal(area.area), zones, opt);
}

std::vector<EvalRun> evaluateArea(const std::string& areaName, const grid::Grid& g, const EvalOptions& opt) {
    std::vector<int> starts;
    for (int i = 0; i < g.cellCount(); ++i)
        if (g.onContour(i))
            starts.push_back(i);
    if (opt.maxStarts > 0 && static_cast<int>(starts.size()) > opt.maxStarts) {
        std::vector<int> picked;
        for (int k = 0; k < opt.maxStarts; ++k)
            picked.push_back(starts[static_cast<std::size_t>(k) * starts.size() / opt.maxStarts]);
        starts.swap(picked);
    }
    std::vector<EvalRun> runs;
    for (PlannerKind kind : opt.planners) {
        PlanOptions po;
        po.kind = kind;
        po.wavefront = opt.wavefront;
        po.strideVariants = opt.strideVariants;
        MetricsOptions mo;
        mo.turnLowerBound = false;
        mo.diagonalSteps = kind == PlannerKind::Wavefront && opt.wavefront.moore;
        mo.time = opt.wavefront.time;
        for (int s : starts) {
            CoverageRequest req;
            req.start = s;
            const auto t0 = std::chrono::steady_clock::now();
            auto path = planCoverage(g, req, po);
            const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
            if (!path)
                continue; // cannot happen for a contour cell; the summary would show fewer runs
            EvalRun r;
            r.area = areaName;
            r.planner = kind;
            r.startCell = s;
            r.startCol = g.col(s);
            r.startRow = g.row(s);
            r.metrics = computeMetrics(g, *path, mo);
            r.metrics.planningMs = ms;
            runs.push_back(std::move(r));
        }
    }
    return runs;
}

std::vector<EvalSummary> summarise(const std::vector<EvalRun>& runs, const std::vector<int>& lowerBounds) {
    std::vector<EvalSummary> out;
    std::map<std::pair<std::string, int>, std::size_t> index;
    std::vector<std::string> areaOrder;
    for (const auto& r : runs) {
        const auto key = std::make_pair(r.area, static_cast<int>(r.planner));
        auto it = index.find(key);
        if (it == index.end()) {
            if (std::find(areaOrder.begin(), areaOrder.end(), r.area) == areaOrder.end())
                areaOrder.push_back(r.area);
            EvalSummary s;
            s.area = r.area;
            s.planner = r.planner;
            s.cells = r.metrics.visitable;
            s.minTurns = s.maxTurns = r.metrics.turns;
            const std::size_t ai = static_cast<std::size_t>(
                std::find(areaOrder.begin(), areaOrder.end(), r.area) - areaOrder.begin());
            if (ai < lowerBounds.size())
                s.turnLowerBound = lowerBounds[ai];
            it = index.emplace(key, out.size()).first;
            out.push_back(s);
        }
        EvalSummary& s = out[it->second];
        ++s.runs;
        s.incomplete += r.metrics.complete() ? 0 : 1;
        s.avgTurns += r.metrics.turns;
        s.minTurns = std::min<double>(s.minTurns, r.metrics.turns);
        s.maxTurns = std::max<double>(s.maxTurns, r.metrics.turns);
        s.avgDistanceM += r.metrics.distanceM;
        s.avgJumps += r.metrics.jumps;
        s.avgRevisits += r.metrics.revisits;
        s.avgTimeS += r.metrics.estimatedTimeS;
        s.avgPlanningMs += r.metrics.planningMs;
    }
    for (auto& s : out) {
        const double n = std::max(1, s.runs);
        s.avgTurns /= n;
        s.avgDistanceM /= n;
        s.avgJumps /= n;
        s.avgRevisits /= n;
        s.avgTimeS /= n;
        s.avgPlanningMs /= n;
    }
    return out;
}

} // namespace pf::plan
