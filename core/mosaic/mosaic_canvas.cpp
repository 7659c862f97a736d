#include "core/mosaic/mosaic_canvas.h"

#include "core/geo/gdal_util.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <mutex>

namespace pf::mosaic {

struct MosaicCanvas::Impl {
    std::string path;
    GDALDatasetUniquePtr ds;
    std::mutex mutex;
    std::vector<std::uint8_t> buffer; // the window being blended (RGBA), reused
};

MosaicCanvas::~MosaicCanvas() {
    if (m_impl) {
        m_impl->ds.reset();
        std::error_code ec;
        std::filesystem::remove(m_impl->path, ec);
    }
}

Result<std::unique_ptr<MosaicCanvas>> MosaicCanvas::create(const OutputGrid& grid,
                                                           const std::string& wkt,
                                                           const std::string& scratchPath) {
    geo::detail::ensureGdalRegistered();
    std::unique_ptr<MosaicCanvas> canvas(new MosaicCanvas);
    canvas->m_impl = std::make_unique<Impl>();
    canvas->m_impl->path = scratchPath;
    GDALDriver* gtiff = GetGDALDriverManager()->GetDriverByName("GTiff");
    // Uncompressed: photos blend into tiles in any order, several times each; a compressed tile
    // rewritten would only grow the file.
    const char* const options[] = {"TILED=YES",        "BLOCKXSIZE=256",   "BLOCKYSIZE=256",
                                   "INTERLEAVE=PIXEL", "BIGTIFF=IF_SAFER", "SPARSE_OK=TRUE",
                                   "PHOTOMETRIC=RGB",  "ALPHA=YES",        nullptr};
    geo::detail::GdalErrorCapture errors;
    canvas->m_impl->ds.reset(gtiff ? gtiff->Create(scratchPath.c_str(), grid.width, grid.height, 4,
                                                   GDT_Byte, const_cast<char**>(options))
                                   : nullptr);
    if (!canvas->m_impl->ds)
        return makeError(ErrorCode::IoError, "cannot create the scratch file " + scratchPath +
                                                 " (" + errors.message() + ")");
    double gt[6];
    grid.geoTransform(gt);
    canvas->m_impl->ds->SetGeoTransform(gt);
    canvas->m_impl->ds->SetProjection(wkt.c_str());
    return canvas;
}

Status MosaicCanvas::add(const PixelWindow& w, const std::vector<std::uint8_t>& rgb,
                         const std::vector<float>& weight,
                         const std::vector<std::uint8_t>& opaque) {
    if (w.empty())
        return {};
    std::lock_guard<std::mutex> lock(m_impl->mutex);
    auto& buf = m_impl->buffer;
    const std::size_t n = static_cast<std::size_t>(w.w) * w.h;
    buf.resize(n * 4);
    geo::detail::GdalErrorCapture errors;
    GDALDataset& ds = *m_impl->ds;
    if (ds.RasterIO(GF_Read, w.x0, w.y0, w.w, w.h, buf.data(), w.w, w.h, GDT_Byte, 4, nullptr, 4,
                    4 * w.w, 1, nullptr) != CE_None)
        return makeError(ErrorCode::IoError, "cannot read the scratch file " + m_impl->path + " (" +
                                                 errors.message() + ")");
    for (std::size_t i = 0; i < n; ++i) {
        const float wt = weight[i];
        if (wt > 0.0f)
            for (int c = 0; c < 3; ++c) {
                const int v = buf[i * 4 + c] + static_cast<int>(std::lround(wt * rgb[i * 3 + c]));
                buf[i * 4 + c] = static_cast<std::uint8_t>(std::min(255, v));
            }
        if (opaque[i])
            buf[i * 4 + 3] = 255;
    }
    if (ds.RasterIO(GF_Write, w.x0, w.y0, w.w, w.h, buf.data(), w.w, w.h, GDT_Byte, 4, nullptr, 4,
                    4 * w.w, 1, nullptr) != CE_None)
        return makeError(ErrorCode::IoError, "cannot write the scratch file " + m_impl->path +
                                                 " (" + errors.message() + "): is the disk full?");
    return {};
}

namespace {

struct ProgressBridge {
    const std::function<bool(double)>* fn = nullptr;
    bool stopped = false;
};

int CPL_STDCALL gdalProgress(double done, const char*, void* arg) {
    auto* b = static_cast<ProgressBridge*>(arg);
    if (b->fn && *b->fn && !(*b->fn)(done))
        b->stopped = true;
    return b->stopped ? FALSE : TRUE;
}

} // namespace

Status MosaicCanvas::writeGeoTiff(const std::string& path, bool jpeg,
                                  const std::map<std::string, std::string>& metadata,
                                  const std::function<bool(double)>& progress) {
    std::lock_guard<std::mutex> lock(m_impl->mutex);
    GDALDataset& ds = *m_impl->ds;
    for (const auto& [k, v] : metadata)
        ds.SetMetadataItem(k.c_str(), v.c_str());
    ds.FlushCache();
    GDALDriver* cog = GetGDALDriverManager()->GetDriverByName("COG");
    if (!cog)
        return makeError(ErrorCode::Unsupported,
                         "this GDAL has no COG driver (GDAL 3.1 or newer is needed)");
    std::vector<const char*> options;
    if (jpeg) {
        options = {"COMPRESS=JPEG", "QUALITY=90"};
    } else {
        options = {"COMPRESS=DEFLATE", "PREDICTOR=YES"};
    }
    options.insert(options.end(), {"BLOCKSIZE=512", "BIGTIFF=IF_SAFER",
                                   "OVERVIEW_RESAMPLING=AVERAGE", "NUM_THREADS=ALL_CPUS", nullptr});
    const std::filesystem::path final(path);
    const std::filesystem::path temp =
        final.parent_path() / ("." + final.filename().string() + ".partial");
    ProgressBridge bridge;
    bridge.fn = &progress;
    geo::detail::GdalErrorCapture errors;
    GDALDatasetUniquePtr out(cog->CreateCopy(temp.string().c_str(), &ds, FALSE,
                                             const_cast<char**>(options.data()), gdalProgress,
                                             &bridge));
    const bool ok = out != nullptr;
    out.reset();
    std::error_code ec;
    if (!ok) {
        std::filesystem::remove(temp, ec);
        if (bridge.stopped)
            return makeError(ErrorCode::Cancelled, "cancelled");
        return makeError(ErrorCode::IoError,
                         "cannot write " + path + " (" + errors.message() + ")");
    }
    std::filesystem::rename(temp, final, ec);
    if (ec) {
        std::filesystem::remove(temp, ec);
        return makeError(ErrorCode::IoError, "cannot write " + path + " (" + ec.message() + ")");
    }
    return {};
}

} // namespace pf::mosaic
