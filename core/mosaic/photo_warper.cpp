#include "core/mosaic/photo_warper.h"

#include "core/geo/gdal_util.h"

#include <gdal_alg.h>
#include <gdalwarper.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace pf::mosaic {

namespace {

// What GDAL's warper calls to map output pixels to photo pixels (and back): the camera model over
// the ground model. Output pixels are relative to the window, photo pixels to the decoded part of
// the photo at its reduction.
struct CameraTransform {
    const PhotoGeometry* photo = nullptr;
    const GroundModel* ground = nullptr;
    OutputGrid grid;
    PixelWindow window;
    double scaleX = 1.0, scaleY = 1.0; // reduced pixels per stored pixel
    int srcX0 = 0, srcY0 = 0;          // the decoded part's offset, reduced pixels
};

int cameraTransform(void* arg, int dstToSrc, int n, double* x, double* y, double* z, int* ok) {
    const auto* t = static_cast<const CameraTransform*>(arg);
    const auto level = t->ground->levelHeight();
    for (int i = 0; i < n; ++i) {
        if (dstToSrc) {
            const double gx = t->grid.originX + (t->window.x0 + x[i]) * t->grid.gsd;
            const double gy = t->grid.originY - (t->window.y0 + y[i]) * t->grid.gsd;
            const double gz = level ? *level : t->ground->heightAt(gx, gy);
            double col = 0, row = 0;
            ok[i] = t->photo->camera.project(Vec3(gx, gy, gz), &col, &row) ? TRUE : FALSE;
            x[i] = col * t->scaleX - t->srcX0;
            y[i] = row * t->scaleY - t->srcY0;
        } else {
            const double col = (x[i] + t->srcX0) / t->scaleX, row = (y[i] + t->srcY0) / t->scaleY;
            const auto p = intersectGround(*t->ground, t->photo->camera.centre(),
                                           t->photo->camera.ray(col, row));
            ok[i] = p ? TRUE : FALSE;
            if (p) {
                x[i] = t->grid.col(p->x()) - t->window.x0;
                y[i] = t->grid.row(p->y()) - t->window.y0;
            }
        }
        if (z)
            z[i] = 0.0;
    }
    return TRUE;
}

struct ApproxDeleter {
    void operator()(void* p) const { GDALDestroyApproxTransformer(p); }
};
struct WarpOptionsDeleter {
    void operator()(GDALWarpOptions* p) const { GDALDestroyWarpOptions(p); }
};

// The coarsest reduction of the photo (JPEG decodes 1/2, 1/4, 1/8 directly) still as fine as the
// output, with its level (0: the stored size).
GDALDataset* coarsestFineEnough(GDALDataset* ds, double ratio, int bands, int& level) {
    GDALRasterBand* band1 = ds->GetRasterBand(1);
    const int storedW = ds->GetRasterXSize();
    for (int k = band1->GetOverviewCount() - 1; k >= 0; --k) {
        GDALRasterBand* ovr = band1->GetOverview(k);
        if (!ovr || !ovr->GetDataset() || ovr->GetDataset()->GetRasterCount() < bands)
            continue;
        const double f = static_cast<double>(storedW) / ovr->GetXSize();
        if (f <= ratio * 1.001) {
            level = static_cast<int>(std::lround(std::log2(f)));
            return ovr->GetDataset();
        }
    }
    return ds;
}

struct SourceRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// The part of the photo (at its reduction, srcW x srcH) the window needs: a lattice of the window's
// pixels projected, grown by the resampling kernel's reach; none when it sees nothing.
std::optional<SourceRect> neededSource(CameraTransform& t, const PixelWindow& window, int srcW,
                                       int srcH) {
    double minC = 1e300, minR = 1e300, maxC = -1e300, maxR = -1e300;
    constexpr int kSamples = 12;
    for (int j = 0; j <= kSamples; ++j) {
        for (int i = 0; i <= kSamples; ++i) {
            double px = window.w * static_cast<double>(i) / kSamples,
                   py = window.h * static_cast<double>(j) / kSamples;
            double pz = 0;
            int ok = 0;
            cameraTransform(&t, TRUE, 1, &px, &py, &pz, &ok);
            if (!ok)
                continue;
            minC = std::min(minC, px);
            maxC = std::max(maxC, px);
            minR = std::min(minR, py);
            maxR = std::max(maxR, py);
        }
    }
    if (minC > maxC)
        return std::nullopt;
    const int pad = 3; // the resampling kernel's reach, and curvature between the samples
    SourceRect r;
    r.x0 = std::clamp(static_cast<int>(std::floor(minC)) - pad, 0, srcW);
    r.y0 = std::clamp(static_cast<int>(std::floor(minR)) - pad, 0, srcH);
    r.x1 = std::clamp(static_cast<int>(std::ceil(maxC)) + pad, 0, srcW);
    r.y1 = std::clamp(static_cast<int>(std::ceil(maxR)) + pad, 0, srcH);
    if (r.x1 <= r.x0 || r.y1 <= r.y0)
        return std::nullopt;
    return r;
}

// An in-memory dataset over band-sequential pixels (sw x sh per band) the warper reads.
GDALDatasetUniquePtr memoryDataset(std::vector<std::uint8_t>& pixels, int sw, int sh, int bands) {
    GDALDriver* memDriver = GetGDALDriverManager()->GetDriverByName("MEM");
    GDALDatasetUniquePtr mem(memDriver->Create("", sw, sh, 0, GDT_Byte, nullptr));
    for (int b = 0; b < bands; ++b) {
        char ptr[64];
        std::snprintf(ptr, sizeof ptr, "DATAPOINTER=%p",
                      static_cast<void*>(pixels.data() + static_cast<std::size_t>(b) * sw * sh));
        const char* const bandOptions[] = {ptr, nullptr};
        mem->AddBand(GDT_Byte, const_cast<char**>(bandOptions));
    }
    return mem;
}

// The decoded part (mem) warped into the window, band-sequential; GDAL's message when it fails.
Result<std::vector<std::uint8_t>> warpWindow(GDALDataset* mem, CameraTransform& t, int bands,
                                             Resampling resampling, const PixelWindow& window,
                                             geo::detail::GdalErrorCapture& errors,
                                             const std::string& name) {
    std::unique_ptr<void, ApproxDeleter> approx(
        GDALCreateApproxTransformer(cameraTransform, &t, 0.125));
    std::unique_ptr<GDALWarpOptions, WarpOptionsDeleter> wo(GDALCreateWarpOptions());
    wo->hSrcDS = GDALDataset::ToHandle(mem);
    wo->hDstDS = nullptr;
    wo->nBandCount = bands;
    wo->panSrcBands = static_cast<int*>(CPLMalloc(sizeof(int) * bands));
    wo->panDstBands = static_cast<int*>(CPLMalloc(sizeof(int) * bands));
    for (int b = 0; b < bands; ++b)
        wo->panSrcBands[b] = wo->panDstBands[b] = b + 1;
    wo->eResampleAlg = resampling == Resampling::Cubic     ? GRA_Cubic
                       : resampling == Resampling::Lanczos ? GRA_Lanczos
                                                           : GRA_Bilinear;
    wo->eWorkingDataType = GDT_Byte;
    wo->pfnTransformer = GDALApproxTransform;
    wo->pTransformerArg = approx.get();
    wo->dfWarpMemoryLimit = 64.0 * 1024 * 1024;

    GDALWarpOperation op;
    if (op.Initialize(wo.get()) != CE_None)
        return makeError(ErrorCode::Internal,
                         name + ": GDAL's warper refused the photo (" + errors.message() + ")");
    std::vector<std::uint8_t> warped(static_cast<std::size_t>(window.w) * window.h * bands, 0);
    if (op.WarpRegionToBuffer(0, 0, window.w, window.h, warped.data(), GDT_Byte, 0, 0,
                              mem->GetRasterXSize(), mem->GetRasterYSize()) != CE_None)
        return makeError(ErrorCode::Internal, name + ": warping failed (" + errors.message() + ")");
    return warped;
}

} // namespace

Result<WarpedWindow> warpPhoto(const std::string& path, const PhotoGeometry& photo,
                               const GroundModel& ground, const OutputGrid& grid,
                               const PixelWindow& window, Resampling resampling) {
    const std::string name = geo::detail::fileName(path);
    WarpedWindow out;
    out.window = window;
    out.rgb.assign(static_cast<std::size_t>(window.w) * window.h * 3, 0);
    if (window.empty())
        return out;

    CPLConfigOptionSetter strict("GDAL_ERROR_ON_LIBJPEG_WARNING", "TRUE", true);
    geo::detail::GdalErrorCapture errors;
    auto ds = geo::detail::openRaster(path);
    if (!ds)
        return makeError(ErrorCode::ParseError,
                         name + ": cannot be opened any more (" + errors.message() + ")");
    const int storedW = ds->GetRasterXSize(), storedH = ds->GetRasterYSize();
    if (storedW != photo.camera.storedWidth() || storedH != photo.camera.storedHeight())
        return makeError(ErrorCode::IoError, name + ": changed while the mosaic was made");
    const int bands = std::min(3, ds->GetRasterCount());
    GDALDataset* src =
        coarsestFineEnough(ds.get(), grid.gsd / std::max(photo.nadirGsdM, 1e-9), bands, out.level);
    const int srcW = src->GetRasterXSize(), srcH = src->GetRasterYSize();

    CameraTransform t;
    t.photo = &photo;
    t.ground = &ground;
    t.grid = grid;
    t.window = window;
    t.scaleX = static_cast<double>(srcW) / storedW;
    t.scaleY = static_cast<double>(srcH) / storedH;
    const std::optional<SourceRect> r = neededSource(t, window, srcW, srcH);
    if (!r)
        return out;
    const int sw = r->x1 - r->x0, sh = r->y1 - r->y0;
    t.srcX0 = r->x0;
    t.srcY0 = r->y0;

    // Decode that part (band-sequential) into an in-memory dataset the warper reads.
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(sw) * sh * bands);
    if (src->RasterIO(GF_Read, r->x0, r->y0, sw, sh, pixels.data(), sw, sh, GDT_Byte, bands,
                      nullptr, 0, 0, 0, nullptr) != CE_None ||
        errors.failed())
        return makeError(ErrorCode::ParseError,
                         name + ": the image data is damaged (" + errors.message() + ")");
    GDALDatasetUniquePtr mem = memoryDataset(pixels, sw, sh, bands);
    auto warped = warpWindow(mem.get(), t, bands, resampling, window, errors, name);
    if (!warped)
        return warped.error();
    const std::size_t plane = static_cast<std::size_t>(window.w) * window.h;
    for (std::size_t i = 0; i < plane; ++i)
        for (int c = 0; c < 3; ++c)
            out.rgb[i * 3 + c] = (*warped)[std::min(c, bands - 1) * plane + i];
    return out;
}

} // namespace pf::mosaic
