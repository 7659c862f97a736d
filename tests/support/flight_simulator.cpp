#include "tests/support/flight_simulator.h"

#include <cpl_string.h>
#include <gdal_alg.h>
#include <gdal_priv.h>
#include <gdal_utils.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <thread>

namespace pf::testsim {

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

struct V3 {
    double x, y, z;
};
V3 operator+(V3 a, V3 b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
V3 operator*(double s, V3 a) {
    return {s * a.x, s * a.y, s * a.z};
}
double dot(V3 a, V3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
V3 cross(V3 a, V3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
// Rodrigues: v turned by `angle` about the unit axis k (right-handed).
V3 rotate(V3 v, V3 k, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return c * v + s * cross(k, v) + (dot(k, v) * (1 - c)) * k;
}

// The camera's axes in the local frame (x east, y north, z up), built from the gimbal angles the
// way a gimbal moves: face the yaw, tilt by the pitch about the right axis, roll about the forward
// axis.
struct Axes {
    V3 right, down, view;
};
Axes cameraAxes(const SimPose& p) {
    const double yaw = p.yawDeg * kDeg, pitch = p.pitchDeg * kDeg, roll = p.rollDeg * kDeg;
    const V3 forward{std::sin(yaw), std::cos(yaw), 0}, up{0, 0, 1};
    Axes a;
    a.right = {std::cos(yaw), -std::sin(yaw), 0};
    a.view = std::cos(pitch) * forward + std::sin(pitch) * up;
    a.down = std::sin(pitch) * forward + (-std::cos(pitch)) * up;
    a.right = rotate(a.right, forward, roll);
    a.view = rotate(a.view, forward, roll);
    a.down = rotate(a.down, forward, roll);
    return a;
}

std::string dms(double v) {
    v = std::abs(v);
    const double d = std::floor(v);
    const double m = std::floor((v - d) * 60.0);
    const double s = ((v - d) * 60.0 - m) * 60.0;
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%.0f) (%.0f) (%.6f)", d, m, s);
    return buf;
}

std::string num(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}

// A fine deterministic texture (value noise on a lattice) standing in for the detail a real photo
// has.
double grainAt(double x, double y, double cell) {
    auto h = [](long long i, long long j) {
        unsigned long long k = static_cast<unsigned long long>(i) * 0x9E3779B97F4A7C15ull ^
                               static_cast<unsigned long long>(j) * 0xC2B2AE3D27D4EB4Full;
        k ^= k >> 29;
        k *= 0xBF58476D1CE4E5B9ull;
        k ^= k >> 32;
        return static_cast<double>(k & 0xFFFF) / 65535.0 - 0.5;
    };
    const double u = x / cell, v = y / cell;
    const long long i = static_cast<long long>(std::floor(u)),
                    j = static_cast<long long>(std::floor(v));
    const double fu = u - i, fv = v - j;
    return (h(i, j) * (1 - fu) + h(i + 1, j) * fu) * (1 - fv) +
           (h(i, j + 1) * (1 - fu) + h(i + 1, j + 1) * fu) * fv;
}

struct GdalDatasetCloser {
    void operator()(GDALDatasetH h) const {
        if (h)
            GDALClose(h);
    }
};

} // namespace

std::string demoMapPath() {
#ifdef PF_DEMO_MAP_PATH
    if (std::filesystem::exists(PF_DEMO_MAP_PATH))
        return PF_DEMO_MAP_PATH;
#endif
    return {};
}

Result<GroundImage> GroundImage::load(const std::string& mapPath, geo::LonLat centre, double halfW,
                                      double halfH, double res) {
    GDALAllRegister();
    auto frame = geo::LocalFrame::create(centre);
    if (!frame)
        return frame.error();
    GroundImage img(*frame);
    img.m_res = res;
    img.m_x0 = -halfW;
    img.m_y0 = halfH;
    img.m_w = static_cast<int>(std::ceil(2 * halfW / res));
    img.m_h = static_cast<int>(std::ceil(2 * halfH / res));
    std::unique_ptr<void, GdalDatasetCloser> src(GDALOpen(mapPath.c_str(), GA_ReadOnly));
    if (!src)
        return makeError(ErrorCode::IoError, mapPath + ": cannot open the map");
    OGRSpatialReference tm;
    tm.importFromProj4(img.m_frame.projString().c_str());
    char* wkt = nullptr;
    tm.exportToWkt(&wkt);
    const std::string wktStr = wkt ? wkt : "";
    CPLFree(wkt);
    CPLStringList argv;
    argv.AddString("-of");
    argv.AddString("MEM");
    argv.AddString("-t_srs");
    argv.AddString(wktStr.c_str());
    argv.AddString("-te");
    argv.AddString(num("%.6f", -halfW).c_str());
    argv.AddString(num("%.6f", halfH - img.m_h * res).c_str());
    argv.AddString(num("%.6f", -halfW + img.m_w * res).c_str());
    argv.AddString(num("%.6f", halfH).c_str());
    argv.AddString("-ts");
    argv.AddString(std::to_string(img.m_w).c_str());
    argv.AddString(std::to_string(img.m_h).c_str());
    argv.AddString("-r");
    argv.AddString("bilinear");
    GDALWarpAppOptions* wo = GDALWarpAppOptionsNew(argv.List(), nullptr);
    GDALDatasetH srcH = src.get();
    int usageError = 0;
    std::unique_ptr<void, GdalDatasetCloser> warped(
        GDALWarp("", nullptr, 1, &srcH, wo, &usageError));
    GDALWarpAppOptionsFree(wo);
    if (!warped)
        return makeError(ErrorCode::IoError,
                         mapPath + ": cannot resample the map into the local frame");
    img.m_rgb.resize(static_cast<std::size_t>(img.m_w) * img.m_h * 3);
    int bands[3] = {1, 2, 3};
    if (GDALDatasetRasterIO(warped.get(), GF_Read, 0, 0, img.m_w, img.m_h, img.m_rgb.data(),
                            img.m_w, img.m_h, GDT_Byte, 3, bands, 3, 3 * img.m_w, 1) != CE_None)
        return makeError(ErrorCode::IoError, mapPath + ": cannot read the resampled map");
    return img;
}

bool GroundImage::sample(double x, double y, std::uint8_t rgb[3]) const {
    const double u = (x - m_x0) / m_res - 0.5, v = (m_y0 - y) / m_res - 0.5;
    if (!(u >= 0 && v >= 0 && u < m_w - 1 && v < m_h - 1))
        return false;
    const int i = static_cast<int>(u), j = static_cast<int>(v);
    const double fu = u - i, fv = v - j;
    const std::uint8_t* p = m_rgb.data() + (static_cast<std::size_t>(j) * m_w + i) * 3;
    const std::size_t row = static_cast<std::size_t>(m_w) * 3;
    for (int c = 0; c < 3; ++c) {
        const double a = p[c] * (1 - fu) + p[3 + c] * fu;
        const double b = p[row + c] * (1 - fu) + p[row + 3 + c] * fu;
        rgb[c] = static_cast<std::uint8_t>(std::min(255.0, a * (1 - fv) + b * fv + 0.5));
    }
    return true;
}

Status writePhoto(const GroundImage& ground, const SimPose& truth, const SimPose& recorded,
                  const SimOptions& o, int index, const std::string& path) {
    const int w = o.camera.widthPx, h = o.camera.heightPx;
    const bool landscape = w >= h;
    const double fovX = (landscape ? o.camera.longSideFovDeg : o.camera.shortSideFovDeg) * kDeg;
    const double fovY = (landscape ? o.camera.shortSideFovDeg : o.camera.longSideFovDeg) * kDeg;
    const double fx = (w / 2.0) / std::tan(fovX / 2.0), fy = (h / 2.0) / std::tan(fovY / 2.0);
    const Axes axes = cameraAxes(truth);
    const geo::Vec2 c2 = ground.frame().toLocal(truth.position);
    const V3 centre{c2.x(), c2.y(), truth.altitudeM};

    std::vector<std::uint8_t> rgb(static_cast<std::size_t>(w) * h * 3, 0);
    auto renderRows = [&](int r0, int r1) {
        for (int r = r0; r < r1; ++r) {
            for (int c = 0; c < w; ++c) {
                const V3 dir = axes.view + ((c + 0.5 - w / 2.0) / fx) * axes.right +
                               ((r + 0.5 - h / 2.0) / fy) * axes.down;
                if (dir.z >= 0)
                    continue;
                // Flat ground at 0, or the terrain by fixed-point steps along the ray.
                double gz = 0.0;
                double t = (gz - centre.z) / dir.z;
                V3 p = centre + t * dir;
                if (o.terrain) {
                    for (int it = 0; it < 60; ++it) {
                        const double nz = o.terrain(p.x, p.y);
                        if (std::abs(nz - gz) < 1e-4)
                            break;
                        gz = nz;
                        t = (gz - centre.z) / dir.z;
                        p = centre + t * dir;
                    }
                }
                std::uint8_t* px = rgb.data() + (static_cast<std::size_t>(r) * w + c) * 3;
                if (!ground.sample(p.x, p.y, px))
                    continue;
                if (o.grain > 0) {
                    const double g = o.grain * grainAt(p.x, p.y, o.grainCellM);
                    for (int k = 0; k < 3; ++k)
                        px[k] = static_cast<std::uint8_t>(
                            std::clamp(static_cast<int>(std::lround(px[k] + g)), 0, 255));
                }
            }
        }
    };
    const int threads = std::max(1, o.threads);
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back(renderRows, h * t / threads, h * (t + 1) / threads);
    for (auto& t : pool)
        t.join();

    GDALDriverH mem = GDALGetDriverByName("MEM");
    std::unique_ptr<void, GdalDatasetCloser> ds(GDALCreate(mem, "", w, h, 0, GDT_Byte, nullptr));
    for (int b = 0; b < 3; ++b) {
        char opt[3][64];
        std::snprintf(opt[0], sizeof opt[0], "DATAPOINTER=%p", static_cast<void*>(rgb.data() + b));
        std::snprintf(opt[1], sizeof opt[1], "PIXELOFFSET=3");
        std::snprintf(opt[2], sizeof opt[2], "LINEOFFSET=%d", 3 * w);
        const char* const list[] = {opt[0], opt[1], opt[2], nullptr};
        GDALAddBand(ds.get(), GDT_Byte, const_cast<char**>(list));
    }
    auto md = [&](const char* key, const std::string& value) {
        GDALSetMetadataItem(ds.get(), key, value.c_str(), nullptr);
    };
    md("EXIF_Make", o.camera.make);
    md("EXIF_Model", o.camera.model);
    md("EXIF_Orientation", "1");
    char date[64];
    std::snprintf(date, sizeof date, "2024:06:07 10:%02d:%02d", (index * 2 / 60) % 60,
                  (index * 2) % 60);
    md("EXIF_DateTimeOriginal", date);
    if (o.write35mm) {
        const double diag = std::hypot(std::tan(fovX / 2), std::tan(fovY / 2));
        md("EXIF_FocalLengthIn35mmFilm", num("%.0f", 43.2666 / (2.0 * diag)));
    }
    if (o.writeGps) {
        md("EXIF_GPSLatitudeRef", recorded.position.lat >= 0 ? "N" : "S");
        md("EXIF_GPSLatitude", dms(recorded.position.lat));
        md("EXIF_GPSLongitudeRef", recorded.position.lon >= 0 ? "E" : "W");
        md("EXIF_GPSLongitude", dms(recorded.position.lon));
        md("EXIF_GPSAltitudeRef", "0");
        md("EXIF_GPSAltitude",
           "(" + num("%.3f", recorded.altitudeM + o.takeoffAltitudeAmslM) + ")");
    }
    if (o.writeDirection) {
        md("EXIF_GPSImgDirectionRef", "T");
        md("EXIF_GPSImgDirection",
           "(" + num("%.3f", std::fmod(recorded.yawDeg + 360.0, 360.0)) + ")");
    }
    const std::string q = "QUALITY=" + std::to_string(o.jpegQuality);
    const char* const jpegOptions[] = {q.c_str(), nullptr};
    {
        std::unique_ptr<void, GdalDatasetCloser> out(
            GDALCreateCopy(GDALGetDriverByName("JPEG"), path.c_str(), ds.get(), FALSE,
                           const_cast<char**>(jpegOptions), nullptr, nullptr));
        if (!out)
            return makeError(ErrorCode::IoError, path + ": cannot write the photo");
    }
    std::filesystem::remove(path + ".aux.xml");
    if (!o.writeXmp)
        return {};
    // GDAL's JPEG writer has no XMP option: add the APP1 XMP segment after the start-of-image
    // marker.
    const std::string xmp =
        "<x:xmpmeta xmlns:x=\"adobe:ns:meta/\"><rdf:RDF "
        "xmlns:rdf=\"http://www.w3.org/1999/02/22-rdf-syntax-ns#\">"
        "<rdf:Description rdf:about=\"\" xmlns:drone-dji=\"http://www.dji.com/drone-dji/1.0/\" "
        "drone-dji:AbsoluteAltitude=\"" +
        num("%+.3f", recorded.altitudeM + o.takeoffAltitudeAmslM) +
        "\" drone-dji:RelativeAltitude=\"" + num("%+.3f", recorded.altitudeM) +
        "\" drone-dji:GimbalRollDegree=\"" + num("%+.3f", recorded.rollDeg) +
        "\" drone-dji:GimbalYawDegree=\"" + num("%+.3f", recorded.yawDeg) +
        "\" drone-dji:GimbalPitchDegree=\"" + num("%+.3f", recorded.pitchDeg) +
        "\" drone-dji:FlightYawDegree=\"" + num("%+.3f", recorded.yawDeg) +
        "\"/></rdf:RDF></x:xmpmeta>";
    std::string payload = std::string("http://ns.adobe.com/xap/1.0/") + '\0' + xmp;
    std::string bytes;
    {
        std::ifstream in(path, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    if (bytes.size() < 2)
        return makeError(ErrorCode::IoError, path + ": empty photo");
    const std::size_t len = payload.size() + 2;
    std::string segment = {'\xFF', '\xE1', static_cast<char>(len >> 8),
                           static_cast<char>(len & 0xFF)};
    bytes.insert(2, segment + payload);
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return out ? Status{} : Status(makeError(ErrorCode::IoError, path + ": cannot write the XMP"));
}

Result<std::vector<SimulatedPhoto>> simulateFlight(const GroundImage& ground,
                                                   const std::vector<mosaic::PlannedPhoto>& planned,
                                                   const SimOptions& o, const std::string& dir) {
    std::filesystem::create_directories(dir);
    std::mt19937 rng(o.seed);
    std::normal_distribution<double> pos(0.0, 1.0), ang(0.0, 1.0);
    std::vector<SimulatedPhoto> out;
    int i = o.firstIndex - 1;
    for (const auto& p : planned) {
        SimulatedPhoto s;
        s.truth.position = p.position;
        s.truth.altitudeM = p.altitudeM;
        s.truth.yawDeg = p.headingDeg;
        s.recorded = s.truth;
        if (o.positionNoiseM > 0 || o.angleNoiseDeg > 0) {
            const geo::Vec2 local = ground.frame().toLocal(p.position);
            const double dx = o.positionNoiseM * pos(rng), dy = o.positionNoiseM * pos(rng),
                         dz = o.positionNoiseM * pos(rng);
            s.recorded.position = ground.frame().toGeo(local + geo::Vec2(dx, dy));
            s.recorded.altitudeM += dz;
            s.recorded.yawDeg += o.angleNoiseDeg * ang(rng);
            s.recorded.pitchDeg += o.angleNoiseDeg * ang(rng);
            s.recorded.rollDeg += o.angleNoiseDeg * ang(rng);
        }
        char name[32];
        std::snprintf(name, sizeof name, "%04d.JPG", ++i);
        s.path = (std::filesystem::path(dir) / (o.namePrefix + name)).string();
        if (Status st = writePhoto(ground, s.truth, s.recorded, o, i, s.path); !st)
            return st.error();
        out.push_back(s);
    }
    return out;
}

Result<Comparison> compareWithMap(const std::string& mosaicPath, const std::string& mapPath,
                                  const std::vector<geo::GeoPolygon>& area) {
    GDALAllRegister();
    std::unique_ptr<void, GdalDatasetCloser> mos(GDALOpen(mosaicPath.c_str(), GA_ReadOnly));
    std::unique_ptr<void, GdalDatasetCloser> map(GDALOpen(mapPath.c_str(), GA_ReadOnly));
    if (!mos || !map)
        return makeError(ErrorCode::IoError, "cannot open " + (mos ? mapPath : mosaicPath));
    const int w = GDALGetRasterXSize(mos.get()), h = GDALGetRasterYSize(mos.get());
    double gt[6];
    GDALGetGeoTransform(mos.get(), gt);
    const std::string wkt = GDALGetProjectionRef(mos.get());
    CPLStringList argv;
    for (const char* a : {"-of", "MEM", "-r", "average", "-t_srs"})
        argv.AddString(a);
    argv.AddString(wkt.c_str());
    argv.AddString("-te");
    for (double v : {gt[0], gt[3] + h * gt[5], gt[0] + w * gt[1], gt[3]})
        argv.AddString(num("%.6f", v).c_str());
    argv.AddString("-ts");
    argv.AddString(std::to_string(w).c_str());
    argv.AddString(std::to_string(h).c_str());
    GDALWarpAppOptions* wo = GDALWarpAppOptionsNew(argv.List(), nullptr);
    GDALDatasetH mapH = map.get();
    int usageError = 0;
    std::unique_ptr<void, GdalDatasetCloser> ref(GDALWarp("", nullptr, 1, &mapH, wo, &usageError));
    GDALWarpAppOptionsFree(wo);
    if (!ref)
        return makeError(ErrorCode::IoError,
                         "cannot resample " + mapPath + " onto the mosaic's grid");

    // The area as a raster mask on the same grid.
    std::vector<std::uint8_t> inArea(static_cast<std::size_t>(w) * h, area.empty() ? 1 : 0);
    double areaPixels = 0.0; // the whole area, also where it lies beyond the mosaic
    if (!area.empty()) {
        std::unique_ptr<void, GdalDatasetCloser> maskDs(
            GDALCreate(GDALGetDriverByName("MEM"), "", w, h, 1, GDT_Byte, nullptr));
        GDALSetGeoTransform(maskDs.get(), gt);
        OGRSpatialReference wgs84, dst;
        wgs84.SetWellKnownGeogCS("WGS84");
        wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
        dst.importFromWkt(wkt.c_str());
        dst.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
        std::unique_ptr<OGRCoordinateTransformation> ct(
            OGRCreateCoordinateTransformation(&wgs84, &dst));
        std::vector<OGRGeometryH> geoms;
        for (const auto& poly : area) {
            auto* p = new OGRPolygon;
            auto ring = [&](const geo::GeoRing& r) {
                auto* lr = new OGRLinearRing;
                for (const auto& q : r)
                    lr->addPoint(q.lon, q.lat);
                lr->closeRings();
                return lr;
            };
            p->addRingDirectly(ring(poly.outer));
            for (const auto& hole : poly.holes)
                p->addRingDirectly(ring(hole));
            p->transform(ct.get());
            areaPixels += p->get_Area() / std::abs(gt[1] * gt[5]);
            geoms.push_back(OGRGeometry::ToHandle(p));
        }
        int band = 1;
        std::vector<double> burn(geoms.size(), 1.0);
        GDALRasterizeGeometries(maskDs.get(), 1, &band, static_cast<int>(geoms.size()),
                                geoms.data(), nullptr, nullptr, burn.data(), nullptr, nullptr,
                                nullptr);
        for (auto g : geoms)
            OGR_G_DestroyGeometry(g);
        if (GDALRasterIO(GDALGetRasterBand(maskDs.get(), 1), GF_Read, 0, 0, w, h, inArea.data(), w,
                         h, GDT_Byte, 0, 0) != CE_None)
            return makeError(ErrorCode::Internal, "cannot rasterise the area");
    }

    Comparison cmp;
    long long areaPx = 0, coveredPx = 0;
    double sum = 0.0;
    const int rowsPerChunk = 256;
    std::vector<std::uint8_t> a, b, m;
    int bands[3] = {1, 2, 3};
    for (int y0 = 0; y0 < h; y0 += rowsPerChunk) {
        const int rows = std::min(rowsPerChunk, h - y0);
        a.resize(static_cast<std::size_t>(w) * rows * 3);
        b.resize(a.size());
        m.resize(static_cast<std::size_t>(w) * rows);
        if (GDALDatasetRasterIO(mos.get(), GF_Read, 0, y0, w, rows, a.data(), w, rows, GDT_Byte, 3,
                                bands, 3, 3 * w, 1) != CE_None ||
            GDALDatasetRasterIO(ref.get(), GF_Read, 0, y0, w, rows, b.data(), w, rows, GDT_Byte, 3,
                                bands, 3, 3 * w, 1) != CE_None ||
            GDALRasterIO(GDALGetMaskBand(GDALGetRasterBand(mos.get(), 1)), GF_Read, 0, y0, w, rows,
                         m.data(), w, rows, GDT_Byte, 0, 0) != CE_None)
            return makeError(ErrorCode::IoError, "cannot read " + mosaicPath);
        for (int r = 0; r < rows; ++r)
            for (int c = 0; c < w; ++c) {
                const std::size_t i = static_cast<std::size_t>(r) * w + c;
                if (!inArea[static_cast<std::size_t>(y0 + r) * w + c])
                    continue;
                ++areaPx;
                if (m[i] < 128)
                    continue;
                ++coveredPx;
                for (int k = 0; k < 3; ++k)
                    sum +=
                        std::abs(static_cast<int>(a[i * 3 + k]) - static_cast<int>(b[i * 3 + k]));
            }
    }
    cmp.comparedPixels = coveredPx;
    cmp.meanAbsError = coveredPx ? sum / (3.0 * coveredPx) : 0.0;
    if (area.empty())
        areaPixels = static_cast<double>(areaPx);
    cmp.coveredShare = areaPixels > 0 ? std::min(1.0, coveredPx / areaPixels) : 0.0;
    return cmp;
}

} // namespace pf::testsim
