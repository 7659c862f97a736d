#include "core/mosaic/mosaic_builder.h"

#include "core/geo/ogr_adapter.h"
#include "core/geo/polygon_ops.h"
#include "core/geo/gdal_util.h"
#include "core/mosaic/mosaic_canvas.h"
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

// The part [base, base + span] of the job's progress.
struct Stage {
    Progress& progress;
    double base;
    double span;
    std::string name;
    bool operator()(double f) {
        progress.report(base + span * std::clamp(f, 0.0, 1.0), name);
        return !progress.cancelled();
    }
};

// Runs fn(i) for i in [0, n) on `threads` threads (the caller's among them).
template <class Fn> void parallelFor(int n, int threads, Fn fn) {
    std::atomic<int> next{0};
    auto worker = [&] {
        for (int i = next++; i < n; i = next++)
            fn(i);
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < std::min(threads, n); ++t)
        pool.emplace_back(worker);
    worker();
    for (auto& t : pool)
        t.join();
}

Error cancelled() {
    return makeError(ErrorCode::Cancelled, "the mosaic was cancelled");
}

// An automatic output resolution: the photos' median, to the millimetre.
double roundGsd(double gsd) {
    return std::max(0.001, std::round(gsd * 1000.0) / 1000.0);
}

geo::GeoRing ringToGeo(const geo::Ring& r, const UtmProjection& utm) {
    geo::GeoRing out;
    out.reserve(r.size());
    for (const auto& p : r)
        out.push_back(utm.toGeo(p));
    return out;
}

geo::GeoPolygon polygonToGeo(const geo::Polygon& p, const UtmProjection& utm) {
    geo::GeoPolygon out;
    out.outer = ringToGeo(p.outer, utm);
    for (const auto& h : p.holes)
        out.holes.push_back(ringToGeo(h, utm));
    return out;
}

geo::MultiPolygon simplified(const geo::MultiPolygon& mp, double tolerance) {
    if (mp.empty())
        return mp;
    auto ogr = geo::detail::toOgr(mp);
    geo::detail::OgrGeomPtr s(ogr->SimplifyPreserveTopology(tolerance));
    return s ? geo::detail::fromOgr(s.get()) : mp;
}

bool sameName(const std::string& a, const std::string& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
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

} // namespace

std::string defaultVectorPath(const std::string& outputPath) {
    std::filesystem::path p(outputPath);
    p.replace_extension(".gpkg");
    return p.string();
}

Result<MosaicReport> buildMosaic(const MosaicOptions& options, Progress& progress) {
    const auto started = std::chrono::steady_clock::now();
    geo::detail::ensureGdalRegistered();

    // Options.
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
    const std::filesystem::path outDir =
        outPath.parent_path().empty() ? std::filesystem::path(".") : outPath.parent_path();
    std::error_code ec;
    if (!std::filesystem::is_directory(outDir, ec))
        return makeError(ErrorCode::IoError, options.outputPath + ": the directory " +
                                                 outDir.string() + " does not exist");
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
    auto lap = std::chrono::steady_clock::now();
    std::clock_t cpuLap = std::clock();
    auto timeStage = [&](const char* name) {
        const auto now = std::chrono::steady_clock::now();
        const std::clock_t cpu = std::clock();
        report.stages.push_back({name, std::chrono::duration<double>(now - lap).count(),
                                 static_cast<double>(cpu - cpuLap) / CLOCKS_PER_SEC});
        lap = now;
        cpuLap = cpu;
    };

    // 1. Read every photo's metadata and make sure its image data decodes.
    Stage reading{progress, 0.0, 0.08, "reading photos"};
    reading(0.0);
    std::vector<std::string> paths;
    {
        std::set<std::string> seen;
        for (const auto& p : options.photos) {
            const std::string key = std::filesystem::weakly_canonical(p, ec).string();
            if (!seen.insert(ec ? p : key).second) {
                report.findings.push_back({geo::detail::fileName(p), PhotoFinding::Kind::Duplicate, true,
                                           "given twice: used once"});
                continue;
            }
            paths.push_back(p);
        }
    }
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

    timeStage("reading");

    // 2. Poses and cameras.
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

    // 3. The output coordinate system: the UTM zone of the site.
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

    const int n = static_cast<int>(poses->photos.size());
    std::vector<PhotoGeometry> geoms(n);
    std::vector<std::string> status(n, "used");
    std::vector<char> active(n, 1);
    std::vector<double> gsds;
    for (int i = 0; i < n; ++i) {
        const PlacedPhoto& p = poses->photos[i];
        geoms[i] = photoGeometry(gridCamera(p, utm, k), ground, options.maxViewAngleDeg);
        if (!geoms[i].seesGround) {
            active[i] = 0;
            status[i] = "left out: looks too far from the vertical";
            report.findings.push_back(
                {geo::detail::fileName(p.meta.path), PhotoFinding::Kind::Unused, true,
                 "looks " + fmt("%.0f", geoms[i].camera.offNadirDeg()) +
                     " degrees from the vertical: none of its ground is within " +
                     fmt("%.0f", options.maxViewAngleDeg) + " degrees of it"});
            continue;
        }
        gsds.push_back(geoms[i].nadirGsdM / k);
    }
    if (gsds.empty())
        return makeError(ErrorCode::InvalidInput, "none of the photos looks at the ground within " +
                                                      fmt("%.0f", options.maxViewAngleDeg) +
                                                      " degrees of the vertical");

    // 4. The output grid: every usable footprint, on a pixel lattice aligned to the GSD.
    std::sort(gsds.begin(), gsds.end());
    const double photoGsd = gsds[gsds.size() / 2];
    OutputGrid grid;
    grid.gsd = options.gsdM > 0 ? options.gsdM : roundGsd(photoGsd);
    if (grid.gsd < 0.25 * gsds.front())
        report.notes.push_back("the output GSD " + fmt("%.1f cm", grid.gsd * 100) +
                               " is much finer than the photos' (" +
                               fmt("%.1f cm", gsds.front() * 100) +
                               "): the mosaic is larger, not sharper");
    double minX = 1e300, minY = 1e300, maxX = -1e300, maxY = -1e300;
    for (int i = 0; i < n; ++i) {
        if (!active[i])
            continue;
        minX = std::min(minX, geoms[i].footprintBox.min.x());
        minY = std::min(minY, geoms[i].footprintBox.min.y());
        maxX = std::max(maxX, geoms[i].footprintBox.max.x());
        maxY = std::max(maxY, geoms[i].footprintBox.max.y());
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

    // The area coverage is measured against: the plan's, or one aircraft's part of it.
    geo::MultiPolygon areaGrid;
    if (options.plan)
        for (std::size_t ai = 0; ai < options.plan->area.size(); ++ai) {
            const auto& poly = options.plan->area[ai];
            if (!options.planAircraft.empty() && ai < options.plan->areaAircraft.size() &&
                !sameName(options.plan->areaAircraft[ai], options.planAircraft))
                continue;
            geo::Polygon g;
            for (const auto& p : poly.outer)
                g.outer.push_back(utm.toGrid(p));
            for (const auto& h : poly.holes) {
                geo::Ring r;
                for (const auto& p : h)
                    r.push_back(utm.toGrid(p));
                g.holes.push_back(r);
            }
            areaGrid.push_back(g);
        }
    if (options.plan && !options.planAircraft.empty() && !areaGrid.empty())
        report.notes.push_back("coverage is measured over the part of the area planned for " +
                               options.planAircraft);

    // 5. Seams: which photo sees each pixel most from above.
    const std::string stem = "." + outPath.stem().string();
    std::vector<PhotoGeometry> seamInput = geoms;
    for (int i = 0; i < n; ++i)
        if (!active[i])
            seamInput[i].seesGround = false;
    Stage seamStage{progress, 0.08, 0.17, "drawing seams"};
    auto seams = SeamMap::compute(seamInput, ground, grid, areaGrid, options.featherM * k, threads,
                                  (outDir / (stem + ".labels.tmp.tif")).string(), seamStage);
    if (!seams)
        return seams.error().code == ErrorCode::Cancelled ? cancelled() : seams.error();
    timeStage("seams");
    const auto& windows = (*seams)->windows();
    for (int i = 0; i < n; ++i)
        if (active[i] && windows[i].empty()) {
            active[i] = 0;
            status[i] = "not used: other photos see all of its ground more from above";
            report.findings.push_back(
                {geo::detail::fileName(poses->photos[i].meta.path), PhotoFinding::Kind::Unused, false,
                 "not used: other photos see all of its ground more from above"});
        }

    // 6. Warp every photo into the parts it gives colour to, one decoded photo per worker.
    auto canvasR =
        MosaicCanvas::create(grid, utm.wkt(), (outDir / (stem + ".canvas.tmp.tif")).string());
    if (!canvasR)
        return canvasR.error();
    MosaicCanvas& canvas = **canvasR;
    std::vector<int> order;
    for (int i = 0; i < n; ++i)
        if (active[i])
            order.push_back(i);
    Stage warpStage{progress, 0.25, 0.55, "warping photos"};
    warpStage(0.0);
    std::atomic<int> warped{0};
    std::mutex findingsMutex;
    std::string ioError;
    const double featherGrid = options.featherM * k;
    parallelFor(static_cast<int>(order.size()), threads, [&](int oi) {
        if (progress.cancelled())
            return;
        const int i = order[oi];
        const PixelWindow& w = windows[i];
        auto fail = [&](const std::string& msg, bool io) {
            std::lock_guard<std::mutex> lock(findingsMutex);
            if (io) {
                if (ioError.empty())
                    ioError = msg;
                progress.cancel();
                return;
            }
            active[i] = 0;
            status[i] = "left out: " + msg;
            report.findings.push_back({geo::detail::fileName(poses->photos[i].meta.path),
                                       PhotoFinding::Kind::Unreadable, true, msg});
        };
        auto rgb = warpPhoto(poses->photos[i].meta.path, geoms[i], ground, grid, w);
        if (!rgb) {
            fail(rgb.error().message, false);
            return;
        }
        std::vector<std::uint16_t> best, second;
        if (Status st = (*seams)->read(w, &best, &second); !st) {
            fail(st.error().message, true);
            return;
        }
        const std::size_t count = best.size();
        std::vector<float> weight(count, 0.0f);
        std::vector<std::uint8_t> opaque(count, 0);
        const auto me = static_cast<std::uint16_t>(i + 1);
        const auto level = ground.levelHeight();
        for (int r = 0; r < w.h; ++r) {
            for (int c = 0; c < w.w; ++c) {
                const std::size_t at = static_cast<std::size_t>(r) * w.w + c;
                const std::uint16_t b = best[at], s = second[at];
                if (b != me && s != me)
                    continue;
                opaque[at] = b == me;
                if (s == 0) {
                    weight[at] = 1.0f;
                    continue;
                }
                const double x = grid.x(w.x0 + c), y = grid.y(w.y0 + r);
                const double z = level ? *level : ground.heightAt(x, y);
                const double sb = std::sqrt(geoms[b - 1].viewScore2(x, y, z));
                const double sc = std::sqrt(geoms[s - 1].viewScore2(x, y, z));
                const double h = geoms[b - 1].camera.centre().z() - z;
                const double wc = 0.5 * std::max(0.0, 1.0 - (sc - sb) * h / featherGrid);
                weight[at] = static_cast<float>(b == me ? 1.0 - wc : wc);
            }
        }
        if (Status st = canvas.add(w, rgb->rgb, weight, opaque); !st) {
            fail(st.error().message, true);
            return;
        }
        warpStage(static_cast<double>(++warped) / order.size());
    });
    if (!ioError.empty())
        return makeError(ErrorCode::IoError, ioError);
    if (progress.cancelled())
        return cancelled();

    timeStage("warping");

    // 7. The GeoTIFF.
    int used = 0;
    for (int i = 0; i < n; ++i)
        used += active[i] ? 1 : 0;
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
    canvasR->reset();
    timeStage("writing");

    // 8. Seams, coverage of the area, gaps, and the vector layers.
    Stage vectorStage{progress, 0.95, 0.05, "writing footprints and seams"};
    vectorStage(0.0);
    auto seamPolys = (*seams)->seamPolygons(n);
    if (!seamPolys)
        return seamPolys.error();
    std::vector<geo::Polygon> gapPolys;
    if (!areaGrid.empty()) {
        geo::MultiPolygon all;
        for (const auto& mp : *seamPolys)
            all.insert(all.end(), mp.begin(), mp.end());
        const geo::MultiPolygon covered = geo::unite(all);
        const double minGap = std::max(1.0, 9.0 * grid.gsd * grid.gsd);
        for (auto& g : geo::difference(areaGrid, covered))
            if (geo::area(g) >= minGap)
                gapPolys.push_back(std::move(g));
        std::sort(gapPolys.begin(), gapPolys.end(),
                  [](const geo::Polygon& a, const geo::Polygon& b) {
                      return geo::area(a) > geo::area(b);
                  });
        report.areaM2 = geo::area(areaGrid) / (k * k);
        // Against the whole area: parts of it may lie outside the mosaic's grid (no photo there).
        const double areaPixels = geo::area(areaGrid) / (grid.gsd * grid.gsd);
        report.coveredRatio =
            areaPixels > 0
                ? std::min(1.0, static_cast<double>((*seams)->coveredAreaPixels()) / areaPixels)
                : 0.0;
        for (const auto& g : gapPolys) {
            GapArea gap;
            gap.shape.push_back(polygonToGeo(g, utm));
            gap.areaM2 = geo::area(g) / (k * k);
            const geo::Box b = geo::bounds(g);
            gap.centre = utm.toGeo(0.5 * (b.min + b.max));
            report.gapAreaM2 += gap.areaM2;
            report.gaps.push_back(std::move(gap));
        }
    }
    seams->reset();

    std::vector<VectorPhoto> vphotos;
    for (int i = 0; i < n; ++i) {
        const PlacedPhoto& p = poses->photos[i];
        VectorPhoto v;
        v.file = geo::detail::fileName(p.meta.path);
        v.used = active[i] != 0;
        v.status = status[i];
        v.footprint = geoms[i].footprint;
        v.seam = (*seamPolys)[i];
        v.camera = {geoms[i].camera.centre().x(), geoms[i].camera.centre().y()};
        v.altitudeM = p.altitudeM;
        v.yawDeg = p.yawDeg;
        v.pitchDeg = p.pitchDeg;
        v.rollDeg = p.rollDeg;
        v.gsdM = geoms[i].nadirGsdM / k;
        v.planned = p.planned >= 0 ? poses->planned[p.planned].label() : "";
        v.planOffsetM = p.planOffsetM;
        v.poseFrom = p.poseFrom;
        v.cameraName = p.camera;
        vphotos.push_back(v);

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
        for (const auto& poly : simplified(v.seam, grid.gsd))
            s.seam.push_back(polygonToGeo(poly, utm));
        report.photos.push_back(std::move(s));
    }
    std::vector<VectorPoint> missing;
    for (const auto& m : report.missing)
        missing.push_back({m.label, utm.toGrid(m.position)});
    if (Status st = writeMosaicVectors(vectorPath, utm.wkt(), vphotos, gapPolys, missing); !st)
        return st.error();
    vectorStage(1.0);
    timeStage("vectors");
    report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return report;
}

} // namespace pf::mosaic
