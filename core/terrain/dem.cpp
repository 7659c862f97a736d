#include "core/terrain/dem.h"

#include "core/geo/polygon_ops.h"
#include "core/geo/gdal_util.h"
#include "core/terrain/direct_resample.h"

#include <gdal_utils.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <mutex>

namespace pf::terrain {

namespace {

using geo::detail::GdalErrorCapture;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t kMaxNodes = 16'000'000;

std::string num(double v, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

std::string lonLatText(const geo::LonLat& p) {
    return num(std::fabs(p.lat), 5) + (p.lat >= 0 ? "° N " : "° S ") + num(std::fabs(p.lon), 5) +
           (p.lon >= 0 ? "° E" : "° W");
}

OGRSpatialReference wgs84() {
    OGRSpatialReference s;
    s.SetWellKnownGeogCS("WGS84");
    s.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    return s;
}

// The band's unit to metres; nothing for a unit that is not a length we know.
std::optional<double> unitFactor(std::string unit) {
    std::transform(unit.begin(), unit.end(), unit.begin(), [](unsigned char c) { return std::tolower(c); });
    if (unit.empty() || unit == "m" || unit == "metre" || unit == "meter" || unit == "metres" || unit == "meters")
        return 1.0;
    if (unit == "ft" || unit == "foot" || unit == "feet" || unit == "international foot")
        return 0.3048;
    if (unit == "us survey foot" || unit == "us-ft" || unit == "ftus")
        return 1200.0 / 3937.0;
    if (unit == "cm")
        return 0.01;
    if (unit == "dm")
        return 0.1;
    return std::nullopt;
}

// Which way `p` lies from `c`, in words ("north-east", ..., or "central" when close).
std::string direction(const geo::Vec2& c, const geo::Vec2& p, double scale) {
    const geo::Vec2 d = p - c;
    if (d.norm() < 0.2 * scale)
        return "central";
    const double az = std::atan2(d.x(), d.y()) * 180.0 / M_PI; // clockwise from north
    static const char* names[] = {"north", "north-east", "east", "south-east", "south", "south-west", "west", "north-west"};
    const int k = static_cast<int>(std::lround(((az < 0 ? az + 360.0 : az)) / 45.0)) % 8;
    return names[k];
}

} // namespace

struct Dem::Impl {
    GDALDatasetUniquePtr ds;
    DemInfo info;
    double scale = 1.0, offset = 0.0; // band scale and offset (before the unit)
    // The horizontal CRS alone: the warper is given it as the source CRS, so that it never shifts
    // the heights between vertical datums on its own (a compound CRS with EGM96 would otherwise be
    // turned into ellipsoidal heights; the datum is handled here, once).
    std::string horizontalWkt;
    double invGt[6] = {0, 1, 0, 0, 0, 1}; // georeferenced coordinates -> pixel coordinates
    std::optional<double> noData;
    bool maskBand = false;            // validity from a mask band (not a nodata value)
    mutable std::mutex mutex;         // GDAL datasets are not safe to read from two threads at once
};

namespace {

// The grid through GDAL's warper (bilinear, error threshold 1 % of a pixel): the general case, for
// what readDirect declines. Called under the dataset's lock.
Status warpGrid(const Dem::Impl& m, const std::string& who, const std::string& srs, double x0, double y0,
                double spacingM, int cols, int rows, std::vector<float>& h) {
    std::vector<std::string> args = {"-of", "MEM", "-t_srs", srs, "-te",
                                     num(x0 - spacingM / 2, 6), num(y0 - (rows - 0.5) * spacingM, 6),
                                     num(x0 + (cols - 0.5) * spacingM, 6), num(y0 + spacingM / 2, 6),
                                     "-ts", std::to_string(cols), std::to_string(rows), "-r", "bilinear",
                                     "-ot", "Float32", "-dstnodata", "nan", "-et", "0.01", "-wo",
                                     "INIT_DEST=NO_DATA", "-q"};
    if (!m.horizontalWkt.empty()) {
        args.push_back("-s_srs");
        args.push_back(m.horizontalWkt);
    }
    std::vector<char*> argv;
    for (auto& a : args)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    {
        GdalErrorCapture errors;
        GDALWarpAppOptions* opts = GDALWarpAppOptionsNew(argv.data(), nullptr);
        if (!opts)
            return makeError(ErrorCode::Internal, "the terrain resampling options were refused: " + errors.message());
        GDALDatasetH src = GDALDataset::ToHandle(m.ds.get());
        int usageError = 0;
        GDALDatasetH out = GDALWarp("", nullptr, 1, &src, opts, &usageError);
        GDALWarpAppOptionsFree(opts);
        if (!out)
            return makeError(ErrorCode::InvalidInput,
                             who + " cannot be resampled onto the planning grid: " + errors.message());
        GDALDatasetUniquePtr outDs(GDALDataset::FromHandle(out));
        if (outDs->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, cols, rows, h.data(), cols, rows, GDT_Float32, 0, 0,
                                              nullptr) != CE_None)
            return makeError(ErrorCode::IoError, who + " cannot be read: " + errors.message());
    }
    return {};
}

} // namespace

Dem::Dem(std::unique_ptr<Impl> impl) : m(std::move(impl)) {}
Dem::Dem(Dem&&) noexcept = default;
Dem& Dem::operator=(Dem&&) noexcept = default;
Dem::~Dem() = default;

const DemInfo& Dem::info() const { return m->info; }

Result<Dem> Dem::open(const std::string& path) {
    geo::detail::ensureGdalRegistered();
    const std::string who = "the terrain model \"" + path + "\"";
    GdalErrorCapture errors;
    GDALDatasetUniquePtr ds = geo::detail::openRaster(path);
    if (!ds) {
        std::string why = errors.message();
        return makeError(ErrorCode::IoError, who + " cannot be read" + (why.empty() ? "" : ": " + why) +
                                                 " (expected a GeoTIFF, an SRTM .hgt, a VRT or another raster "
                                                 "GDAL reads)");
    }
    if (ds->GetRasterCount() < 1)
        return makeError(ErrorCode::InvalidInput, who + " has no raster band");
    double gt[6];
    const OGRSpatialReference* srs = ds->GetSpatialRef();
    if (ds->GetGeoTransform(gt) != CE_None || !srs)
        return makeError(ErrorCode::InvalidInput,
                         who + " is not georeferenced (no geotransform or no coordinate reference system): "
                               "the heights cannot be placed on the map");
    auto impl = std::make_unique<Impl>();
    DemInfo& info = impl->info;
    info.path = path;
    info.driver = ds->GetDriver() ? ds->GetDriver()->GetDescription() : "";
    info.widthPx = ds->GetRasterXSize();
    info.heightPx = ds->GetRasterYSize();
    info.crs = srs->GetName() ? srs->GetName() : "";

    GDALRasterBand* band = ds->GetRasterBand(1);
    const auto factor = unitFactor(band->GetUnitType() ? band->GetUnitType() : "");
    if (!factor)
        return makeError(ErrorCode::Unsupported, who + ": heights in \"" + std::string(band->GetUnitType()) +
                                                     "\" are not supported (metres or feet)");
    info.unitToMetres = *factor;
    int has = 0;
    const double sc = band->GetScale(&has);
    impl->scale = has ? sc : 1.0;
    const double off = band->GetOffset(&has);
    impl->offset = has ? off : 0.0;
    const double nd = band->GetNoDataValue(&has);
    if (has)
        impl->noData = nd;
    const int maskFlags = band->GetMaskFlags();
    impl->maskBand = !(maskFlags & GMF_ALL_VALID) && !(maskFlags & GMF_NODATA);
    if (!GDALInvGeoTransform(gt, impl->invGt))
        return makeError(ErrorCode::InvalidInput, who + " has a geotransform that cannot be inverted");

    // Vertical datum: a compound CRS names its vertical part; a geographic or projected 3D CRS means
    // heights above the ellipsoid.
    if (srs->IsCompound()) {
        const char* v = srs->GetAttrValue("COMPD_CS|VERT_CS");
        info.verticalDatum = v ? v : "a vertical datum without a name";
    } else if (srs->GetAxesCount() == 3) {
        info.ellipsoidal = true;
        info.verticalDatum = "ellipsoidal (" + info.crs + "), converted to EGM96";
    } else if (srs->IsVertical()) {
        info.verticalDatum = srs->GetName() ? srs->GetName() : "vertical";
    } else {
        info.verticalDatum = "not stated (taken as height above mean sea level)";
    }
    if (info.ellipsoidal) {
        // The conversion needs PROJ's EGM96 grid (proj-data's egm96_15.gtx); refuse now, not mid-plan.
        OGRSpatialReference from, to;
        from.importFromEPSG(4979);
        to.SetFromUserInput("EPSG:4326+5773");
        from.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
        to.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
        std::unique_ptr<OGRCoordinateTransformation> ct(OGRCreateCoordinateTransformation(&from, &to));
        double x = 0, y = 0, z = 0;
        if (!ct || !ct->Transform(1, &x, &y, &z) || !std::isfinite(z) || z == 0.0)
            return makeError(ErrorCode::Unsupported,
                             who + " holds heights above the ellipsoid, and PROJ has no EGM96 geoid grid "
                                   "(egm96_15.gtx, Debian package proj-data) to convert them to heights above sea level");
    }

    // Bounds in WGS84 and the pixel's ground size, from the corners.
    OGRSpatialReference src = *srs;
    if (src.IsCompound())
        src.StripVertical();
    if (src.GetAxesCount() == 3)
        src.DemoteTo2D(nullptr);
    src.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    {
        char* wkt = nullptr;
        const char* const wktOpts[] = {"FORMAT=WKT2_2019", nullptr};
        if (src.exportToWkt(&wkt, wktOpts) == OGRERR_NONE && wkt)
            impl->horizontalWkt = wkt;
        CPLFree(wkt);
    }
    OGRSpatialReference geo = wgs84();
    std::unique_ptr<OGRCoordinateTransformation> toGeo(OGRCreateCoordinateTransformation(&src, &geo));
    if (!toGeo)
        return makeError(ErrorCode::InvalidInput, who + ": its coordinate reference system (" + info.crs +
                                                      ") cannot be converted to WGS84");
    double xs[4], ys[4];
    const double W = info.widthPx, H = info.heightPx;
    const double px[4] = {0, W, W, 0}, py[4] = {0, 0, H, H};
    for (int i = 0; i < 4; ++i) {
        xs[i] = gt[0] + px[i] * gt[1] + py[i] * gt[2];
        ys[i] = gt[3] + px[i] * gt[4] + py[i] * gt[5];
    }
    if (!toGeo->Transform(4, xs, ys))
        return makeError(ErrorCode::InvalidInput, who + ": its corners cannot be converted to WGS84");
    info.southWest = {*std::min_element(xs, xs + 4), *std::min_element(ys, ys + 4)};
    info.northEast = {*std::max_element(xs, xs + 4), *std::max_element(ys, ys + 4)};
    const double midLat = 0.5 * (info.southWest.lat + info.northEast.lat) * M_PI / 180.0;
    const double dx = std::hypot(gt[1], gt[4]), dy = std::hypot(gt[2], gt[5]);
    const double pixel = std::min(dx, dy);
    info.pixelSizeM = pixel * src.GetLinearUnits();
    if (src.IsGeographic())
        info.pixelSizeM = std::min(dx * 111'320.0 * std::max(std::cos(midLat), 0.01), dy * 110'574.0);

    auto lower = [](std::string s) {
        std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
        return s;
    };
    const char* synthetic = ds->GetMetadataItem("SYNTHETIC");
    const char* desc = ds->GetMetadataItem("TIFFTAG_IMAGEDESCRIPTION");
    if (!desc)
        desc = ds->GetMetadataItem("DESCRIPTION");
    info.description = desc ? desc : "";
    info.synthetic = (synthetic && lower(synthetic) == "yes") || lower(info.description).find("synthetic") != std::string::npos;
    impl->ds = std::move(ds);
    return Dem(std::move(impl));
}

bool Dem::looksLikeDem(const std::string& path) {
    const auto dot = path.find_last_of('.');
    std::string ext = dot == std::string::npos ? std::string() : path.substr(dot + 1);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext == "hgt" || ext == "dem")
        return true;
    if (ext != "tif" && ext != "tiff" && ext != "vrt")
        return false;
    geo::detail::ensureGdalRegistered();
    GdalErrorCapture errors;
    GDALDatasetUniquePtr ds = geo::detail::openRaster(path);
    if (!ds || ds->GetRasterCount() != 1 || !ds->GetSpatialRef())
        return false;
    double gt[6];
    GDALRasterBand* band = ds->GetRasterBand(1);
    return ds->GetGeoTransform(gt) == CE_None && band->GetRasterDataType() != GDT_Byte && !band->GetColorTable();
}

Result<HeightGrid> Dem::resample(const std::string& srs, double x0, double y0, double spacingM, int cols,
                                 int rows) const {
    const std::string who = "the terrain model \"" + m->info.path + "\"";
    if (!(spacingM > 0) || cols < 1 || rows < 1)
        return makeError(ErrorCode::InvalidInput, "a terrain grid needs a spacing above 0 and at least one node");
    if (static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows) > 4 * kMaxNodes)
        return makeError(ErrorCode::TooLarge, "a terrain grid of " + std::to_string(cols) + " x " +
                                                  std::to_string(rows) + " nodes is too large");
    std::vector<float> h(static_cast<std::size_t>(cols) * rows, std::numeric_limits<float>::quiet_NaN());
    {
        std::lock_guard<std::mutex> lock(m->mutex);
        GdalErrorCapture errors;
        const detail::SourceRaster source{m->ds->GetRasterBand(1), m->info.widthPx, m->info.heightPx, m->invGt,
                                          m->noData, m->maskBand, m->horizontalWkt};
        auto direct = detail::resampleDirect(source, srs, x0, y0, spacingM, cols, rows, h);
        if (!direct)
            return makeError(ErrorCode::IoError, who + " cannot be read: " + errors.message());
        if (!*direct)
            if (auto warped = warpGrid(*m, who, srs, x0, y0, spacingM, cols, rows, h); !warped)
                return warped.error();
    }
    const double s = m->scale * m->info.unitToMetres, o = m->offset * m->info.unitToMetres;
    if (s != 1.0 || o != 0.0)
        for (float& v : h)
            v = static_cast<float>(v * s + o);
    if (m->info.ellipsoidal) {
        // H = h - N: the undulation varies over hundreds of kilometres, so it is computed on a lattice
        // of at most 17 x 17 nodes and interpolated.
        OGRSpatialReference grid, ell, ortho;
        grid.SetFromUserInput(srs.c_str());
        grid.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
        ell.importFromEPSG(4979);
        ell.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
        ortho.SetFromUserInput("EPSG:4326+5773");
        ortho.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
        OGRSpatialReference geo = wgs84();
        std::unique_ptr<OGRCoordinateTransformation> toGeo(OGRCreateCoordinateTransformation(&grid, &geo));
        std::unique_ptr<OGRCoordinateTransformation> undulation(OGRCreateCoordinateTransformation(&ell, &ortho));
        if (!toGeo || !undulation)
            return makeError(ErrorCode::Unsupported, who + ": its ellipsoidal heights cannot be converted to EGM96");
        constexpr int kL = 17;
        std::vector<double> lx(kL * kL), ly(kL * kL), lz(kL * kL, 0.0);
        for (int j = 0; j < kL; ++j)
            for (int i = 0; i < kL; ++i) {
                lx[j * kL + i] = x0 + (cols - 1) * spacingM * i / (kL - 1);
                ly[j * kL + i] = y0 - (rows - 1) * spacingM * j / (kL - 1);
            }
        if (!toGeo->Transform(kL * kL, lx.data(), ly.data()) ||
            !undulation->Transform(kL * kL, lx.data(), ly.data(), lz.data()))
            return makeError(ErrorCode::Unsupported, who + ": the EGM96 geoid is not known for this place");
        for (int r = 0; r < rows; ++r)
            for (int c = 0; c < cols; ++c) {
                const double fi = cols > 1 ? static_cast<double>(c) * (kL - 1) / (cols - 1) : 0.0;
                const double fj = rows > 1 ? static_cast<double>(r) * (kL - 1) / (rows - 1) : 0.0;
                const int i = std::min(static_cast<int>(fi), kL - 2), j = std::min(static_cast<int>(fj), kL - 2);
                const double tx = fi - i, ty = fj - j;
                // lz holds 0 - N (the ellipsoidal height 0 as an EGM96 height).
                const double mN = (lz[j * kL + i] * (1 - tx) + lz[j * kL + i + 1] * tx) * (1 - ty) +
                                  (lz[(j + 1) * kL + i] * (1 - tx) + lz[(j + 1) * kL + i + 1] * tx) * ty;
                float& v = h[static_cast<std::size_t>(r) * cols + c];
                v = static_cast<float>(v + mN);
            }
    }
    return HeightGrid(x0, y0, spacingM, cols, rows, std::move(h));
}

Result<HeightGrid> Dem::overRegion(const geo::LocalFrame& frame, const geo::MultiPolygon& region, double marginM,
                                   double spacingM) const {
    const std::string who = "the terrain model \"" + m->info.path + "\"";
    if (region.empty())
        return makeError(ErrorCode::InvalidInput, "there is no area to read the terrain for");
    const geo::Box box = geo::bounds(region);
    double spacing = spacingM > 0 ? spacingM : std::clamp(m->info.pixelSizeM, 0.5, 5.0);
    const double w = box.max.x() - box.min.x() + 2 * marginM, hgt = box.max.y() - box.min.y() + 2 * marginM;
    while ((w / spacing + 2) * (hgt / spacing + 2) > static_cast<double>(kMaxNodes))
        spacing *= 1.5;
    const int cols = static_cast<int>(std::ceil(w / spacing)) + 1;
    const int rows = static_cast<int>(std::ceil(hgt / spacing)) + 1;
    auto grid = resample(frame.projString(), box.min.x() - marginM, box.max.y() + marginM, spacing, cols, rows);
    if (!grid)
        return grid;

    // Is the region covered? Checked on a lattice of at most ~40,000 points inside it.
    const double step = std::max(spacing, std::sqrt(w * hgt / 40'000.0));
    int inside = 0, missing = 0;
    geo::Box miss{{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()},
                  {-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()}};
    geo::Vec2 missSum(0, 0);
    for (double y = box.min.y() + step / 2; y < box.max.y(); y += step)
        for (double x = box.min.x() + step / 2; x < box.max.x(); x += step) {
            const geo::Vec2 p(x, y);
            if (!geo::contains(region, p))
                continue;
            ++inside;
            if (grid->heightAt(p))
                continue;
            ++missing;
            missSum += p;
            miss.min = miss.min.cwiseMin(p);
            miss.max = miss.max.cwiseMax(p);
        }
    if (inside == 0 || missing == 0)
        return grid;
    if (missing == inside) {
        // Outside the DEM's bounds, or inside them on no-data pixels?
        const geo::LonLat a = frame.toGeo(box.min), b = frame.toGeo(box.max);
        const auto& sw = m->info.southWest;
        const auto& ne = m->info.northEast;
        const bool overlaps = std::max(a.lon, b.lon) >= sw.lon && std::min(a.lon, b.lon) <= ne.lon &&
                              std::max(a.lat, b.lat) >= sw.lat && std::min(a.lat, b.lat) <= ne.lat;
        return makeError(ErrorCode::InvalidInput,
                         who + " has no heights over the area: " +
                             (overlaps ? std::string("every pixel there is no-data")
                                       : "it covers " + lonLatText(sw) + " to " + lonLatText(ne) +
                                             ", the area lies elsewhere"));
    }
    const geo::Vec2 centre = (box.min + box.max) / 2;
    const double share = 100.0 * missing / inside;
    return makeError(ErrorCode::InvalidInput,
                     who + " does not cover the whole area: its " +
                         direction(centre, missSum / missing, 0.5 * (box.max - box.min).norm()) + " part (" +
                         num(share, share < 1 ? 2 : 0) + " % of the area, from " + lonLatText(frame.toGeo(miss.min)) +
                         " to " + lonLatText(frame.toGeo(miss.max)) + ") has no heights" +
                         " (the DEM covers " + lonLatText(m->info.southWest) + " to " + lonLatText(m->info.northEast) +
                         ")");
}

} // namespace pf::terrain
