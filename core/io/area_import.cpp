// Area, no-fly-zone and line import through OGR: any supported vector format and CRS -> WGS84 2D
// polygons and lines.
#include "core/io/area_import.h"

#include "core/io/waypoint_format_util.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_string.h>
#include <cpl_vsi.h>
#include <gdal.h>
#include <gdal_priv.h>
#include <ogr_geometry.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <mutex>

namespace pf::io {

namespace {

// GDAL's process-wide handler: drop messages (they reach the user as Result errors through
// GdalErrorScope), except when GDAL debugging is switched on with CPL_DEBUG.
void CPL_STDCALL quietHandler(CPLErr cls, CPLErrorNum num, const char* msg) {
    if (CPLTestBool(CPLGetConfigOption("CPL_DEBUG", "NO")))
        CPLDefaultErrorHandler(cls, num, msg);
}

void CPL_STDCALL scopeHandler(CPLErr cls, CPLErrorNum /*num*/, const char* msg) {
    if (cls < CE_Failure)
        return;
    if (auto* scope = static_cast<detail::GdalErrorScope*>(CPLGetErrorHandlerUserData()))
        scope->record(msg);
}

struct DatasetCloser {
    void operator()(GDALDataset* ds) const { GDALClose(ds); }
};
using DatasetPtr = std::unique_ptr<GDALDataset, DatasetCloser>;

// The formats this importer promises, by driver name, with the words used in messages.
struct Format {
    const char* driver;
    const char* label;
};
constexpr Format kFormats[] = {{"GeoJSON", "GeoJSON"},      {"KML", "KML"},        {"LIBKML", "KML"},
                               {"ESRI Shapefile", "Shapefile"}, {"GPKG", "GeoPackage"}, {"GML", "GML"}};

const char* labelForExtension(const std::string& ext) {
    if (ext == ".geojson" || ext == ".json")
        return "GeoJSON";
    if (ext == ".kml")
        return "KML";
    if (ext == ".shp")
        return "Shapefile";
    if (ext == ".gpkg")
        return "GeoPackage";
    if (ext == ".gml" || ext == ".xml")
        return "GML";
    return nullptr;
}

const Format* formatForDriver(const char* driver) {
    for (const auto& f : kFormats)
        if (EQUAL(f.driver, driver))
            return &f;
    return nullptr;
}

constexpr const char* kSupported = "GeoJSON (.geojson), KML (.kml), Shapefile (.shp), GeoPackage (.gpkg) or GML (.gml)";

geo::GeoRing toGeoRing(const OGRLinearRing* ring) {
    geo::GeoRing out;
    if (!ring)
        return out;
    const int n = ring->getNumPoints();
    out.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        const geo::LonLat p{ring->getX(i), ring->getY(i)};
        if (out.empty() || out.back() != p) // repeated vertices carry no shape
            out.push_back(p);
    }
    if (out.size() > 1 && out.front() == out.back())
        out.pop_back(); // rings are stored open
    return out;
}

void collectPolygons(const OGRGeometry* g, std::vector<geo::GeoPolygon>& out, int& others) {
    if (!g || g->IsEmpty())
        return;
    const auto type = wkbFlatten(g->getGeometryType());
    if (type == wkbPolygon) {
        const auto* poly = g->toPolygon();
        geo::GeoPolygon p;
        p.outer = toGeoRing(poly->getExteriorRing());
        for (int i = 0; i < poly->getNumInteriorRings(); ++i)
            p.holes.push_back(toGeoRing(poly->getInteriorRing(i)));
        out.push_back(std::move(p));
    } else if (OGR_GT_IsSubClassOf(type, wkbGeometryCollection)) {
        for (const auto* part : *g->toGeometryCollection())
            collectPolygons(part, out, others);
    } else {
        ++others;
    }
}

// Longitude/latitude plausibility of a whole layer's extent.
bool plausibleLonLat(const OGREnvelope& e) {
    return e.MinX >= -180.0 && e.MaxX <= 180.0 && e.MinY >= -90.0 && e.MaxY <= 90.0;
}

std::string featureName(OGRFeature& f, OGRLayer& layer) {
    for (const char* field : {"name", "Name", "NAME"}) {
        const int idx = f.GetFieldIndex(field);
        if (idx >= 0 && f.IsFieldSetAndNotNull(idx)) {
            std::string v = f.GetFieldAsString(idx);
            if (!v.empty())
                return v;
        }
    }
    return std::string(layer.GetName()) + " #" + std::to_string(f.GetFID());
}

std::string featureRole(OGRFeature& f) {
    const int idx = f.GetFieldIndex("role");
    if (idx < 0 || !f.IsFieldSetAndNotNull(idx))
        return {};
    std::string v = f.GetFieldAsString(idx);
    std::transform(v.begin(), v.end(), v.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return v;
}

} // namespace

namespace detail {

GdalErrorScope::GdalErrorScope() { CPLPushErrorHandlerEx(scopeHandler, this); }
GdalErrorScope::~GdalErrorScope() { CPLPopErrorHandler(); }
void GdalErrorScope::record(const char* message) {
    if (m_firstError.empty() && message)
        m_firstError = message;
}

} // namespace detail

void initGdal() {
    static std::once_flag once;
    std::call_once(once, [] {
        CPLSetErrorHandler(quietHandler);
        GDALAllRegister();
    });
}

namespace {

// The formats a line may come from besides those of areas: GPS tracks and routes.
constexpr Format kGpx{"GPX", "GPX"};
constexpr const char* kSupportedLines = "GeoJSON (.geojson), KML (.kml), GPX (.gpx), Shapefile "
                                        "(.shp), GeoPackage (.gpkg) or GML (.gml)";

// An opened vector file with the words for its format.
struct OpenedFile {
    DatasetPtr ds;
    std::string formatLabel;
};

// Opens `path` with one of the documented drivers (GPX too with `lines`). Errors name the file and
// the problem: missing, a folder, empty, unreadable, unsupported or damaged.
Result<OpenedFile> openVectorFile(const std::string& path, bool lines,
                                  detail::GdalErrorScope& errors) {
    VSIStatBufL st;
    if (VSIStatL(path.c_str(), &st) != 0)
        return makeError(ErrorCode::IoError, path + ": cannot import: the file does not exist");
    if (VSI_ISDIR(st.st_mode))
        return makeError(ErrorCode::IoError, path + ": cannot import: this is a folder, not a file");
    if (st.st_size == 0)
        return makeError(ErrorCode::ParseError, path + ": cannot read the file: it is empty (0 bytes)");
    if (VSILFILE* f = VSIFOpenL(path.c_str(), "rb"))
        VSIFCloseL(f);
    else
        return makeError(ErrorCode::IoError, path + ": cannot read the file: " + std::strerror(errno));

    const std::string ext = detail::extensionOf(path);
    const char* supported = lines ? kSupportedLines : kSupported;
    const auto known = [&](const char* driver) {
        return formatForDriver(driver) || (lines && EQUAL(driver, kGpx.driver));
    };
    const auto labelFor = [&](const std::string& e) -> const char* {
        return lines && e == ".gpx" ? kGpx.label : labelForExtension(e);
    };

    // Refuse formats outside the documented list before opening: GDAL would read many more, but only
    // these are tested and documented.
    GDALDriverH identified = GDALIdentifyDriverEx(path.c_str(), GDAL_OF_VECTOR, nullptr, nullptr);
    if (identified && !known(GDALGetDriverShortName(identified)))
        return makeError(ErrorCode::Unsupported, path + ": unsupported format (" +
                                                     GDALGetDriverLongName(identified) +
                                                     "); expected " + supported);
    if (!identified && !labelFor(ext))
        return makeError(ErrorCode::Unsupported,
                         path + ": unsupported or unrecognised format; expected " + supported);

    const char* const drivers[] = {"GeoJSON", "KML", "LIBKML", "ESRI Shapefile", "GPKG", "GML", nullptr};
    const char* const lineDrivers[] = {"GeoJSON", "KML", "LIBKML", "ESRI Shapefile",
                                       "GPKG",    "GML", "GPX",    nullptr};
    // GML: do not leave a .gfs schema file beside the user's file.
    const char* const openOptions[] = {"WRITE_GFS=NO", nullptr};
    const bool isGml = (identified && EQUAL(GDALGetDriverShortName(identified), "GML")) || ext == ".gml";
    DatasetPtr ds(static_cast<GDALDataset*>(
        GDALOpenEx(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, lines ? lineDrivers : drivers,
                   isGml ? openOptions : nullptr, nullptr)));
    if (!ds) {
        const char* label = labelFor(ext);
        std::string why = errors.firstError();
        return makeError(ErrorCode::ParseError,
                         path + ": cannot read the file: it is damaged or not a valid " +
                             (label ? label : "GeoJSON, KML, Shapefile, GeoPackage or GML") + " file" +
                             (why.empty() ? std::string() : " (" + why + ")"));
    }
    const Format* format = formatForDriver(ds->GetDriverName());
    std::string label = format                                    ? format->label
                        : EQUAL(ds->GetDriverName(), kGpx.driver) ? kGpx.label
                                                                  : ds->GetDriverName();
    return OpenedFile{std::move(ds), std::move(label)};
}

// The transformation of a layer's coordinates to WGS84 (null when it has no CRS), after checking
// that coordinates without a CRS look like longitude/latitude.
Result<std::unique_ptr<OGRCoordinateTransformation>>
layerToWgs84(const std::string& path, OGRLayer& layer, const std::string& formatLabel,
             const OGRSpatialReference& wgs84) {
    std::unique_ptr<OGRCoordinateTransformation> toWgs84;
    const OGRSpatialReference* layerSrs = layer.GetSpatialRef();
    if (layerSrs) {
        std::unique_ptr<OGRSpatialReference> src(layerSrs->Clone());
        src->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
        toWgs84.reset(OGRCreateCoordinateTransformation(src.get(), &wgs84));
        if (!toWgs84) {
            const char* srsName = src->GetName();
            return makeError(ErrorCode::Unsupported,
                             path + ": layer '" + layer.GetName() +
                                 "': cannot convert its coordinate system (" +
                                 (srsName ? srsName : "unnamed") + ") to WGS84 longitude/latitude");
        }
    }
    // No CRS (GeoJSON and KML without one are WGS84 by definition, so OGR says WGS84): the
    // coordinates must at least look like longitude/latitude. Projected metres (UTM) are one
    // request for the CRS, not a list of out-of-range vertices.
    if (!layerSrs || layerSrs->IsGeographic()) {
        OGREnvelope env;
        if (layer.GetExtent(&env, TRUE) == OGRERR_NONE && !plausibleLonLat(env)) {
            char buf[200];
            std::snprintf(buf, sizeof buf, "x %.0f..%.0f, y %.0f..%.0f", env.MinX, env.MaxX,
                          env.MinY, env.MaxY);
            const bool wgs84ByDefinition =
                formatLabel == "GeoJSON" || formatLabel == "KML" || formatLabel == "GPX";
            return makeError(
                ErrorCode::InvalidInput,
                path + ": layer '" + layer.GetName() + "' has " +
                    (layerSrs ? "longitude/latitude as its coordinate reference system but"
                              : "no coordinate reference system and") +
                    " its coordinates (" + buf + ") are not longitude/latitude; " +
                    (wgs84ByDefinition
                         ? "a " + formatLabel +
                               " file without a CRS must be in WGS84: "
                               "reproject it (e.g. ogr2ogr -t_srs EPSG:4326) or give it its CRS"
                         : std::string("save the file with its CRS (for a Shapefile, the .prj "
                                       "file beside it)")));
        }
    }
    return toWgs84;
}

// Every feature's geometry of every layer, linear, 2D and in WGS84, handed to `visit` with its
// feature and layer. Counts the features read.
Status forEachGeometry(const std::string& path, const OpenedFile& file,
                       const std::function<void(OGRFeature&, OGRLayer&, const OGRGeometry&)>& visit,
                       int& features) {
    OGRSpatialReference wgs84;
    wgs84.SetWellKnownGeogCS("WGS84");
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    for (OGRLayer* layer : file.ds->GetLayers()) {
        auto toWgs84 = layerToWgs84(path, *layer, file.formatLabel, wgs84);
        if (!toWgs84)
            return toWgs84.error();
        layer->ResetReading();
        for (auto& feature : *layer) {
            ++features;
            const OGRGeometry* geom = feature->GetGeometryRef();
            if (!geom)
                continue;
            std::unique_ptr<OGRGeometry> g(geom->hasCurveGeometry() ? geom->getLinearGeometry() : geom->clone());
            if (!g)
                continue;
            g->flattenTo2D();
            if (*toWgs84 && g->transform(toWgs84->get()) != OGRERR_NONE)
                return makeError(ErrorCode::InvalidInput, path + ": feature '" + featureName(*feature, *layer) +
                                                              "' could not be converted to WGS84");
            visit(*feature, *layer, *g);
        }
    }
    return {};
}

void collectLines(const OGRGeometry* g, std::vector<geo::GeoRing>& out, int& others) {
    if (!g || g->IsEmpty())
        return;
    const auto type = wkbFlatten(g->getGeometryType());
    if (type == wkbLineString) {
        const auto* l = g->toLineString();
        geo::GeoRing line;
        for (int i = 0; i < l->getNumPoints(); ++i) {
            const geo::LonLat p{l->getX(i), l->getY(i)};
            if (line.empty() || line.back() != p)
                line.push_back(p);
        }
        out.push_back(std::move(line));
    } else if (OGR_GT_IsSubClassOf(type, wkbGeometryCollection)) {
        for (const auto* part : *g->toGeometryCollection())
            collectLines(part, out, others);
    } else {
        ++others;
    }
}

// Why an import found nothing to import, or nothing: a driver that stumbled half-way (importing
// the features read so far would silently drop the rest), or no shape of the `kind` asked for.
Status importOutcome(const std::string& path, const detail::GdalErrorScope& errors, bool found,
                     int features, int others, const char* kind, const char* otherKinds) {
    if (!errors.firstError().empty())
        return makeError(ErrorCode::ParseError,
                         path + ": cannot read the file: " + errors.firstError());
    if (found)
        return {};
    const std::string what = features == 0
                                 ? "it has no features"
                                 : "it has " + std::to_string(features) + " feature(s)" +
                                       (others > 0 ? std::string(", only ") + otherKinds
                                                   : std::string(", none with a ") + kind);
    return makeError(ErrorCode::InvalidGeometry, path + ": no " + kind + " to import: " + what);
}

} // namespace

Result<std::vector<ImportedPolygon>> importPolygons(const std::string& path) {
    initGdal();
    detail::GdalErrorScope errors;
    auto file = openVectorFile(path, false, errors);
    if (!file)
        return file.error();
    std::vector<ImportedPolygon> out;
    int otherGeometries = 0;
    int features = 0;
    const auto visit = [&](OGRFeature& feature, OGRLayer& layer, const OGRGeometry& g) {
        std::vector<geo::GeoPolygon> polys;
        collectPolygons(&g, polys, otherGeometries);
        const std::string name = featureName(feature, layer);
        const std::string role = featureRole(feature);
        for (std::size_t i = 0; i < polys.size(); ++i) {
            ImportedPolygon ip;
            ip.name = polys.size() == 1 ? name : name + " (part " + std::to_string(i + 1) + ")";
            ip.layer = layer.GetName();
            ip.role = role;
            ip.polygon = std::move(polys[i]);
            out.push_back(std::move(ip));
        }
    };
    if (auto st = forEachGeometry(path, *file, visit, features); !st)
        return st.error();
    if (auto st = importOutcome(path, errors, !out.empty(), features, otherGeometries, "polygon",
                                "points or lines");
        !st)
        return st.error();
    return out;
}

Result<std::vector<ImportedLine>> importLines(const std::string& path) {
    initGdal();
    detail::GdalErrorScope errors;
    auto file = openVectorFile(path, true, errors);
    if (!file)
        return file.error();
    std::vector<ImportedLine> out;
    int otherGeometries = 0;
    int features = 0;
    const auto visit = [&](OGRFeature& feature, OGRLayer& layer, const OGRGeometry& g) {
        std::vector<geo::GeoRing> lines;
        collectLines(&g, lines, otherGeometries);
        const std::string name = featureName(feature, layer);
        for (std::size_t i = 0; i < lines.size(); ++i)
            out.push_back(
                {lines.size() == 1 ? name : name + " (part " + std::to_string(i + 1) + ")",
                 layer.GetName(), std::move(lines[i])});
    };
    if (auto st = forEachGeometry(path, *file, visit, features); !st)
        return st.error();
    if (auto st = importOutcome(path, errors, !out.empty(), features, otherGeometries, "line",
                                "points or polygons");
        !st)
        return st.error();
    return out;
}

} // namespace pf::io
