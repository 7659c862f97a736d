#include "core/io/gpx.h"

#include "core/geo/geodesic.h"
#include "core/io/waypoint_format_util.h"

#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <cstdlib>
#include <cstring>

namespace pf::io {

namespace {

using detail::DatasetPtr;

using detail::FeaturePtr;

std::string xmlEscape(const std::string& in) {
    std::string out;
    for (char c : in) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    }
    return out;
}

std::string pointName(const std::string& label, std::size_t i) {
    char buf[32];
    std::snprintf(buf, sizeof buf, " %03zu", i + 1);
    return label + buf;
}

void setIfField(OGRFeature& f, const char* name, const std::string& value) {
    if (f.GetFieldIndex(name) >= 0)
        f.SetField(name, value.c_str());
}

Status addField(OGRLayer* layer, const char* name, OGRFieldType type, const std::string& path) {
    if (layer->FindFieldIndex(name, TRUE) >= 0)
        return {};
    OGRFieldDefn def(name, type);
    if (layer->CreateField(&def) != OGRERR_NONE)
        return makeError(ErrorCode::IoError,
                         "cannot write " + path + ": " +
                             detail::lastGdalError("field " + std::string(name)));
    return {};
}

} // namespace

Status writeGpx(const ExportContext& ctx, const std::vector<std::size_t>& routeIndices,
                const std::string& path) {
    for (auto i : routeIndices)
        if (i >= ctx.routes.size())
            return makeError(ErrorCode::InvalidInput,
                             "there is no route " + std::to_string(i + 1) + " to export");
    auto ds = detail::createVectorDataset("GPX", path, {"GPX_USE_EXTENSIONS=YES"});
    if (!ds)
        return ds.error();
    OGRSpatialReference wgs84;
    wgs84.SetWellKnownGeogCS("WGS84");
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);

    // GPX wants every <wpt> before the first <rte>: waypoints of all routes first.
    OGRLayer* wpts = (*ds)->CreateLayer("waypoints", &wgs84, wkbPoint, nullptr);
    if (!wpts)
        return makeError(ErrorCode::IoError, "cannot write " + path + ": " +
                                                 detail::lastGdalError("no waypoint layer"));
    for (const char* f : {"heading", "aircraft"})
        if (auto st = addField(wpts, f, std::string(f) == "heading" ? OFTReal : OFTString, path);
            !st)
            return st;
    // Over a terrain model <ele> is what GPX means by it, metres above sea level (the home's elevation
    // plus the altitude above take-off); without one, the altitude above take-off as before.
    bool amsl = !routeIndices.empty();
    for (auto ri : routeIndices)
        amsl = amsl && ctx.routes[ri].hasTerrain();
    auto base = [&](const route::Route& r) { return amsl ? *r.homeElevationM : 0.0; };
    std::optional<double> sharedHome;
    bool oneHome = amsl;
    for (auto ri : routeIndices) {
        if (!amsl)
            break;
        if (sharedHome && std::abs(*sharedHome - *ctx.routes[ri].homeElevationM) > 1e-6)
            oneHome = false;
        sharedHome = ctx.routes[ri].homeElevationM;
    }
    for (auto ri : routeIndices) {
        const auto& r = ctx.routes[ri];
        const std::string label = ctx.routeLabel(ri);
        for (std::size_t i = 0; i < r.waypoints.size(); ++i) {
            const auto& w = r.waypoints[i];
            FeaturePtr f(OGRFeature::CreateFeature(wpts->GetLayerDefn()));
            OGRPoint pt(w.position.lon, w.position.lat);
            f->SetGeometry(&pt);
            f->SetField("ele", w.altitudeM + base(r));
            setIfField(*f, "name", pointName(label, i));
            setIfField(*f, "type", detail::kindName(w.kind));
            f->SetField("heading", detail::normaliseHeading(w.headingDeg));
            f->SetField("aircraft", label.c_str());
            if (wpts->CreateFeature(f.get()) != OGRERR_NONE)
                return makeError(ErrorCode::IoError,
                                 "cannot write " + path + ": " + detail::lastGdalError("waypoint"));
        }
    }
    OGRLayer* rpts = (*ds)->CreateLayer("route_points", &wgs84, wkbPoint, nullptr);
    if (!rpts)
        return makeError(ErrorCode::IoError,
                         "cannot write " + path + ": " + detail::lastGdalError("no route layer"));
    if (auto st = addField(rpts, "heading", OFTReal, path); !st)
        return st;
    int routeFid = 0;
    for (auto ri : routeIndices) {
        const auto& r = ctx.routes[ri];
        const std::string label = ctx.routeLabel(ri);
        for (std::size_t i = 0; i < r.waypoints.size(); ++i) {
            const auto& w = r.waypoints[i];
            FeaturePtr f(OGRFeature::CreateFeature(rpts->GetLayerDefn()));
            OGRPoint pt(w.position.lon, w.position.lat);
            f->SetGeometry(&pt);
            f->SetField("route_fid", routeFid);
            setIfField(*f, "route_name", label);
            f->SetField("ele", w.altitudeM + base(r));
            setIfField(*f, "name", pointName(label, i));
            setIfField(*f, "type", detail::kindName(w.kind));
            f->SetField("heading", detail::normaliseHeading(w.headingDeg));
            if (rpts->CreateFeature(f.get()) != OGRERR_NONE)
                return makeError(ErrorCode::IoError, "cannot write " + path + ": " +
                                                         detail::lastGdalError("route point"));
        }
        ++routeFid;
    }
    if (auto st = detail::closeDataset(*ds, path); !st)
        return st;
    // GPX's <ele> is normally metres above sea level; say in the metadata what these are. OGR's
    // GPX driver writes no <metadata>, so it is put in as the first child of <gpx>, as GPX 1.1
    // requires.
    auto text = detail::readTextFile(path);
    if (!text)
        return text.error();
    const std::string meta = "<name>" +
                             xmlEscape(ctx.mission.name.empty() ? "Photoflight mission" : ctx.mission.name) +
                             "</name><desc>" +
                             (amsl ? std::string(kGpxAmslNote) +
                                         (oneHome ? " " + std::string(kGpxTakeOffMarker) +
                                                        detail::formatNumber(*sharedHome, 3) + " m."
                                                  : std::string())
                                   : std::string(kGpxElevationNote)) +
                             "</desc>";
    const auto open = text->find("<gpx");
    const auto gpxEnd = open == std::string::npos ? open : text->find('>', open);
    if (gpxEnd == std::string::npos)
        return makeError(ErrorCode::IoError, "cannot write " + path + ": GDAL wrote no <gpx> element");
    // GDAL may have written <metadata><bounds/></metadata>: name and desc come first in it.
    const auto m = text->find("<metadata>", gpxEnd);
    if (m != std::string::npos && text->find("<wpt", gpxEnd) > m)
        text->insert(m + 10, meta);
    else
        text->insert(gpxEnd + 1, "\n<metadata>" + meta + "</metadata>");
    return detail::writeTextFile(path, *text);
}

namespace {

// The line of the n-th (1-based) element `tag` in the file's text, or 0: OGR does not say where a
// feature came from, but people fix files by line.
std::size_t lineOfElement(const std::string& text, const std::string& tag, std::size_t n) {
    std::size_t pos = 0;
    for (std::size_t k = 0; k < n; ++k) {
        pos = text.find("<" + tag, k == 0 ? 0 : pos + 1);
        while (pos != std::string::npos && pos + tag.size() + 1 < text.size() &&
               std::isalnum(static_cast<unsigned char>(text[pos + tag.size() + 1])))
            pos = text.find("<" + tag, pos + 1); // <rtept> is not <rte>
        if (pos == std::string::npos)
            return 0;
    }
    return 1 + static_cast<std::size_t>(
                   std::count(text.begin(), text.begin() + static_cast<long>(pos), '\n'));
}

// Headings for points that had none: towards the next point (the last keeps the one before).
void fillHeadings(route::Route& r, const std::vector<bool>& hasHeading) {
    for (std::size_t i = 0; i < r.waypoints.size(); ++i) {
        if (hasHeading[i])
            continue;
        if (i + 1 < r.waypoints.size())
            r.waypoints[i].headingDeg =
                geo::initialBearingDeg(r.waypoints[i].position, r.waypoints[i + 1].position);
        else if (i > 0)
            r.waypoints[i].headingDeg = r.waypoints[i - 1].headingDeg;
    }
}

Result<route::Waypoint> readPoint(OGRFeature& f, const std::string& path, std::string what,
                                  bool& hasHeading) {
    const OGRGeometry* g = f.GetGeometryRef();
    if (!g || wkbFlatten(g->getGeometryType()) != wkbPoint)
        return makeError(ErrorCode::ParseError, path + ": " + what + " has no position");
    const auto* p = g->toPoint();
    route::Waypoint w;
    w.position = {p->getX(), p->getY()};
    const int ele = f.GetFieldIndex("ele");
    if (ele < 0 || !f.IsFieldSetAndNotNull(ele))
        return makeError(ErrorCode::ParseError,
                         path + ": " + what + " has no <ele> (altitude above take-off)");
    w.altitudeM = f.GetFieldAsDouble(ele);
    if (const std::string why = detail::waypointPositionProblem(w.position.lon, w.position.lat, w.altitudeM);
        !why.empty())
        return makeError(ErrorCode::ParseError, path + ": " + what + ": " + why);
    const int hdg = f.GetFieldIndex("ogr_heading");
    hasHeading = hdg >= 0 && f.IsFieldSetAndNotNull(hdg);
    if (hasHeading) {
        auto v = detail::parseNumber(f.GetFieldAsString(hdg));
        if (!v)
            return makeError(ErrorCode::ParseError, path + ": " + what + ": the heading \"" +
                                                        std::string(f.GetFieldAsString(hdg)) +
                                                        "\" is not a number");
        w.headingDeg = detail::normaliseHeading(*v);
    }
    const int type = f.GetFieldIndex("type");
    if (type >= 0 && f.IsFieldSetAndNotNull(type))
        w.kind =
            detail::kindFromName(f.GetFieldAsString(type)).value_or(route::WaypointKind::Photo);
    return w;
}

} // namespace

Result<ImportedWaypoints> readGpx(const std::string& path) {
    auto ds = detail::openVectorDataset(path, "GPX");
    if (!ds)
        return ds.error();
    auto text = detail::readTextFile(path);
    if (!text)
        return text.error();
    auto where = [&](const char* tag, const char* what, std::size_t k) {
        const std::size_t line = lineOfElement(*text, tag, k);
        return (line ? "line " + std::to_string(line) + ": " : std::string()) + what + " " +
               std::to_string(k);
    };
    ImportedWaypoints out;
    CPLErrorReset();
    CPLPushErrorHandler(CPLQuietErrorHandler);
    struct Pop {
        ~Pop() { CPLPopErrorHandler(); }
    } pop;

    std::vector<std::string> routeNames;
    if (OGRLayer* routes = (*ds)->GetLayerByName("routes")) {
        for (auto& f : *routes) {
            const int n = f->GetFieldIndex("name");
            routeNames.push_back(n >= 0 && f->IsFieldSetAndNotNull(n) ? f->GetFieldAsString(n)
                                                                      : "");
        }
    }
    std::map<int, std::size_t> routeOf; // route_fid -> index in out.routes
    std::vector<std::vector<bool>> headings;
    if (OGRLayer* rpts = (*ds)->GetLayerByName("route_points")) {
        std::size_t k = 0;
        for (auto& f : *rpts) {
            ++k;
            const int fid = f->GetFieldAsInteger("route_fid");
            auto [it, inserted] = routeOf.emplace(fid, out.routes.size());
            if (inserted) {
                route::Route r;
                r.aircraft = fid >= 0 && static_cast<std::size_t>(fid) < routeNames.size()
                                 ? routeNames[fid]
                                 : "";
                out.routes.push_back(r);
                headings.emplace_back();
            }
            bool has = false;
            auto w = readPoint(*f, path, where("rtept", "route point", k), has);
            if (!w)
                return w.error();
            out.routes[it->second].waypoints.push_back(*w);
            headings[it->second].push_back(has);
        }
    }
    if (out.routes.empty()) {
        if (OGRLayer* wpts = (*ds)->GetLayerByName("waypoints")) {
            route::Route r;
            std::vector<bool> has;
            std::size_t k = 0;
            for (auto& f : *wpts) {
                bool h = false;
                auto w = readPoint(*f, path, where("wpt", "waypoint", ++k), h);
                if (!w)
                    return w.error();
                r.waypoints.push_back(*w);
                has.push_back(h);
            }
            if (!r.waypoints.empty()) {
                out.routes.push_back(r);
                headings.push_back(has);
            }
        }
    }
    if (CPLGetLastErrorType() >= CE_Failure)
        return makeError(ErrorCode::ParseError,
                         path + ": " + detail::lastGdalError("the GPX could not be read"));
    if (out.routes.empty())
        return makeError(ErrorCode::ParseError, path + ": the file has no route and no waypoint");
    for (std::size_t i = 0; i < out.routes.size(); ++i)
        fillHeadings(out.routes[i], headings[i]);
    // A file written over a terrain model holds elevations above sea level and names the take-off's.
    if (const auto at = text->find(kGpxTakeOffMarker); at != std::string::npos) {
        const double home = std::strtod(text->c_str() + at + std::strlen(kGpxTakeOffMarker), nullptr);
        for (auto& r : out.routes) {
            r.homeElevationM = home;
            for (auto& w : r.waypoints)
                w.altitudeM -= home;
        }
    }
    return out;
}

} // namespace pf::io
