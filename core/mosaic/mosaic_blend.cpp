#include "core/mosaic/mosaic_blend.h"

#include "core/geo/gdal_util.h"
#include "core/mosaic/photo_warper.h"

#include <cmath>
#include <cstdint>
#include <mutex>
#include <string>

namespace pf::mosaic::detail {

namespace {

// Photo i's share of each pixel of its window: all of it where it alone sees the ground; near a
// seam
// (`second` set) its weight falls from 1 to 0.5 at the seam and on to 0 over the feather width,
// measured by how much more from above the best photo sees the pixel than the runner-up. `opaque`:
// the pixels photo i is the best of.
void seamWeights(int i, const PixelWindow& w, const std::vector<std::uint16_t>& best,
                 const std::vector<std::uint16_t>& second, const std::vector<PhotoGeometry>& geoms,
                 const ScaledGround& ground, const OutputGrid& grid, double featherGrid,
                 std::vector<float>& weight, std::vector<std::uint8_t>& opaque) {
    const std::size_t count = best.size();
    weight.assign(count, 0.0f);
    opaque.assign(count, 0);
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
}

} // namespace

Status blendPhotos(const std::vector<PlacedPhoto>& photos, PhotoUse& use,
                   const ScaledGround& ground, const OutputGrid& grid, const SeamMap& seams,
                   MosaicCanvas& canvas, double featherGrid, int threads, Progress& progress,
                   std::vector<PhotoFinding>& findings) {
    const auto& windows = seams.windows();
    std::vector<int> order;
    for (int i = 0; i < static_cast<int>(photos.size()); ++i)
        if (use.active[i])
            order.push_back(i);
    Stage warpStage{progress, 0.25, 0.55, "warping photos"};
    warpStage(0.0);
    std::atomic<int> warped{0};
    std::mutex findingsMutex;
    std::string ioError;
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
            use.active[i] = 0;
            use.status[i] = "left out: " + msg;
            findings.push_back({geo::detail::fileName(photos[i].meta.path),
                                PhotoFinding::Kind::Unreadable, true, msg});
        };
        auto rgb = warpPhoto(photos[i].meta.path, use.geoms[i], ground, grid, w);
        if (!rgb) {
            fail(rgb.error().message, false);
            return;
        }
        std::vector<std::uint16_t> best, second;
        if (Status st = seams.read(w, &best, &second); !st) {
            fail(st.error().message, true);
            return;
        }
        std::vector<float> weight;
        std::vector<std::uint8_t> opaque;
        seamWeights(i, w, best, second, use.geoms, ground, grid, featherGrid, weight, opaque);
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
    return {};
}

} // namespace pf::mosaic::detail
