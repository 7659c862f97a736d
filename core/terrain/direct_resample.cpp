#include "core/terrain/direct_resample.h"

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace pf::terrain::detail {

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr double kMaxErrorPx = 0.01;
constexpr std::size_t kMaxBufferPx = 64'000'000; // the window read: at most 256 MB of Float32

// Grid nodes -> source pixel coordinates, exact on the nodes of a lattice `step` nodes apart (and
// on the last row and column), bilinear in between.
struct Lattice {
    int step = 32, lc = 0, lr = 0, cols = 0, rows = 0;
    std::vector<double> px, py;
    int col(int a) const { return std::min(a * step, cols - 1); }
    int row(int b) const { return std::min(b * step, rows - 1); }
};

class Mapper {
public:
    Mapper(OGRCoordinateTransformation& ct, const double* inv, double x0, double y0, double spacing)
        : m_ct(ct), m_inv(inv), m_x0(x0), m_y0(y0), m_spacing(spacing) {}
    // Grid nodes (as fractional columns and rows) to pixel coordinates in place; false if PROJ
    // refuses one.
    bool toPixel(std::vector<double>& x, std::vector<double>& y) const {
        for (std::size_t i = 0; i < x.size(); ++i) {
            x[i] = m_x0 + x[i] * m_spacing;
            y[i] = m_y0 - y[i] * m_spacing;
        }
        std::vector<int> ok(x.size(), 0);
        if (!x.empty() && !m_ct.Transform(x.size(), x.data(), y.data(), nullptr, ok.data()))
            return false;
        for (std::size_t i = 0; i < x.size(); ++i) {
            if (!ok[i] || !std::isfinite(x[i]) || !std::isfinite(y[i]))
                return false;
            const double gx = x[i], gy = y[i];
            x[i] = m_inv[0] + gx * m_inv[1] + gy * m_inv[2];
            y[i] = m_inv[3] + gx * m_inv[4] + gy * m_inv[5];
        }
        return true;
    }

private:
    OGRCoordinateTransformation& m_ct;
    const double* m_inv;
    double m_x0, m_y0, m_spacing;
};

bool buildLattice(const Mapper& map, int cols, int rows, int step, Lattice& l) {
    l.step = step;
    l.cols = cols;
    l.rows = rows;
    l.lc = (cols - 1 + step - 1) / step + 1;
    l.lr = (rows - 1 + step - 1) / step + 1;
    l.px.resize(static_cast<std::size_t>(l.lc) * l.lr);
    l.py.resize(l.px.size());
    for (int b = 0; b < l.lr; ++b)
        for (int a = 0; a < l.lc; ++a) {
            l.px[static_cast<std::size_t>(b) * l.lc + a] = l.col(a);
            l.py[static_cast<std::size_t>(b) * l.lc + a] = l.row(b);
        }
    return map.toPixel(l.px, l.py);
}

// The largest distance, in pixels, between the exact position of the lattice cells' centres and
// the interpolated one; negative if PROJ refuses one.
double latticeError(const Mapper& map, const Lattice& l) {
    if (l.step == 1)
        return 0.0;
    std::vector<double> x, y, ix, iy;
    for (int b = 0; b + 1 < l.lr; ++b)
        for (int a = 0; a + 1 < l.lc; ++a) {
            const double c = 0.5 * (l.col(a) + l.col(a + 1)), r = 0.5 * (l.row(b) + l.row(b + 1));
            x.push_back(c);
            y.push_back(r);
            const std::size_t k = static_cast<std::size_t>(b) * l.lc + a;
            ix.push_back(0.25 * (l.px[k] + l.px[k + 1] + l.px[k + l.lc] + l.px[k + l.lc + 1]));
            iy.push_back(0.25 * (l.py[k] + l.py[k + 1] + l.py[k + l.lc] + l.py[k + l.lc + 1]));
        }
    if (!map.toPixel(x, y))
        return -1.0;
    double worst = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i)
        worst = std::max(worst, std::hypot(x[i] - ix[i], y[i] - iy[i]));
    return worst;
}

} // namespace

Result<bool> resampleDirect(const SourceRaster& src, const std::string& srs, double x0, double y0,
                            double spacingM, int cols, int rows, std::vector<float>& out) {
    if (!src.band || !src.invGeoTransform || src.horizontalWkt.empty() || cols < 1 || rows < 1)
        return false;
    OGRSpatialReference dst, source;
    if (dst.SetFromUserInput(srs.c_str()) != OGRERR_NONE ||
        source.importFromWkt(src.horizontalWkt.c_str()) != OGRERR_NONE)
        return false;
    dst.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    source.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    std::unique_ptr<OGRCoordinateTransformation> ct(
        OGRCreateCoordinateTransformation(&dst, &source));
    if (!ct)
        return false;
    const Mapper map(*ct, src.invGeoTransform, x0, y0, spacingM);

    // A lattice fine enough for 1 % of a pixel.
    Lattice l;
    int step = 32;
    for (;;) {
        if (!buildLattice(map, cols, rows, step, l))
            return false;
        const double err = latticeError(map, l);
        if (err < 0)
            return false;
        if (err <= kMaxErrorPx || step == 1)
            break;
        step = std::max(1, step / 4);
    }

    // The window of the DEM the grid needs, and how much it may be averaged down on reading.
    const double W = src.widthPx, H = src.heightPx;
    const auto [xMin, xMax] = std::minmax_element(l.px.begin(), l.px.end());
    const auto [yMin, yMax] = std::minmax_element(l.py.begin(), l.py.end());
    const int wx0 = static_cast<int>(std::clamp(std::floor(*xMin) - 2, 0.0, W));
    const int wx1 = static_cast<int>(std::clamp(std::ceil(*xMax) + 2, 0.0, W));
    const int wy0 = static_cast<int>(std::clamp(std::floor(*yMin) - 2, 0.0, H));
    const int wy1 = static_cast<int>(std::clamp(std::ceil(*yMax) + 2, 0.0, H));
    std::fill(out.begin(), out.end(), kNaN);
    if (wx1 <= wx0 || wy1 <= wy0)
        return true; // the grid lies beside the DEM
    const int winW = wx1 - wx0, winH = wy1 - wy0;
    double ratio = std::numeric_limits<double>::infinity(); // source pixels per grid spacing
    if (l.lc > 1)
        ratio = std::min(ratio,
                         std::hypot(l.px[1] - l.px[0], l.py[1] - l.py[0]) / (l.col(1) - l.col(0)));
    if (l.lr > 1)
        ratio = std::min(ratio, std::hypot(l.px[l.lc] - l.px[0], l.py[l.lc] - l.py[0]) /
                                    (l.row(1) - l.row(0)));
    int factor = std::isfinite(ratio) && ratio >= 2.0 ? static_cast<int>(std::floor(ratio)) : 1;
    while (static_cast<std::size_t>((winW + factor - 1) / factor) *
               static_cast<std::size_t>((winH + factor - 1) / factor) >
           kMaxBufferPx)
        ++factor;
    const int bw = (winW + factor - 1) / factor, bh = (winH + factor - 1) / factor;
    std::vector<float> buf(static_cast<std::size_t>(bw) * bh);
    GDALRasterIOExtraArg extra;
    INIT_RASTERIO_EXTRA_ARG(extra);
    extra.eResampleAlg = factor > 1 ? GRIORA_Average : GRIORA_NearestNeighbour;
    if (src.band->RasterIO(GF_Read, wx0, wy0, winW, winH, buf.data(), bw, bh, GDT_Float32, 0, 0,
                           &extra) != CE_None)
        return makeError(ErrorCode::IoError, "its heights cannot be read");
    if (src.noData) {
        const float nd = static_cast<float>(*src.noData);
        for (float& v : buf)
            if (v == nd)
                v = kNaN;
    }
    if (src.maskBand) {
        std::vector<GByte> mask(buf.size());
        GDALRasterBand* mb = src.band->GetMaskBand();
        if (!mb || mb->RasterIO(GF_Read, wx0, wy0, winW, winH, mask.data(), bw, bh, GDT_Byte, 0, 0,
                                nullptr) != CE_None)
            return makeError(ErrorCode::IoError, "its no-data mask cannot be read");
        for (std::size_t i = 0; i < buf.size(); ++i)
            if (!mask[i])
                buf[i] = kNaN;
    }

    // Bilinear at every node; the pixel holding the node must have data (as GDAL's warper).
    const double sx = static_cast<double>(winW) / bw, sy = static_cast<double>(winH) / bh;
    const double isx = 1.0 / sx, isy = 1.0 / sy;
    auto edgeSample = [&](double fx, double fy) -> float {
        const int hx = std::clamp(static_cast<int>(fx), 0, bw - 1),
                  hy = std::clamp(static_cast<int>(fy), 0, bh - 1);
        if (std::isnan(buf[static_cast<std::size_t>(hy) * bw + hx]))
            return kNaN;
        const double bx = fx - 0.5, by = fy - 0.5;
        const int i0 = static_cast<int>(std::floor(bx)), j0 = static_cast<int>(std::floor(by));
        const double tx = bx - i0, ty = by - j0;
        double sum = 0.0, wsum = 0.0;
        for (int dj = 0; dj < 2; ++dj)
            for (int di = 0; di < 2; ++di) {
                const int i = std::clamp(i0 + di, 0, bw - 1), j = std::clamp(j0 + dj, 0, bh - 1);
                const float v = buf[static_cast<std::size_t>(j) * bw + i];
                const double w = (di ? tx : 1 - tx) * (dj ? ty : 1 - ty);
                if (!std::isnan(v) && w > 0) {
                    sum += w * v;
                    wsum += w;
                }
            }
        return wsum > 1e-9 ? static_cast<float>(sum / wsum)
                           : buf[static_cast<std::size_t>(hy) * bw + hx];
    };
    auto sample = [&](double px, double py) -> float {
        if (!(px >= 0 && py >= 0 && px <= W && py <= H))
            return kNaN;
        const double fx = (px - wx0) * isx, fy = (py - wy0) * isy;
        // Inside the window with four known pixels: plain bilinear (nearly every node).
        const double bx = fx - 0.5, by = fy - 0.5;
        if (bx >= 0 && by >= 0) {
            const int i0 = static_cast<int>(bx), j0 = static_cast<int>(by);
            if (i0 + 1 < bw && j0 + 1 < bh) {
                const float* q = buf.data() + static_cast<std::size_t>(j0) * bw + i0;
                const double tx = bx - i0, ty = by - j0;
                const double v = (q[0] * (1 - tx) + q[1] * tx) * (1 - ty) +
                                 (q[bw] * (1 - tx) + q[bw + 1] * tx) * ty;
                if (!std::isnan(v))
                    return static_cast<float>(v);
            }
        }
        return edgeSample(fx, fy);
    };
    for (int r = 0; r < rows; ++r) {
        const int b = std::min(r / l.step, std::max(l.lr - 2, 0));
        const int r0 = l.row(b), r1 = l.lr > 1 ? l.row(b + 1) : r0;
        const double ty = r1 > r0 ? static_cast<double>(r - r0) / (r1 - r0) : 0.0;
        float* line = out.data() + static_cast<std::size_t>(r) * cols;
        for (int a = 0; a + 1 < l.lc || a == 0; ++a) {
            const std::size_t k0 = static_cast<std::size_t>(b) * l.lc + a;
            const std::size_t k1 = l.lr > 1 ? k0 + l.lc : k0;
            const std::size_t a1 = l.lc > 1 ? 1 : 0;
            const double lx0 = l.px[k0] + (l.px[k1] - l.px[k0]) * ty,
                         ly0 = l.py[k0] + (l.py[k1] - l.py[k0]) * ty;
            const double lx1 = l.px[k0 + a1] + (l.px[k1 + a1] - l.px[k0 + a1]) * ty;
            const double ly1 = l.py[k0 + a1] + (l.py[k1 + a1] - l.py[k0 + a1]) * ty;
            const int c0 = l.col(a), c1 = l.lc > 1 ? l.col(a + 1) : c0;
            const int cEnd = (a + 2 >= l.lc) ? cols : c1; // the last cell takes its end column
            for (int c = c0; c < cEnd; ++c) {
                const double tx = c1 > c0 ? static_cast<double>(c - c0) / (c1 - c0) : 0.0;
                line[c] = sample(lx0 + (lx1 - lx0) * tx, ly0 + (ly1 - ly0) * tx);
            }
            if (l.lc == 1)
                break;
        }
    }
    return true;
}

} // namespace pf::terrain::detail
