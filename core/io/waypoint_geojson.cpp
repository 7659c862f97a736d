#include "core/io/waypoint_geojson.h"

#include "core/geo/geodesic.h"
#include "core/io/waypoint_format_util.h"

#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <vector>

namespace pf::io {

namespace {

using detail::FeaturePtr;

using detail::toOgrPolygon;

geo::GeoRing fromOgrRing(const OGRLinearRing* r) {
    geo::GeoRing out;
    for (int i = 0; r && i < r->getNumPoints(); ++i)
        out.push_back({r->getX(i), r->getY(i)});
    if (out.size() > 1 && out.front() == out.back())
        out.pop_back();
    return out;
}

} // namespace

Status writeWaypointGeoJson(const ExportContext& ctx, const std::vector<std::size_t>& routeIndices,
                            const std::string& path) {
    for (auto i : routeIndices)
        if (i >= ctx.routes.size())
            return makeError(ErrorCode::InvalidInput,
                             "there is no route " + std::to_string(i + 1) + " to export");
    auto ds = detail::createVectorDataset("GeoJSON", path);
    if (!ds)
        return ds.error();
    OGRSpatialReference wgs84;
    wgs84.SetWellKnownGeogCS("WGS84");
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    // RFC 7946: no "crs" member, outer rings counter-clockwise and holes clockwise (OGR rewinds
    // them); coordinates keep 15 decimals so that reading gives back the same positions.
    const char* const layerOpts[] = {"WRITE_NAME=NO", "RFC7946=YES", "COORDINATE_PRECISION=15",
                                     nullptr};
    OGRLayer* layer =
        (*ds)->CreateLayer("waypoints", &wgs84, wkbUnknown, const_cast<char**>(layerOpts));
    if (!layer)
        return makeError(ErrorCode::IoError,
                         "cannot write " + path + ": " + detail::lastGdalError("no layer"));
    const std::pair<const char*, OGRFieldType> fields[] = {
        {"kind", OFTString},   {"name", OFTString},     {"aircraft", OFTString},
        {"index", OFTInteger}, {"altitude_m", OFTReal}, {"heading_deg", OFTReal}};
    // Routes over a terrain model also give, per waypoint, the ground under it above sea level, its
    // altitude above sea level and its height above the ground.
    bool terrain = false;
    for (auto ri : routeIndices)
        terrain = terrain || ctx.routes[ri].hasTerrain();
    std::vector<std::pair<const char*, OGRFieldType>> all(std::begin(fields), std::end(fields));
    if (terrain)
        for (const char* f : {"ground_m", "altitude_amsl_m", "height_above_ground_m"})
            all.push_back({f, OFTReal});
    for (const auto& [name, type] : all) {
        OGRFieldDefn def(name, type);
        if (layer->CreateField(&def) != OGRERR_NONE)
            return makeError(ErrorCode::IoError,
                             "cannot write " + path + ": " + detail::lastGdalError(name));
    }
    auto add = [&](OGRGeometry* g, const char* kind,
                   const std::string& name) -> Result<FeaturePtr> {
        FeaturePtr f(OGRFeature::CreateFeature(layer->GetLayerDefn()));
        f->SetGeometry(g);
        f->SetField("kind", kind);
        if (!name.empty())
            f->SetField("name", name.c_str());
        return f;
    };
    auto commit = [&](FeaturePtr& f) -> Status {
        if (layer->CreateFeature(f.get()) != OGRERR_NONE)
            return makeError(ErrorCode::IoError,
                             "cannot write " + path + ": " + detail::lastGdalError("feature"));
        return {};
    };
    if (!ctx.mission.area.outer.empty()) {
        auto g = toOgrPolygon(ctx.mission.area);
        auto f = add(g.get(), "area", ctx.mission.name);
        if (auto st = commit(*f); !st)
            return st;
    }
    for (const auto& z : ctx.mission.noFlyZones) {
        auto g = toOgrPolygon(z.polygon);
        auto f = add(g.get(), "no-fly zone", z.name);
        if (auto st = commit(*f); !st)
            return st;
    }
    if (ctx.mission.home) {
        OGRPoint p(ctx.mission.home->lon, ctx.mission.home->lat);
        auto f = add(&p, "home", "Home");
        if (auto st = commit(*f); !st)
            return st;
    }
    for (auto ri : routeIndices) {
        const auto& r = ctx.routes[ri];
        const std::string label = ctx.routeLabel(ri);
        OGRLineString line;
        for (const auto& w : r.waypoints)
            line.addPoint(w.position.lon, w.position.lat);
        auto pf = add(&line, "path", label);
        (*pf)->SetField("aircraft", label.c_str());
        if (auto st = commit(*pf); !st)
            return st;
        for (std::size_t i = 0; i < r.waypoints.size(); ++i) {
            const auto& w = r.waypoints[i];
            OGRPoint p(w.position.lon, w.position.lat);
            auto f = add(&p, detail::kindName(w.kind), "");
            (*f)->SetField("aircraft", label.c_str());
            (*f)->SetField("index", static_cast<int>(i + 1));
            (*f)->SetField("altitude_m", w.altitudeM);
            (*f)->SetField("heading_deg", detail::normaliseHeading(w.headingDeg));
            if (r.hasTerrain() && w.groundM) {
                const double amsl = *r.homeElevationM + w.altitudeM;
                (*f)->SetField("ground_m", *w.groundM);
                (*f)->SetField("altitude_amsl_m", amsl);
                (*f)->SetField("height_above_ground_m", amsl - *w.groundM);
            }
            if (auto st = commit(*f); !st)
                return st;
        }
    }
    return detail::closeDataset(*ds, path);
}

Result<ImportedWaypoints> readWaypointGeoJson(const std::string& path) {
    // OGR's own message for broken JSON has no line number; check the syntax first.
    auto text = detail::readTextFile(path);
    if (!text)
        return text.error();
    auto json = detail::parseJson(*text, path);
    if (!json)
        return json.error();
    auto ds = detail::openVectorDataset(path, "GeoJSON");
    if (!ds)
        return ds.error();
    OGRLayer* layer = (*ds)->GetLayerCount() > 0 ? (*ds)->GetLayer(0) : nullptr;
    if (!layer)
        return makeError(ErrorCode::ParseError, path + ": the file has no features");

    struct Pending {
        route::Waypoint w;
        int index = -1;
        bool hasHeading = false;
    };
    std::vector<std::string> order;
    std::vector<std::vector<Pending>> groups;
    ImportedWaypoints out;
    std::size_t k = 0;
    for (auto& f : *layer) {
        ++k;
        const std::string where =
            path + ": feature " + std::to_string(k) + " (features[" + std::to_string(k - 1) + "])";
        const OGRGeometry* g = f->GetGeometryRef();
        const int kindIdx = f->GetFieldIndex("kind");
        const std::string kind =
            kindIdx >= 0 && f->IsFieldSetAndNotNull(kindIdx) ? f->GetFieldAsString(kindIdx) : "";
        const auto wpKind =
            kind.empty() ? std::optional(route::WaypointKind::Photo) : detail::kindFromName(kind);
        if (!g)
            continue;
        const auto type = wkbFlatten(g->getGeometryType());
        if (kind == "no-fly zone" && type == wkbPolygon) {
            const auto* p = g->toPolygon();
            mission::NoFlyZone z;
            const int n = f->GetFieldIndex("name");
            z.name = n >= 0 && f->IsFieldSetAndNotNull(n) ? f->GetFieldAsString(n)
                                                          : "No-fly zone " + std::to_string(k);
            z.polygon.outer = fromOgrRing(p->getExteriorRing());
            for (int h = 0; h < p->getNumInteriorRings(); ++h)
                z.polygon.holes.push_back(fromOgrRing(p->getInteriorRing(h)));
            out.noFlyZones.push_back(std::move(z));
            continue;
        }
        if (kind == "home" && type == wkbPoint) {
            out.home = geo::LonLat{g->toPoint()->getX(), g->toPoint()->getY()};
            continue;
        }
        if (type != wkbPoint || !wpKind)
            continue; // paths, the area and anything else are drawn, not edited
        const auto* p = g->toPoint();
        Pending pw;
        pw.w.position = {p->getX(), p->getY()};
        pw.w.kind = *wpKind;
        const int alt = f->GetFieldIndex("altitude_m");
        if (alt >= 0 && f->IsFieldSetAndNotNull(alt)) {
            auto v = detail::parseNumber(f->GetFieldAsString(alt));
            if (!v)
                return makeError(ErrorCode::ParseError,
                                 where + ": property \"altitude_m\" is not a number");
            pw.w.altitudeM = *v;
        } else if (p->Is3D()) {
            pw.w.altitudeM = p->getZ();
        } else {
            return makeError(ErrorCode::ParseError, where + ": missing property \"altitude_m\"");
        }
        if (const std::string why =
                detail::waypointPositionProblem(pw.w.position.lon, pw.w.position.lat, pw.w.altitudeM);
            !why.empty())
            return makeError(ErrorCode::ParseError, where + ": " + why);
        const int hdg = f->GetFieldIndex("heading_deg");
        if (hdg >= 0 && f->IsFieldSetAndNotNull(hdg)) {
            auto v = detail::parseNumber(f->GetFieldAsString(hdg));
            if (!v)
                return makeError(ErrorCode::ParseError,
                                 where + ": property \"heading_deg\" is not a number");
            pw.w.headingDeg = detail::normaliseHeading(*v);
            pw.hasHeading = true;
        }
        const int idx = f->GetFieldIndex("index");
        if (idx >= 0 && f->IsFieldSetAndNotNull(idx))
            pw.index = f->GetFieldAsInteger(idx);
        const int ac = f->GetFieldIndex("aircraft");
        const std::string aircraft =
            ac >= 0 && f->IsFieldSetAndNotNull(ac) ? f->GetFieldAsString(ac) : "";
        auto it = std::find(order.begin(), order.end(), aircraft);
        if (it == order.end()) {
            order.push_back(aircraft);
            groups.emplace_back();
            it = order.end() - 1;
        }
        groups[static_cast<std::size_t>(it - order.begin())].push_back(pw);
    }
    for (std::size_t gi = 0; gi < groups.size(); ++gi) {
        auto& grp = groups[gi];
        if (std::all_of(grp.begin(), grp.end(), [](const Pending& p) { return p.index >= 0; }))
            std::stable_sort(grp.begin(), grp.end(),
                             [](const Pending& a, const Pending& b) { return a.index < b.index; });
        route::Route r;
        r.aircraft = order[gi];
        r.home = out.home;
        for (std::size_t i = 0; i < grp.size(); ++i) {
            route::Waypoint w = grp[i].w;
            if (!grp[i].hasHeading) {
                if (i + 1 < grp.size())
                    w.headingDeg = geo::initialBearingDeg(w.position, grp[i + 1].w.position);
                else if (i > 0)
                    w.headingDeg = r.waypoints.back().headingDeg;
            }
            r.waypoints.push_back(w);
        }
        out.routes.push_back(std::move(r));
    }
    if (out.routes.empty())
        return makeError(ErrorCode::ParseError,
                         path + ": the file has no waypoint (point) features");
    return out;
}

} // namespace pf::io
