#include "core/mosaic/seam_map.h"

#include "core/geo/ogr_adapter.h"
#include "core/geo/gdal_util.h"

#include <gdal_alg.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <thread>

namespace pf::mosaic {

namespace {

constexpr int kTile = 256; // the scratch raster's block size: every tile is written once, whole

// The area as edges in pixel coordinates, filled row by row with the even-odd rule (holes work).
class AreaRows {
public:
    AreaRows(const geo::MultiPolygon& area, const OutputGrid& grid) {
        auto addRing = [&](const geo::Ring& r) {
            for (std::size_t i = 0; i < r.size(); ++i) {
                const geo::Vec2& a = r[i];
                const geo::Vec2& b = r[(i + 1) % r.size()];
                m_edges.push_back(
                    {grid.col(a.x()), grid.row(a.y()), grid.col(b.x()), grid.row(b.y())});
            }
        };
        for (const auto& p : area) {
            addRing(p.outer);
            for (const auto& h : p.holes)
                addRing(h);
        }
    }
    bool empty() const { return m_edges.empty(); }
    // Marks the pixels of row `row`, columns [c0, c0 + w), whose centres lie in the area.
    void fill(int row, int c0, int w, std::uint8_t* out, std::vector<double>* xs) const {
        std::fill(out, out + w, std::uint8_t(0));
        const double yc = row + 0.5;
        xs->clear();
        for (const auto& e : m_edges) {
            if ((e.y0 <= yc && yc < e.y1) || (e.y1 <= yc && yc < e.y0))
                xs->push_back(e.x0 + (yc - e.y0) * (e.x1 - e.x0) / (e.y1 - e.y0));
        }
        std::sort(xs->begin(), xs->end());
        for (std::size_t i = 0; i + 1 < xs->size(); i += 2) {
            // Pixel c is inside when its centre c + 0.5 lies in [x_i, x_i+1).
            const int a = std::max(c0, static_cast<int>(std::ceil((*xs)[i] - 0.5)));
            const int b = std::min(c0 + w, static_cast<int>(std::ceil((*xs)[i + 1] - 0.5)));
            for (int c = a; c < b; ++c)
                out[c - c0] = 1;
        }
    }

private:
    struct Edge {
        double x0, y0, x1, y1;
    };
    std::vector<Edge> m_edges;
};

struct TileResult {
    PixelWindow window;
    std::vector<std::uint16_t> labels; // interleaved best, second
    std::map<int, PixelWindow> used;   // photo -> pixels of this tile it colours
    long long covered = 0, coveredArea = 0;
};

// The scratch raster of the labels: two 16-bit bands (best, second), tiled, in the grid.
Result<GDALDatasetUniquePtr> createLabelRaster(const OutputGrid& grid,
                                               const std::string& scratchPath) {
    GDALDriver* gtiff = GetGDALDriverManager()->GetDriverByName("GTiff");
    const char* const options[] = {"TILED=YES",        "BLOCKXSIZE=256", "BLOCKYSIZE=256",
                                   "INTERLEAVE=PIXEL", "COMPRESS=ZSTD",  "ZSTD_LEVEL=1",
                                   "BIGTIFF=IF_SAFER", "SPARSE_OK=TRUE", nullptr};
    geo::detail::GdalErrorCapture errors;
    GDALDatasetUniquePtr ds(gtiff ? gtiff->Create(scratchPath.c_str(), grid.width, grid.height, 2,
                                                  GDT_UInt16, const_cast<char**>(options))
                                  : nullptr);
    if (!ds)
        return makeError(ErrorCode::IoError, "cannot create the scratch file " + scratchPath +
                                                 " (" + errors.message() + ")");
    double gt[6];
    grid.geoTransform(gt);
    ds->SetGeoTransform(gt);
    return ds;
}

// The pixels of a tile a candidate photo colours: their extent in the tile.
struct Extent {
    int c0 = 1 << 30, r0 = 1 << 30, c1 = -1, r1 = -1;
    void add(int c, int r) {
        c0 = std::min(c0, c);
        c1 = std::max(c1, c);
        r0 = std::min(r0, r);
        r1 = std::max(r1, r);
    }
};

// Labels the tiles of the grid: each pixel gets the photo that sees it most from above and, near a
// seam when feathering, the runner-up.
class TileLabeller {
public:
    TileLabeller(const std::vector<PhotoGeometry>& photos, const GroundModel& ground,
                 const OutputGrid& grid, const geo::MultiPolygon& area, double featherM)
        : m_photos(photos), m_ground(ground), m_grid(grid), m_areaRows(area, grid),
          m_level(ground.levelHeight()), m_featherM(featherM),
          m_tilesX((grid.width + kTile - 1) / kTile) {}

    long long tiles() const {
        return static_cast<long long>(m_tilesX) * ((m_grid.height + kTile - 1) / kTile);
    }

    void label(long long t, TileResult* out) const {
        const int tx = static_cast<int>(t % m_tilesX), ty = static_cast<int>(t / m_tilesX);
        const PixelWindow tw{tx * kTile, ty * kTile, std::min(kTile, m_grid.width - tx * kTile),
                             std::min(kTile, m_grid.height - ty * kTile)};
        out->window = tw;
        out->labels.assign(static_cast<std::size_t>(tw.w) * tw.h * 2, 0);
        out->used.clear();
        out->covered = out->coveredArea = 0;
        const std::vector<int> cand = candidates(tw);
        const std::vector<char> full = holdingWholeTile(cand, tw);
        std::vector<Extent> ext(cand.size());
        std::vector<std::uint8_t> inArea(tw.w, 0);
        std::vector<double> xs;
        for (int r = 0; r < tw.h; ++r) {
            const double y = m_grid.y(tw.y0 + r);
            if (!m_areaRows.empty())
                m_areaRows.fill(tw.y0 + r, tw.x0, tw.w, inArea.data(), &xs);
            for (int c = 0; c < tw.w; ++c) {
                const bool seen = labelPixel(cand, full, tw, c, r, y, ext, out);
                if (seen && !m_areaRows.empty() && inArea[c])
                    ++out->coveredArea;
            }
        }
        for (std::size_t k = 0; k < cand.size(); ++k)
            if (ext[k].c1 >= 0)
                out->used[cand[k]] =
                    PixelWindow{tw.x0 + ext[k].c0, tw.y0 + ext[k].r0, ext[k].c1 - ext[k].c0 + 1,
                                ext[k].r1 - ext[k].r0 + 1};
    }

private:
    // The photos whose footprint meets the tile, nearest to its middle first.
    std::vector<int> candidates(const PixelWindow& tw) const {
        const geo::Box box{
            {m_grid.originX + tw.x0 * m_grid.gsd, m_grid.originY - (tw.y0 + tw.h) * m_grid.gsd},
            {m_grid.originX + (tw.x0 + tw.w) * m_grid.gsd, m_grid.originY - tw.y0 * m_grid.gsd}};
        const geo::Vec2 mid = 0.5 * (box.min + box.max);
        std::vector<int> cand;
        for (int i = 0; i < static_cast<int>(m_photos.size()); ++i)
            if (m_photos[i].seesGround && m_photos[i].footprintBox.intersects(box))
                cand.push_back(i);
        std::sort(cand.begin(), cand.end(), [&](int a, int b) {
            const Vec3& ca = m_photos[a].camera.centre();
            const Vec3& cb = m_photos[b].camera.centre();
            return (geo::Vec2(ca.x(), ca.y()) - mid).squaredNorm() <
                   (geo::Vec2(cb.x(), cb.y()) - mid).squaredNorm();
        });
        return cand;
    }

    // On a level ground a photo that holds the tile's four corners holds all of it: the ground seen
    // within a view angle is convex, and so is the image of a rectangle.
    std::vector<char> holdingWholeTile(const std::vector<int>& cand, const PixelWindow& tw) const {
        std::vector<char> full(cand.size(), 0);
        if (!m_level)
            return full;
        const double z = *m_level;
        for (std::size_t k = 0; k < cand.size(); ++k) {
            const PhotoGeometry& g = m_photos[cand[k]];
            full[k] = g.sees(m_grid.x(tw.x0), m_grid.y(tw.y0), z) &&
                      g.sees(m_grid.x(tw.x0 + tw.w - 1), m_grid.y(tw.y0), z) &&
                      g.sees(m_grid.x(tw.x0), m_grid.y(tw.y0 + tw.h - 1), z) &&
                      g.sees(m_grid.x(tw.x0 + tw.w - 1), m_grid.y(tw.y0 + tw.h - 1), z);
        }
        return full;
    }

    // Labels pixel (c, r) of the tile (at grid height y); true if a photo sees it.
    bool labelPixel(const std::vector<int>& cand, const std::vector<char>& full,
                    const PixelWindow& tw, int c, int r, double y, std::vector<Extent>& ext,
                    TileResult* out) const {
        const bool feather = m_featherM > 0;
        const double x = m_grid.x(tw.x0 + c);
        const double z = m_level ? *m_level : m_ground.heightAt(x, y);
        double best = 1e300, second = 1e300;
        int kb = -1, kc = -1;
        for (std::size_t k = 0; k < cand.size(); ++k) {
            const PhotoGeometry& g = m_photos[cand[k]];
            const double s2 = g.viewScore2(x, y, z);
            if (s2 >= (feather ? second : best))
                continue;
            if (!full[k] && !g.sees(x, y, z))
                continue;
            if (s2 < best) {
                second = best;
                kc = kb;
                best = s2;
                kb = static_cast<int>(k);
            } else {
                second = s2;
                kc = static_cast<int>(k);
            }
        }
        if (kb < 0)
            return false;
        const std::size_t at = (static_cast<std::size_t>(r) * tw.w + c) * 2;
        out->labels[at] = static_cast<std::uint16_t>(cand[kb] + 1);
        ++out->covered;
        ext[kb].add(c, r);
        if (feather && kc >= 0) {
            const double h = m_photos[cand[kb]].camera.centre().z() - z;
            if ((std::sqrt(second) - std::sqrt(best)) * h < m_featherM) {
                out->labels[at + 1] = static_cast<std::uint16_t>(cand[kc] + 1);
                ext[kc].add(c, r);
            }
        }
        return true;
    }

    const std::vector<PhotoGeometry>& m_photos;
    const GroundModel& m_ground;
    const OutputGrid& m_grid;
    const AreaRows m_areaRows;
    const std::optional<double> m_level;
    const double m_featherM;
    const int m_tilesX;
};

} // namespace

struct SeamMap::Impl {
    std::string path;
    GDALDatasetUniquePtr ds;
    mutable std::mutex mutex;
};

SeamMap::~SeamMap() {
    if (m_impl) {
        m_impl->ds.reset();
        std::error_code ec;
        std::filesystem::remove(m_impl->path, ec);
    }
}

Result<std::unique_ptr<SeamMap>> SeamMap::compute(const std::vector<PhotoGeometry>& photos,
                                                  const GroundModel& ground, const OutputGrid& grid,
                                                  const geo::MultiPolygon& area, double featherM,
                                                  int threads, const std::string& scratchPath,
                                                  const std::function<bool(double)>& progress) {
    if (photos.size() >= 65535)
        return makeError(ErrorCode::TooLarge, "at most 65534 photos fit in one mosaic");
    geo::detail::ensureGdalRegistered();
    std::unique_ptr<SeamMap> map(new SeamMap);
    map->m_grid = grid;
    map->m_windows.assign(photos.size(), PixelWindow{});
    map->m_impl = std::make_unique<Impl>();
    map->m_impl->path = scratchPath;
    auto ds = createLabelRaster(grid, scratchPath);
    if (!ds)
        return ds.error();
    map->m_impl->ds = std::move(*ds);

    // Every tile labelled by a worker, then written and counted under the lock.
    const TileLabeller labeller(photos, ground, grid, area, featherM);
    const long long tiles = labeller.tiles();
    std::atomic<long long> next{0};
    std::atomic<bool> stop{false};
    std::string writeError;
    long long done = 0;
    auto worker = [&] {
        TileResult tile;
        for (long long t = next++; t < tiles && !stop; t = next++) {
            labeller.label(t, &tile);
            std::lock_guard<std::mutex> lock(map->m_impl->mutex);
            geo::detail::GdalErrorCapture werrors;
            const CPLErr err = map->m_impl->ds->RasterIO(
                GF_Write, tile.window.x0, tile.window.y0, tile.window.w, tile.window.h,
                tile.labels.data(), tile.window.w, tile.window.h, GDT_UInt16, 2, nullptr, 4,
                4 * tile.window.w, 2, nullptr);
            if (err != CE_None) {
                if (writeError.empty())
                    writeError = werrors.message();
                stop = true;
            }
            for (const auto& [photo, w] : tile.used)
                map->m_windows[photo] = map->m_windows[photo].united(w);
            map->m_covered += tile.covered;
            map->m_coveredArea += tile.coveredArea;
            ++done;
            if (progress && !progress(static_cast<double>(done) / tiles))
                stop = true;
        }
    };
    const int n = std::max(1, threads);
    std::vector<std::thread> pool;
    for (int i = 1; i < n; ++i)
        pool.emplace_back(worker);
    worker();
    for (auto& t : pool)
        t.join();
    if (!writeError.empty())
        return makeError(ErrorCode::IoError, "cannot write the scratch file " + scratchPath + " (" +
                                                 writeError + "): is the disk full?");
    if (stop)
        return makeError(ErrorCode::Cancelled, "cancelled");
    map->m_impl->ds->FlushCache();
    return map;
}

Status SeamMap::read(const PixelWindow& w, std::vector<std::uint16_t>* best,
                     std::vector<std::uint16_t>* second) const {
    std::vector<std::uint16_t> both(static_cast<std::size_t>(w.w) * w.h * 2);
    {
        std::lock_guard<std::mutex> lock(m_impl->mutex);
        geo::detail::GdalErrorCapture errors;
        if (m_impl->ds->RasterIO(GF_Read, w.x0, w.y0, w.w, w.h, both.data(), w.w, w.h, GDT_UInt16,
                                 2, nullptr, 4, 4 * w.w, 2, nullptr) != CE_None)
            return makeError(ErrorCode::IoError, "cannot read the scratch file " + m_impl->path +
                                                     " (" + errors.message() + ")");
    }
    best->resize(both.size() / 2);
    second->resize(both.size() / 2);
    for (std::size_t i = 0; i < best->size(); ++i) {
        (*best)[i] = both[2 * i];
        (*second)[i] = both[2 * i + 1];
    }
    return {};
}

Result<std::vector<geo::MultiPolygon>> SeamMap::seamPolygons(int photoCount) const {
    std::lock_guard<std::mutex> lock(m_impl->mutex);
    GDALDriver* memDriver = GetGDALDriverManager()->GetDriverByName("Memory");
    if (!memDriver)
        return makeError(ErrorCode::Internal, "GDAL has no Memory vector driver");
    GDALDatasetUniquePtr vec(memDriver->Create("seams", 0, 0, 0, GDT_Unknown, nullptr));
    OGRLayer* layer = vec ? vec->CreateLayer("seams", nullptr, wkbPolygon, nullptr) : nullptr;
    if (!layer)
        return makeError(ErrorCode::Internal, "cannot create an in-memory layer for the seams");
    OGRFieldDefn field("label", OFTInteger);
    layer->CreateField(&field);
    GDALRasterBand* band = m_impl->ds->GetRasterBand(1);
    geo::detail::GdalErrorCapture errors;
    if (GDALPolygonize(band, band, layer, 0, nullptr, nullptr, nullptr) != CE_None)
        return makeError(ErrorCode::Internal, "cannot trace the seams (" + errors.message() + ")");
    std::vector<geo::MultiPolygon> out(photoCount);
    layer->ResetReading();
    for (auto& f : *layer) {
        const int label = f->GetFieldAsInteger(0);
        if (label < 1 || label > photoCount || !f->GetGeometryRef())
            continue;
        for (auto& poly : geo::detail::fromOgr(f->GetGeometryRef()))
            out[label - 1].push_back(std::move(poly));
    }
    return out;
}

} // namespace pf::mosaic
