#include "core/io/kml_export.h"

#include "core/io/waypoint_format_util.h"
#include "core/mission/aircraft_naming.h"

#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>

namespace pf::io {

namespace {

constexpr double kPi = 3.14159265358979323846;

using detail::FeaturePtr;


bool isColour(const std::string& c) {
    if (c.size() != 7 || c[0] != '#')
        return false;
    for (std::size_t i = 1; i < 7; ++i)
        if (!std::isxdigit(static_cast<unsigned char>(c[i])))
            return false;
    return true;
}


class KmlWriter {
public:
    KmlWriter(GDALDataset* ds, std::string path, bool libkml)
        : m_ds(ds), m_path(std::move(path)), m_libkml(libkml) {
        m_srs.SetWellKnownGeogCS("WGS84");
        m_srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    }

    void absolute(bool on) { m_absolute = on; }

    Status folder(const std::string& name) {
        // LIBKML writes a layer as a nested <Document> unless asked for a <Folder>.
        const char* const opts[] = {"FOLDER=YES", nullptr};
        m_layer = m_ds->CreateLayer(name.c_str(), &m_srs, wkbUnknown, const_cast<char**>(opts));
        if (!m_layer)
            return fail("folder " + name);
        for (const char* f : {"name", "description"}) {
            OGRFieldDefn def(f, OFTString);
            if (m_layer->CreateField(&def) != OGRERR_NONE)
                return fail(f);
        }
        // LIBKML turns these fields into <altitudeMode> and <extrude> of each placemark.
        if (m_libkml) {
            OGRFieldDefn mode("altitudeMode", OFTString);
            OGRFieldDefn extrude("extrude", OFTInteger);
            if (m_layer->CreateField(&mode) != OGRERR_NONE || m_layer->CreateField(&extrude) != OGRERR_NONE)
                return fail("altitude fields");
        }
        return {};
    }

    // A placemark; `inAir` ones are drawn at their altitude above the ground (the heights are
    // above take-off, which is the ground at home) or, after absolute(true), above sea level (a
    // route over a terrain model), `extrude` ones with a curtain down to the ground.
    Status add(const OGRGeometry& g, const std::string& name, const std::string& description,
               const std::string& style, bool inAir = false, bool extrude = false) {
        FeaturePtr f(OGRFeature::CreateFeature(m_layer->GetLayerDefn()));
        f->SetGeometry(&g);
        if (m_libkml) {
            f->SetField("altitudeMode", !inAir ? "clampToGround" : m_absolute ? "absolute" : "relativeToGround");
            f->SetField("extrude", extrude ? 1 : 0);
        }
        if (!name.empty())
            f->SetField("name", name.c_str());
        if (!description.empty())
            f->SetField("description", description.c_str());
        f->SetStyleString(style.c_str());
        if (m_layer->CreateFeature(f.get()) != OGRERR_NONE)
            return fail("placemark " + name);
        return {};
    }

private:
    Error fail(const std::string& what) const {
        return makeError(ErrorCode::IoError,
                         "cannot write " + m_path + ": " + detail::lastGdalError(what));
    }
    GDALDataset* m_ds;
    std::string m_path;
    bool m_libkml;
    bool m_absolute = false;
    OGRSpatialReference m_srs;
    OGRLayer* m_layer = nullptr;
};

// The trajectory has no heights of its own: each sample flies at the height of the nearest waypoint.
double nearestAltitude(const route::Route& r, geo::LonLat p) {
    double best = 1e300, alt = r.waypoints.empty() ? 0.0 : r.waypoints.front().altitudeM;
    const double k = std::cos(p.lat * kPi / 180.0);
    for (const auto& w : r.waypoints) {
        const double dx = (w.position.lon - p.lon) * k, dy = w.position.lat - p.lat;
        if (dx * dx + dy * dy < best) {
            best = dx * dx + dy * dy;
            alt = w.altitudeM;
        }
    }
    return alt;
}

std::string describe(const route::Waypoint& w, std::optional<double> homeElevation) {
    const std::string ground =
        homeElevation && w.groundM
            ? " (" + detail::formatNumber(*homeElevation + w.altitudeM - *w.groundM, 2) + " m above the ground, " +
                  detail::formatNumber(*homeElevation + w.altitudeM, 2) + " m above sea level)"
            : std::string();
    return std::string(detail::kindName(w.kind)) + ", altitude " +
           detail::formatNumber(w.altitudeM, 2) + " m above take-off" + ground + ", heading " +
           detail::formatNumber(detail::normaliseHeading(w.headingDeg), 2) + " deg";
}

} // namespace

Status writeKml(const ExportContext& ctx, const std::vector<std::size_t>& routeIndices,
                const std::string& path) {
    for (auto i : routeIndices)
        if (i >= ctx.routes.size())
            return makeError(ErrorCode::InvalidInput,
                             "there is no route " + std::to_string(i + 1) + " to export");
    GDALAllRegister();
    const bool libkml = GetGDALDriverManager()->GetDriverByName("LIBKML") != nullptr;
    // Routes over a terrain model are drawn at their altitudes above sea level (absolute), so that
    // they stand at their real height over any terrain the viewer shows.
    bool anyTerrain = false;
    for (auto i : routeIndices)
        anyTerrain = anyTerrain || ctx.routes[i].hasTerrain();
    // The plain KML driver has one altitude mode for the whole file: relative to the ground, so
    // the flight is in the air and the ground shapes (height 0) stay on the ground.
    auto ds = libkml ? detail::createVectorDataset("LIBKML", path)
                     : detail::createVectorDataset("KML", path,
                                                   {"NameField=name", "DescriptionField=description",
                                                    anyTerrain ? "AltitudeMode=absolute" : "AltitudeMode=relativeToGround"});
    if (!ds)
        return ds.error();
    KmlWriter w(ds->get(), path, libkml);

    // OGR style strings: the KML drivers turn them into <Style> elements with these colours.
    const std::string areaStyle = "PEN(c:#1e90ff,w:3px);BRUSH(fc:#1e90ff30)";
    const std::string zoneStyle = "PEN(c:#d00000,w:3px);BRUSH(fc:#d0000060)";
    if (auto st = w.folder(ctx.mission.name.empty() ? "Mission" : ctx.mission.name); !st)
        return st;
    if (!ctx.mission.area.outer.empty())
        if (auto st = w.add(*detail::toOgrPolygon(ctx.mission.area), "Area", "area of interest", areaStyle); !st)
            return st;
    for (const auto& z : ctx.mission.noFlyZones)
        if (auto st = w.add(*detail::toOgrPolygon(z.polygon), z.name.empty() ? "No-fly zone" : z.name,
                            "no-fly zone", zoneStyle);
            !st)
            return st;
    if (ctx.mission.home) {
        OGRPoint p(ctx.mission.home->lon, ctx.mission.home->lat);
        if (auto st = w.add(p, "Home", "take-off point", "SYMBOL(c:#000000,s:1.2)"); !st)
            return st;
    }

    std::size_t n = 0;
    for (auto ri : routeIndices) {
        const auto& r = ctx.routes[ri];
        const std::string label = ctx.routeLabel(ri);
        const auto* aircraft = ctx.aircraftFor(ri);
        const std::string colour = aircraft && isColour(aircraft->colour)
                                       ? aircraft->colour
                                       : mission::aircraftColour(n); // no valid colour of its own
        ++n;
        if (auto st = w.folder(label); !st)
            return st;
        const bool terrain = r.hasTerrain();
        w.absolute(terrain);
        const double base = terrain ? *r.homeElevationM : 0.0; // heights above take-off -> above sea level
        OGRLineString line;
        for (const auto& wp : r.waypoints)
            line.addPoint(wp.position.lon, wp.position.lat, base + wp.altitudeM);
        if (auto st = w.add(line, label + " path",
                            terrain ? "waypoint path, heights above sea level (terrain following)"
                                    : "waypoint path, heights above take-off",
                            "PEN(c:" + colour + ",w:2px)", true, true);
            !st)
            return st;
        if (ri < ctx.trajectories.size() && ctx.trajectories[ri].size() >= 2) {
            OGRLineString traj;
            for (const auto& p : ctx.trajectories[ri])
                traj.addPoint(p.lon, p.lat, base + nearestAltitude(r, p));
            if (auto st = w.add(traj, label + " trajectory", "smoothed flight trajectory",
                                "PEN(c:" + colour + ",w:1px,p:\"4px 4px\")", true, false);
                !st)
                return st;
        }
        const auto fp = ctx.footprintFor(ri);
        std::size_t photo = 0;
        for (std::size_t i = 0; i < r.waypoints.size(); ++i) {
            const auto& wp = r.waypoints[i];
            if (wp.kind != route::WaypointKind::Photo)
                continue;
            ++photo;
            char name[32];
            std::snprintf(name, sizeof name, "Photo %zu", photo);
            OGRPoint p(wp.position.lon, wp.position.lat, base + wp.altitudeM);
            if (auto st = w.add(p, name, describe(wp, r.homeElevationM), "SYMBOL(c:" + colour + ",s:0.6)", true, false);
                !st)
                return st;
            if (fp) {
                geo::GeoPolygon poly{footprintCorners(wp.position, wp.headingDeg, *fp), {}};
                if (auto st = w.add(*detail::toOgrPolygon(poly), std::string(name) + " footprint",
                                    "ground footprint of the photo",
                                    "PEN(c:" + colour + ",w:1px);BRUSH(fc:" + colour + "20)");
                    !st)
                    return st;
            }
        }
    }
    return detail::closeDataset(*ds, path);
}

} // namespace pf::io
