#include "core/io/grid_export.h"

#include <cpl_json.h>
#include <cpl_vsi.h>

#include <cerrno>
#include <cmath>
#include <cstring>

namespace pf::io {

namespace {

const char* stateName(grid::CellState s) {
    switch (s) {
    case grid::CellState::Free:
        return "free";
    case grid::CellState::Shifted:
        return "shifted";
    case grid::CellState::Unflyable:
        return "unflyable";
    case grid::CellState::Outside:
        break;
    }
    return "outside";
}

// Cells are tens of metres wide: 1e-8 degree (about 1 mm) keeps the file short without losing anything.
double rounded(double deg) { return std::round(deg * 1e8) / 1e8; }

CPLJSONArray position(const geo::LonLat& p) {
    CPLJSONArray a;
    a.Add(rounded(p.lon));
    a.Add(rounded(p.lat));
    return a;
}

// Writes the collection piece by piece through `sink`: each feature is built and formatted with
// CPLJSON on its own, so memory stays flat however many cells the grid has (a single document tree of a
// million cells would take gigabytes).
template <class Sink> void writeCollection(const grid::Grid& g, const geo::LocalFrame& frame, const GridExportOptions& opt, Sink sink) {
    CPLJSONObject meta;
    meta.Add("cell_size_m", g.cellSize());
    meta.Add("angle_deg", g.angleDeg());
    meta.Add("cols", g.cols());
    meta.Add("rows", g.rows());
    meta.Add("visit_count", g.visitCount());
    meta.Add("local_frame", frame.projString());
    sink("{\"type\":\"FeatureCollection\",\"photoflight_grid\":" + meta.Format(CPLJSONObject::PrettyFormat::Plain) +
         ",\"features\":[\n");
    bool first = true;
    for (int i = 0; i < g.cellCount(); ++i) {
        const grid::CellState st = g.state(i);
        if (st == grid::CellState::Outside && !opt.includeOutside)
            continue;
        CPLJSONObject f;
        f.Add("type", "Feature");
        CPLJSONObject geom;
        geom.Add("type", "Polygon");
        CPLJSONArray ring;
        const geo::GeoRing corners = frame.toGeo(g.cellCorners(i));
        for (const auto& c : corners)
            ring.Add(position(c));
        ring.Add(position(corners.front()));
        CPLJSONArray rings;
        rings.Add(ring);
        geom.Add("coordinates", rings);
        f.Add("geometry", geom);
        CPLJSONObject props;
        props.Add("index", i);
        props.Add("col", g.col(i));
        props.Add("row", g.row(i));
        props.Add("state", stateName(st));
        props.Add("contour", g.onContour(i));
        if (g.needsVisit(i)) {
            const geo::LonLat fp = frame.toGeo(g.flightPosition(i));
            props.Add("flight_lon", rounded(fp.lon));
            props.Add("flight_lat", rounded(fp.lat));
        } else {
            props.AddNull("flight_lon");
            props.AddNull("flight_lat");
        }
        f.Add("properties", props);
        sink((first ? "" : ",\n") + f.Format(CPLJSONObject::PrettyFormat::Plain));
        first = false;
    }
    sink("\n]}\n");
}

} // namespace

std::string gridToGeoJson(const grid::Grid& g, const geo::LocalFrame& frame, const GridExportOptions& opt) {
    std::string out;
    writeCollection(g, frame, opt, [&](const std::string& piece) { out += piece; });
    return out;
}

Status writeGridGeoJson(const grid::Grid& g, const geo::LocalFrame& frame, const std::string& path,
                        const GridExportOptions& opt) {
    // Written beside the target and renamed over it, so an existing file is never left half written.
    const std::string tmp = path + ".part";
    VSILFILE* f = VSIFOpenL(tmp.c_str(), "wb");
    if (!f)
        return makeError(ErrorCode::IoError, path + ": cannot write the grid: " + std::strerror(errno));
    bool written = true;
    writeCollection(g, frame, opt, [&](const std::string& piece) {
        written = written && VSIFWriteL(piece.data(), 1, piece.size(), f) == piece.size();
    });
    const bool closed = VSIFCloseL(f) == 0;
    if (!written || !closed) {
        VSIUnlink(tmp.c_str());
        return makeError(ErrorCode::IoError, path + ": cannot write the grid: the disk may be full");
    }
    if (VSIRename(tmp.c_str(), path.c_str()) != 0) {
        VSIUnlink(tmp.c_str());
        return makeError(ErrorCode::IoError, path + ": cannot write the grid: " + std::strerror(errno));
    }
    return {};
}

} // namespace pf::io
