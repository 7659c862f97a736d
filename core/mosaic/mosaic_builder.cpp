#include "core/mosaic/mosaic_builder.h"

#include "core/geo/gdal_util.h"
#include "core/geo/ogr_adapter.h"
#include "core/geo/polygon_ops.h"
#include "core/mosaic/mosaic_blend.h"
#include "core/mosaic/mosaic_canvas.h"
#include "core/mosaic/mosaic_coverage.h"
#include "core/mosaic/mosaic_run.h"
#include "core/mosaic/mosaic_vectors.h"
#include "core/mosaic/photo_geometry.h"
#include "core/mosaic/photo_metadata.h"
#include "core/mosaic/photo_warper.h"
#include "core/mosaic/pose_resolver.h"
#include "core/mosaic/seam_map.h"
#include "core/mosaic/site_frame.h"
#include "core/mosaic/utm_projection.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <map>
#include <mutex>
#include <set>
#include <thread>

namespace pf::mosaic {

namespace {

std::string fmt(const char* format, double v) {
    char buf[96];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

// GDAL's block cache is process-wide and defaults to 5 % of the RAM; the scratch rasters would fill
// it. Lowered for the run, restored afterwards.
class CacheLimit {
public:
    explicit CacheLimit(std::size_t bytes) : m_old(GDALGetCacheMax64()) {
        if (bytes > 0 && m_old > static_cast<GIntBig>(bytes)) {
            GDALSetCacheMax64(static_cast<GIntBig>(bytes));
            m_changed = true;
        }
    }
    ~CacheLimit() {
        if (m_changed)
            GDALSetCacheMax64(m_old);
    }
    CacheLimit(const CacheLimit&) = delete;
    CacheLimit& operator=(const CacheLimit&) = delete;

private:
    GIntBig m_old;
    bool m_changed = false;
};

// An automatic output resolution: the photos' median, to the millimetre.
double roundGsd(double gsd) {
    return std::max(0.001, std::round(gsd * 1000.0) / 1000.0);
}

geo::MultiPolygon simplified(const geo::MultiPolygon& mp, double tolerance) {
    if (mp.empty())
        return mp;
    auto ogr = geo::detail::toOgr(mp);
    geo::detail::OgrGeomPtr s(ogr->SimplifyPreserveTopology(tolerance));
    return s ? geo::detail::fromOgr(s.get()) : mp;
}

std::string summarise(const std::vector<PhotoFinding>& findings) {
    std::string out;
    int shown = 0;
    for (const auto& f : findings) {
        if (!f.excluded)
            continue;
        if (shown++ == 3) {
            out += "; ...";
            break;
        }
        out += (out.empty() ? "" : "; ") + f.file + ": " + f.message;
    }
    return out;
}

using namespace detail;

// The directory the output goes into ("." for a bare file name).
std::filesystem::path outputDirectory(const std::filesystem::path& outPath) {
    return outPath.parent_path().empty() ? std::filesystem::path(".") : outPath.parent_path();
}

Status checkOptions(const MosaicOptions& options) {
    if (options.photos.empty())
        return makeError(ErrorCode::InvalidInput, "no photos given");
    if (options.outputPath.empty())
        return makeError(ErrorCode::InvalidInput, "no output file given (--out mosaic.tif)");
    const std::filesystem::path outPath(options.outputPath);
    std::string ext = outPath.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext != ".tif" && ext != ".tiff")
        return makeError(ErrorCode::InvalidInput,
                         options.outputPath + ": the mosaic is a GeoTIFF: give a .tif file name");
    if (!std::isfinite(options.gsdM) || options.gsdM < 0)
        return makeError(ErrorCode::InvalidInput, "the output GSD must be positive");
    if (!std::isfinite(options.featherM) || options.featherM < 0)
        return makeError(ErrorCode::InvalidInput, "the feather width must be 0 or positive");
    if (!(options.maxViewAngleDeg > 0 && options.maxViewAngleDeg < 85))
        return makeError(ErrorCode::InvalidInput,
                         "the maximum view angle must lie between 0 and 85 degrees");
    const std::filesystem::path outDir = outputDirectory(outPath);
    std::error_code ec;
    if (!std::filesystem::is_directory(outDir, ec))
        return makeError(ErrorCode::IoError, options.outputPath + ": the directory " +
                                                 outDir.string() + " does not exist");
    return {};
}

// The wall and processor time of each stage, into the report.
class StageClock {
public:
    explicit StageClock(MosaicReport& report) : m_report(report) {}
    void lap(const char* name) {
        const auto now = std::chrono::steady_clock::now();
        const std::clock_t cpu = std::clock();
        m_report.stages.push_back({name, std::chrono::duration<double>(now - m_lap).count(),
                                   static_cast<double>(cpu - m_cpuLap) / CLOCKS_PER_SEC});
        m_lap = now;
        m_cpuLap = cpu;
    }

private:
    MosaicReport& m_report;
    std::chrono::steady_clock::time_point m_lap = std::chrono::steady_clock::now();
    std::clock_t m_cpuLap = std::clock();
};

// The photos given, each file once (a second mention gets a finding).
std::vector<std::string> distinctPhotos(const MosaicOptions& options, MosaicReport& report) {
    std::vector<std::string> paths;
    std::set<std::string> seen;
    std::error_code ec;
    for (const auto& p : options.photos) {
        const std::string key = std::filesystem::weakly_canonical(p, ec).string();
        if (!seen.insert(ec ? p : key).second) {
            report.findings.push_back({geo::detail::fileName(p), PhotoFinding::Kind::Duplicate,
                                       true, "given twice: used once"});
            continue;
        }
        paths.push_back(p);
    }
    return paths;
}

// Every photo's metadata, for the photos whose image data decodes; the others get a finding.
Result<std::vector<PhotoMetadata>> readPhotos(const MosaicOptions& options, int threads,
                                              Progress& progress, MosaicReport& report) {
    Stage reading{progress, 0.0, 0.08, "reading photos"};
    reading(0.0);
    const std::vector<std::string> paths = distinctPhotos(options, report);
    std::vector<std::optional<PhotoMetadata>> metas(paths.size());
    std::vector<std::string> readErrors(paths.size());
    std::atomic<int> read{0};
    parallelFor(static_cast<int>(paths.size()), threads, [&](int i) {
        if (progress.cancelled())
            return;
        auto m = readPhotoMetadata(paths[i]);
        if (!m) {
            readErrors[i] = m.error().message;
        } else if (Status st = checkPhotoDecodes(paths[i]); !st) {
            readErrors[i] = st.error().message;
        } else {
            metas[i] = std::move(m).value();
        }
        reading(static_cast<double>(++read) / paths.size());
    });
    if (progress.cancelled())
        return cancelled();
    std::vector<PhotoMetadata> readable;
    for (std::size_t i = 0; i < paths.size(); ++i) {
        if (metas[i]) {
            readable.push_back(std::move(*metas[i]));
            continue;
        }
        // The core's messages start with the file name; the finding names it already.
        std::string msg = readErrors[i];
        const std::string name = geo::detail::fileName(paths[i]);
        if (msg.rfind(name + ": ", 0) == 0)
            msg = msg.substr(name.size() + 2);
        report.findings.push_back({name, PhotoFinding::Kind::Unreadable, true, msg});
    }
    return readable;
}

// Poses and cameras of the readable photos; their findings, the missing planned photos and the
// notes go into the report. InvalidInput when none can be placed.
Result<ResolvedPoses> placePhotos(const std::vector<PhotoMetadata>& readable,
                                  const MosaicOptions& options, MosaicReport& report) {
    auto poses = resolvePoses(readable, options);
    if (!poses)
        return poses.error();
    report.findings.insert(report.findings.end(), poses->findings.begin(), poses->findings.end());
    report.missing = poses->missing;
    report.notes = poses->notes;
    if (poses->photos.empty())
        return makeError(ErrorCode::InvalidInput,
                         "none of the " + std::to_string(options.photos.size()) +
                             " photo(s) can be placed: " + summarise(report.findings));
    return poses;
}

// Every placed photo's geometry on the ground; a photo that sees no ground within the maximum view
// angle is left out. `gsds`: the nadir GSD in ground metres of the others, sorted. InvalidInput
// when none sees the ground.
Result<PhotoUse> photoGeometries(const std::vector<PlacedPhoto>& photos, const UtmProjection& utm,
                                 double k, const ScaledGround& ground, const MosaicOptions& options,
                                 std::vector<double>& gsds, MosaicReport& report) {
    const int n = static_cast<int>(photos.size());
    PhotoUse use;
    use.geoms.resize(n);
    use.status.assign(n, "used");
    use.active.assign(n, 1);
    for (int i = 0; i < n; ++i) {
        const PlacedPhoto& p = photos[i];
        use.geoms[i] = photoGeometry(gridCamera(p, utm, k), ground, options.maxViewAngleDeg);
        if (!use.geoms[i].seesGround) {
            use.active[i] = 0;
            use.status[i] = "left out: looks too far from the vertical";
            report.findings.push_back(
                {geo::detail::fileName(p.meta.path), PhotoFinding::Kind::Unused, true,
                 "looks " + fmt("%.0f", use.geoms[i].camera.offNadirDeg()) +
                     " degrees from the vertical: none of its ground is within " +
                     fmt("%.0f", options.maxViewAngleDeg) + " degrees of it"});
            continue;
        }
        gsds.push_back(use.geoms[i].nadirGsdM / k);
    }
    if (gsds.empty())
        return makeError(ErrorCode::InvalidInput, "none of the photos looks at the ground within " +
                                                      fmt("%.0f", options.maxViewAngleDeg) +
                                                      " degrees of the vertical");
    std::sort(gsds.begin(), gsds.end());
    return use;
}

// The output grid: every usable footprint, on a pixel lattice aligned to the GSD (the photos'
// median unless given); TooLarge past options.maxOutputPixels. Its size and corners go into the
// report.
Result<OutputGrid> outputGrid(const PhotoUse& use, const std::vector<double>& gsds,
                              const UtmProjection& utm, const MosaicOptions& options,
                              MosaicReport& report) {
    const double photoGsd = gsds[gsds.size() / 2];
    OutputGrid grid;
    grid.gsd = options.gsdM > 0 ? options.gsdM : roundGsd(photoGsd);
    if (grid.gsd < 0.25 * gsds.front())
        report.notes.push_back("the output GSD " + fmt("%.1f cm", grid.gsd * 100) +
                               " is much finer than the photos' (" +
                               fmt("%.1f cm", gsds.front() * 100) +
                               "): the mosaic is larger, not sharper");
    double minX = 1e300, minY = 1e300, maxX = -1e300, maxY = -1e300;
    for (std::size_t i = 0; i < use.geoms.size(); ++i) {
        if (!use.active[i])
            continue;
        minX = std::min(minX, use.geoms[i].footprintBox.min.x());
        minY = std::min(minY, use.geoms[i].footprintBox.min.y());
        maxX = std::max(maxX, use.geoms[i].footprintBox.max.x());
        maxY = std::max(maxY, use.geoms[i].footprintBox.max.y());
    }
    grid.originX = std::floor(minX / grid.gsd) * grid.gsd;
    grid.originY = std::ceil(maxY / grid.gsd) * grid.gsd;
    const double widthPx = std::ceil((maxX - grid.originX) / grid.gsd);
    const double heightPx = std::ceil((grid.originY - minY) / grid.gsd);
    if (widthPx * heightPx > options.maxOutputPixels || widthPx > 2e9 || heightPx > 2e9) {
        const double fit = grid.gsd * std::sqrt(widthPx * heightPx / options.maxOutputPixels);
        return makeError(
            ErrorCode::TooLarge,
            "the mosaic would be " + fmt("%.0f", widthPx) + " x " + fmt("%.0f", heightPx) +
                " px (" + fmt("%.1f", widthPx * heightPx / 1e9) + " gigapixels) at " +
                fmt("%.1f cm", grid.gsd * 100) + " per pixel, over " + fmt("%.0f", maxX - minX) +
                " x " + fmt("%.0f m", maxY - minY) + ": give a coarser --gsd (at least " +
                fmt("%.1f cm", std::ceil(fit * 1000) / 10) + ")");
    }
    grid.width = std::max(1, static_cast<int>(widthPx));
    grid.height = std::max(1, static_cast<int>(heightPx));
    report.gsdM = grid.gsd;
    report.widthPx = grid.width;
    report.heightPx = grid.height;
    report.southWest = utm.toGeo({grid.originX, grid.originY - grid.height * grid.gsd});
    report.northEast = utm.toGeo({grid.originX + grid.width * grid.gsd, grid.originY});
    return grid;
}

// Seams: which photo sees each pixel most from above. A photo that gives colour to no pixel is not
// used (a finding says so).
Result<std::unique_ptr<SeamMap>> drawSeams(const std::vector<PlacedPhoto>& photos, PhotoUse& use,
                                           const ScaledGround& ground, const OutputGrid& grid,
                                           const geo::MultiPolygon& areaGrid, double featherGrid,
                                           const std::string& scratchPath, int threads,
                                           Progress& progress, MosaicReport& report) {
    const int n = static_cast<int>(photos.size());
    std::vector<PhotoGeometry> seamInput = use.geoms;
    for (int i = 0; i < n; ++i)
        if (!use.active[i])
            seamInput[i].seesGround = false;
    Stage seamStage{progress, 0.08, 0.17, "drawing seams"};
    auto seams = SeamMap::compute(seamInput, ground, grid, areaGrid, featherGrid, threads,
                                  scratchPath, seamStage);
    if (!seams)
        return seams.error().code == ErrorCode::Cancelled ? cancelled() : seams.error();
    const auto& windows = (*seams)->windows();
    for (int i = 0; i < n; ++i)
        if (use.active[i] && windows[i].empty()) {
            use.active[i] = 0;
            use.status[i] = "not used: other photos see all of its ground more from above";
            report.findings.push_back(
                {geo::detail::fileName(photos[i].meta.path), PhotoFinding::Kind::Unused, false,
                 "not used: other photos see all of its ground more from above"});
        }
    return seams;
}

// The GeoTIFF, with the count of photos used and how the mosaic was made in its metadata.
Status writeGeoTiff(MosaicCanvas& canvas, const PhotoUse& use, const OutputGrid& grid,
                    const MosaicOptions& options, Progress& progress, MosaicReport& report) {
    int used = 0;
    for (char a : use.active)
        used += a ? 1 : 0;
    report.photosUsed = used;
    std::map<std::string, std::string> metadata{
        {"TIFFTAG_SOFTWARE", std::string("Photoflight ") + PF_VERSION},
        {"TIFFTAG_IMAGEDESCRIPTION",
         "Mosaic of " + std::to_string(used) +
             " photos by direct georeferencing (camera poses from EXIF/XMP or the plan, " +
             (options.ground ? std::string("ground from a terrain model")
                             : std::string("flat ground at the take-off height")) +
             "); not orthorectified: anything standing above the ground leans away from each "
             "photo's centre"},
        {"PF_MOSAIC_PHOTOS", std::to_string(used)},
        {"PF_MOSAIC_GSD_M", fmt("%.4f", grid.gsd)},
    };
    Stage writeStage{progress, 0.80, 0.15, "writing the GeoTIFF"};
    if (Status st =
            canvas.writeGeoTiff(options.outputPath, options.jpegCompression, metadata, writeStage);
        !st)
        return st.error().code == ErrorCode::Cancelled ? cancelled() : st.error();
    return {};
}

// Photo i for the vector layers.
VectorPhoto vectorPhoto(const ResolvedPoses& poses, const PhotoUse& use, int i,
                        const geo::MultiPolygon& seam, double k) {
    const PlacedPhoto& p = poses.photos[i];
    const PhotoGeometry& g = use.geoms[i];
    VectorPhoto v;
    v.file = geo::detail::fileName(p.meta.path);
    v.used = use.active[i] != 0;
    v.status = use.status[i];
    v.footprint = g.footprint;
    v.seam = seam;
    v.camera = {g.camera.centre().x(), g.camera.centre().y()};
    v.altitudeM = p.altitudeM;
    v.yawDeg = p.yawDeg;
    v.pitchDeg = p.pitchDeg;
    v.rollDeg = p.rollDeg;
    v.gsdM = g.nadirGsdM / k;
    v.planned = p.planned >= 0 ? poses.planned[p.planned].label() : "";
    v.planOffsetM = p.planOffsetM;
    v.poseFrom = p.poseFrom;
    v.cameraName = p.camera;
    return v;
}

// Photo p for the report, in WGS84 (its seam simplified to the pixel size).
PlacedPhotoSummary photoSummary(const PlacedPhoto& p, const VectorPhoto& v,
                                const UtmProjection& utm, double gsd) {
    PlacedPhotoSummary s;
    s.file = v.file;
    s.position = p.position;
    s.altitudeM = p.altitudeM;
    s.yawDeg = p.yawDeg;
    s.pitchDeg = p.pitchDeg;
    s.rollDeg = p.rollDeg;
    s.camera = p.camera;
    s.planned = v.planned;
    s.planOffsetM = p.planOffsetM;
    s.poseFrom = p.poseFrom;
    s.gsdM = v.gsdM;
    if (v.footprint.size() >= 3)
        s.footprint.outer = ringToGeo(v.footprint, utm);
    for (const auto& poly : simplified(v.seam, gsd))
        s.seam.push_back(polygonToGeo(poly, utm));
    return s;
}

// The vector layers (footprints, seams, gaps, camera positions, missing photos) and every photo's
// summary in the report.
Status writeVectors(const std::string& vectorPath, const ResolvedPoses& poses, const PhotoUse& use,
                    const std::vector<geo::MultiPolygon>& seamPolys,
                    const std::vector<geo::Polygon>& gapPolys, const UtmProjection& utm,
                    const OutputGrid& grid, double k, MosaicReport& report) {
    std::vector<VectorPhoto> vphotos;
    for (int i = 0; i < static_cast<int>(poses.photos.size()); ++i) {
        VectorPhoto v = vectorPhoto(poses, use, i, seamPolys[i], k);
        vphotos.push_back(v);
        report.photos.push_back(photoSummary(poses.photos[i], v, utm, grid.gsd));
    }
    std::vector<VectorPoint> missing;
    for (const auto& m : report.missing)
        missing.push_back({m.label, utm.toGrid(m.position)});
    return writeMosaicVectors(vectorPath, utm.wkt(), vphotos, gapPolys, missing);
}

} // namespace

std::string defaultVectorPath(const std::string& outputPath) {
    std::filesystem::path p(outputPath);
    p.replace_extension(".gpkg");
    return p.string();
}

// The stages: options checked; photos read; poses placed; the site's UTM grid and every photo's
// geometry on the ground; the output grid; seams; every photo warped and blended; the GeoTIFF; gaps
// in the area and the vector layers.
Result<MosaicReport> buildMosaic(const MosaicOptions& options, Progress& progress) {
    const auto started = std::chrono::steady_clock::now();
    geo::detail::ensureGdalRegistered();
    if (Status st = checkOptions(options); !st)
        return st.error();
    const std::filesystem::path outPath(options.outputPath);
    const std::filesystem::path outDir = outputDirectory(outPath);
    const std::string vectorPath =
        options.vectorPath.empty() ? defaultVectorPath(options.outputPath) : options.vectorPath;

    CacheLimit cache(options.gdalCacheBytes);
    const int threads =
        options.threads > 0
            ? options.threads
            : std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, 8);
    MosaicReport report;
    report.outputPath = options.outputPath;
    report.vectorPath = vectorPath;
    report.photosGiven = static_cast<int>(options.photos.size());
    StageClock clock(report);

    auto readable = readPhotos(options, threads, progress, report);
    if (!readable)
        return readable.error();
    clock.lap("reading");
    auto poses = placePhotos(*readable, options, report);
    if (!poses)
        return poses.error();

    // The output coordinate system: the UTM zone of the site.
    const geo::LonLat site = mosaicSite(options, poses->photos);
    auto utmR = UtmProjection::forSite(site);
    if (!utmR)
        return utmR.error();
    const UtmProjection& utm = *utmR;
    report.crsName = utm.name();
    report.epsg = utm.epsg();
    const double k = utm.scaleFactor(site);
    const ScaledGround ground(options.ground ? options.ground : std::make_shared<FlatGround>(0.0),
                              k);
    std::vector<double> gsds;
    auto use = photoGeometries(poses->photos, utm, k, ground, options, gsds, report);
    if (!use)
        return use.error();
    auto grid = outputGrid(*use, gsds, utm, options, report);
    if (!grid)
        return grid.error();
    const geo::MultiPolygon areaGrid = coverageArea(options, utm, report.notes);

    const std::string stem = "." + outPath.stem().string();
    const double featherGrid = options.featherM * k;
    auto seams =
        drawSeams(poses->photos, *use, ground, *grid, areaGrid, featherGrid,
                  (outDir / (stem + ".labels.tmp.tif")).string(), threads, progress, report);
    if (!seams)
        return seams.error();
    clock.lap("seams");
    auto canvas =
        MosaicCanvas::create(*grid, utm.wkt(), (outDir / (stem + ".canvas.tmp.tif")).string());
    if (!canvas)
        return canvas.error();
    if (Status st = blendPhotos(poses->photos, *use, ground, *grid, **seams, **canvas, featherGrid,
                                threads, progress, report.findings);
        !st)
        return st.error();
    clock.lap("warping");
    if (Status st = writeGeoTiff(**canvas, *use, *grid, options, progress, report); !st)
        return st.error();
    canvas->reset();
    clock.lap("writing");

    Stage vectorStage{progress, 0.95, 0.05, "writing footprints and seams"};
    vectorStage(0.0);
    auto seamPolys = (*seams)->seamPolygons(static_cast<int>(poses->photos.size()));
    if (!seamPolys)
        return seamPolys.error();
    const std::vector<geo::Polygon> gapPolys =
        areaGrid.empty() ? std::vector<geo::Polygon>{}
                         : measureGaps(areaGrid, *seamPolys, **seams, *grid, utm, k, report);
    seams->reset();
    if (Status st =
            writeVectors(vectorPath, *poses, *use, *seamPolys, gapPolys, utm, *grid, k, report);
        !st)
        return st.error();
    vectorStage(1.0);
    clock.lap("vectors");
    report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return report;
}

} // namespace pf::mosaic
