// Generates the bundled offline demo map: a SYNTHETIC terrain of the demo site as a GeoTIFF (EPSG:3857).
//
// Nothing here is real imagery. Fields, river, roads and buildings are drawn procedurally around the
// fixed demo site ("Rheinhafen training ground", a fictional site near Karlsruhe) so that the
// application shows a plausible map without any network or downloaded data. The image carries a
// visible "synthetic" label and the file carries the same statement in its metadata.
//
// Usage: pf_demo_map_generator OUTPUT.tif
#include <cpl_conv.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <QFont>
#include <QGuiApplication>
#include <QImage>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

namespace {

constexpr double kEarthRadius = 6378137.0; // EPSG:3857 sphere
constexpr double kPi = 3.14159265358979323846;
// Map extent (fixed for the demo site).
constexpr double kLonMin = 8.3230, kLonMax = 8.3370, kLatMin = 49.0085, kLatMax = 49.0160;
constexpr double kPixelSize = 0.5; // Web Mercator metres per pixel (about 0.33 m on the ground)

double mercX(double lon) { return kEarthRadius * lon * kPi / 180.0; }
double mercY(double lat) { return kEarthRadius * std::log(std::tan(kPi / 4.0 + lat * kPi / 360.0)); }

struct Canvas {
    double x0 = mercX(kLonMin), y0 = mercY(kLatMax); // top-left corner
    int width = int(std::ceil((mercX(kLonMax) - mercX(kLonMin)) / kPixelSize));
    int height = int(std::ceil((mercY(kLatMax) - mercY(kLatMin)) / kPixelSize));
    QPointF px(double lon, double lat) const {
        return {(mercX(lon) - x0) / kPixelSize, (y0 - mercY(lat)) / kPixelSize};
    }
    // Pixels per ground metre at the site's latitude (Web Mercator stretches by 1/cos(lat)).
    double perMetre() const { return 1.0 / (kPixelSize * std::cos(49.012 * kPi / 180.0)); }
};

// Deterministic value noise (fractal sum of octaves) so every build produces the same map.
class Noise {
public:
    explicit Noise(unsigned seed) {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<float> u(0.f, 1.f);
        for (auto& v : m_values) v = u(rng);
    }
    float at(double x, double y) const {
        const int xi = int(std::floor(x)), yi = int(std::floor(y));
        const double fx = x - xi, fy = y - yi;
        const double sx = fx * fx * (3 - 2 * fx), sy = fy * fy * (3 - 2 * fy);
        const double a = v(xi, yi), b = v(xi + 1, yi), c = v(xi, yi + 1), d = v(xi + 1, yi + 1);
        return float((a + (b - a) * sx) * (1 - sy) + (c + (d - c) * sx) * sy);
    }
    float fbm(double x, double y, int octaves) const {
        float sum = 0, amp = 0.5f, norm = 0;
        for (int o = 0; o < octaves; ++o) {
            sum += amp * at(x, y);
            norm += amp;
            x *= 2.03;
            y *= 2.03;
            amp *= 0.5f;
        }
        return sum / norm;
    }

private:
    float v(int x, int y) const {
        const unsigned h = (unsigned(x) * 73856093u) ^ (unsigned(y) * 19349663u);
        return m_values[h % m_values.size()];
    }
    std::vector<float> m_values = std::vector<float>(65536);
};

QPolygonF ring(const Canvas& c, std::initializer_list<std::pair<double, double>> lonLat) {
    QPolygonF p;
    for (const auto& [lon, lat] : lonLat) p << c.px(lon, lat);
    return p;
}

void drawFields(QPainter& p, const Canvas& c, std::mt19937& rng) {
    // Long narrow strips in blocks, like the parcels of the Upper Rhine plain.
    const QColor palette[] = {QColor(196, 178, 112), QColor(120, 150, 70), QColor(150, 120, 84),
                              QColor(104, 138, 62), QColor(170, 160, 96), QColor(136, 160, 88),
                              QColor(128, 104, 76)};
    std::uniform_int_distribution<int> colour(0, 6);
    std::uniform_real_distribution<double> width(18.0, 45.0), angle(-25.0, 25.0);
    const double m = c.perMetre();
    for (int by = 0; by < 4; ++by) {
        for (int bx = 0; bx < 5; ++bx) {
            const double blockW = c.width / 5.0, blockH = c.height / 4.0;
            p.save();
            p.translate(bx * blockW + blockW / 2, by * blockH + blockH / 2);
            p.rotate(angle(rng));
            double x = -blockW * 0.75;
            while (x < blockW * 0.75) {
                const double w = width(rng) * m;
                const QColor col = palette[colour(rng)];
                const QRectF strip(x, -blockH * 0.75, w, blockH * 1.5);
                p.fillRect(strip, col);
                // Crop rows: faint lines along the strip.
                p.setPen(QPen(col.darker(112), 1.2));
                for (double r = x + 2; r < x + w - 1; r += 3.5) p.drawLine(QPointF(r, strip.top()), QPointF(r, strip.bottom()));
                // A narrow grass margin between parcels.
                p.setPen(QPen(QColor(96, 124, 58), 1.5 * m));
                p.drawLine(QPointF(x, strip.top()), QPointF(x, strip.bottom()));
                x += w;
            }
            p.restore();
        }
    }
}

void drawTree(QPainter& p, QPointF centre, double radius, std::mt19937& rng) {
    std::uniform_int_distribution<int> shade(-12, 12);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(20, 35, 15, 110)); // shadow towards the north-east (sun in the south-west)
    p.drawEllipse(centre + QPointF(radius * 0.45, -radius * 0.45), radius, radius);
    const int s = shade(rng);
    p.setBrush(QColor(48 + s, 86 + s, 38 + s));
    p.drawEllipse(centre, radius, radius);
    p.setBrush(QColor(72 + s, 112 + s, 52 + s, 160));
    p.drawEllipse(centre - QPointF(radius * 0.25, -radius * 0.25), radius * 0.55, radius * 0.55);
}

void drawBuilding(QPainter& p, const QPolygonF& roof, QColor colour, double shadowPx) {
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(20, 20, 10, 70));
    p.drawPolygon(roof.translated(shadowPx, -shadowPx));
    p.setBrush(colour);
    p.setPen(QPen(colour.darker(135), 1.5));
    p.drawPolygon(roof);
}

void drawLabel(QPainter& p, QPointF at, const QString& text, int pixelSize, bool box) {
    QFont f(QStringLiteral("DejaVu Sans"));
    f.setPixelSize(pixelSize);
    f.setBold(true);
    p.setFont(f);
    const QRectF r = QRectF(p.fontMetrics().boundingRect(text)).adjusted(-10, -6, 10, 6).translated(at);
    if (box) {
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(255, 255, 255, 200));
        p.drawRoundedRect(r, 6, 6);
    }
    p.setPen(QColor(150, 20, 20));
    p.drawText(r, Qt::AlignCenter, text);
}

QImage paintTerrain(const Canvas& c) {
    QImage img(c.width, c.height, QImage::Format_RGB32);
    img.fill(QColor(112, 140, 70));
    std::mt19937 rng(20240607);
    const double m = c.perMetre();
    QPainter p(&img);
    p.setRenderHint(QPainter::Antialiasing);

    drawFields(p, c, rng);

    // The river and its banks across the north of the map.
    QPainterPath river;
    river.moveTo(c.px(8.3225, 49.01505));
    river.cubicTo(c.px(8.3270, 49.01565), c.px(8.3310, 49.01445), c.px(8.3375, 49.01470));
    p.setBrush(Qt::NoBrush);
    p.setPen(QPen(QColor(150, 170, 110), 95 * m, Qt::SolidLine, Qt::FlatCap));
    p.drawPath(river);
    p.setPen(QPen(QColor(52, 96, 128), 70 * m, Qt::SolidLine, Qt::FlatCap));
    p.drawPath(river);
    p.setPen(QPen(QColor(70, 118, 150), 40 * m, Qt::SolidLine, Qt::FlatCap));
    p.drawPath(river);
    // Harbour basin reaching south towards the site.
    const QPolygonF basin = ring(c, {{8.3336, 49.01475}, {8.3352, 49.01475}, {8.3352, 49.01370}, {8.3336, 49.01370}});
    p.setPen(QPen(QColor(160, 160, 150), 3 * m));
    p.setBrush(QColor(58, 104, 136));
    p.drawPolygon(basin);
    // Trees along the southern bank.
    std::uniform_real_distribution<double> jitter(-6.0, 6.0), radius(3.0, 6.0);
    for (double lon = 8.3228; lon < 8.3372; lon += 0.00011) {
        const double t = (lon - 8.3225) / 0.0150;
        const double lat = 49.01505 + t * (49.01470 - 49.01505) - 0.00058 + 0.00018 * std::sin(t * 5.0);
        if (lon > 8.3333 && lon < 8.3355) continue;
        drawTree(p, c.px(lon, lat) + QPointF(jitter(rng) * m, jitter(rng) * m), radius(rng) * m, rng);
    }

    // The training ground: gravel and compacted soil, a concrete pad and rubble piles.
    const QPolygonF site = ring(c, {{8.32715, 49.01083}, {8.33255, 49.01074}, {8.33285, 49.01244},
                                    {8.33090, 49.01262}, {8.33063, 49.01343}, {8.32727, 49.01334}});
    p.setPen(QPen(QColor(120, 110, 90), 2 * m));
    p.setBrush(QColor(176, 164, 138));
    p.drawPolygon(site);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(196, 194, 186));
    p.drawPolygon(ring(c, {{8.3278, 49.0112}, {8.3287, 49.0112}, {8.3287, 49.0118}, {8.3278, 49.0118}}));
    std::uniform_real_distribution<double> rubbleX(8.3276, 8.3290), rubbleY(49.0122, 49.0130), size(2.0, 5.0);
    for (int i = 0; i < 40; ++i) {
        const QPointF at = c.px(rubbleX(rng), rubbleY(rng));
        const double r = size(rng) * m;
        p.setBrush(QColor(0, 0, 0, 70));
        p.drawEllipse(at + QPointF(r * 0.4, -r * 0.4), r, r * 0.8);
        p.setBrush(QColor(150, 140, 128));
        p.drawEllipse(at, r, r * 0.8);
    }
    // Tracks inside the site.
    p.setBrush(Qt::NoBrush);
    p.setPen(QPen(QColor(150, 136, 110), 5 * m, Qt::SolidLine, Qt::RoundCap));
    QPainterPath track;
    track.moveTo(c.px(8.3274, 49.0110));
    track.cubicTo(c.px(8.3290, 49.0111), c.px(8.3300, 49.0125), c.px(8.3322, 49.0121));
    p.drawPath(track);

    // Roads: Hafenstrasse (east-west, south of the site) and a north-south access road.
    auto road = [&](std::initializer_list<std::pair<double, double>> pts, double widthM) {
        QPolygonF line = ring(c, pts);
        p.setBrush(Qt::NoBrush);
        p.setPen(QPen(QColor(235, 232, 222), (widthM + 3) * m, Qt::SolidLine, Qt::FlatCap, Qt::RoundJoin));
        p.drawPolyline(line);
        p.setPen(QPen(QColor(92, 92, 96), widthM * m, Qt::SolidLine, Qt::FlatCap, Qt::RoundJoin));
        p.drawPolyline(line);
        QPen dash(QColor(240, 240, 240), 0.25 * m, Qt::CustomDashLine, Qt::FlatCap);
        dash.setDashPattern({12.0, 12.0});
        p.setPen(dash);
        p.drawPolyline(line);
    };
    road({{8.3225, 49.01005}, {8.3300, 49.01000}, {8.3375, 49.00985}}, 8.0);
    road({{8.32605, 49.0080}, {8.32615, 49.0120}, {8.32570, 49.0165}}, 7.0);
    road({{8.3345, 49.0080}, {8.3342, 49.0136}}, 7.0);

    // The warehouse (no-fly zone "Warehouse"): a corrugated metal roof with a ridge.
    const QPolygonF warehouse = ring(c, {{8.3291782, 49.0118201}, {8.3297261, 49.0118201},
                                         {8.3297261, 49.0121799}, {8.3291782, 49.0121799}});
    drawBuilding(p, warehouse, QColor(150, 158, 166), 3.5 * m);
    const QRectF wr = warehouse.boundingRect();
    p.setPen(QPen(QColor(128, 136, 144), 1.0));
    for (double x = wr.left() + 3; x < wr.right(); x += 4) p.drawLine(QPointF(x, wr.top()), QPointF(x, wr.bottom()));
    p.setPen(QPen(QColor(200, 206, 212), 2.0 * m));
    p.drawLine(QPointF(wr.left(), wr.center().y()), QPointF(wr.right(), wr.center().y()));

    // The radio mast (no-fly zone "Radio mast"): base, guy wires and a long shadow.
    const QPointF mast = c.px(8.3316435, 49.0115504);
    p.setPen(QPen(QColor(20, 20, 20, 120), 1.2 * m));
    p.drawLine(mast, mast + QPointF(45 * m, -45 * m));
    p.setPen(QPen(QColor(220, 220, 220), 0.6 * m));
    for (int k = 0; k < 3; ++k) {
        const double a = k * 2 * kPi / 3 + 0.3;
        p.drawLine(mast, mast + QPointF(std::cos(a), std::sin(a)) * 16 * m);
    }
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(205, 205, 200));
    p.drawRect(QRectF(mast - QPointF(3 * m, 3 * m), QSizeF(6 * m, 6 * m)));
    p.setBrush(QColor(200, 40, 30));
    p.drawEllipse(mast, 1.5 * m, 1.5 * m);

    // Harbour industry east of the site.
    std::uniform_int_distribution<int> grey(130, 185);
    const double blocks[][4] = {{8.33480, 49.01050, 8.33600, 49.01120}, {8.33480, 49.01150, 8.33580, 49.01230},
                                {8.33620, 49.01060, 8.33690, 49.01180}, {8.33460, 49.01260, 8.33560, 49.01330},
                                {8.33600, 49.01240, 8.33690, 49.01320}, {8.32300, 49.01150, 8.32420, 49.01210}};
    for (const auto& b : blocks) {
        const int g = grey(rng);
        drawBuilding(p, ring(c, {{b[0], b[1]}, {b[2], b[1]}, {b[2], b[3]}, {b[0], b[3]}}), QColor(g, g - 6, g - 14), 3.5 * m);
    }
    // A car park with parked cars.
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(120, 120, 124));
    p.drawPolygon(ring(c, {{8.3347, 49.0090}, {8.3366, 49.0090}, {8.3366, 49.0096}, {8.3347, 49.0096}}));
    std::uniform_int_distribution<int> carColour(0, 4);
    const QColor cars[] = {QColor(230, 230, 230), QColor(30, 30, 40), QColor(160, 30, 30), QColor(40, 70, 150),
                           QColor(150, 150, 155)};
    for (int i = 0; i < 14; ++i) {
        const QPointF at = c.px(8.33480 + i * 0.00012, 49.00945);
        p.setBrush(cars[carColour(rng)]);
        p.drawRoundedRect(QRectF(at, QSizeF(2 * m, 4.5 * m)), 0.5 * m, 0.5 * m);
    }
    // Hedges and single trees between fields.
    std::uniform_real_distribution<double> lonR(kLonMin, kLonMax), latR(kLatMin, 49.0103);
    for (int i = 0; i < 90; ++i) drawTree(p, c.px(lonR(rng), latR(rng)), radius(rng) * m, rng);

    // The label that makes clear this is not imagery.
    drawLabel(p, QPointF(c.width * 0.04, c.height * 0.92), QStringLiteral("SYNTHETIC DEMO MAP - NOT REAL IMAGERY"), 34, true);
    drawLabel(p, QPointF(c.width * 0.55, c.height * 0.03), QStringLiteral("SYNTHETIC DEMO MAP - generated by Photoflight"), 26, true);
    drawLabel(p, c.px(8.3276, 49.01365), QStringLiteral("Rheinhafen training ground (fictional)"), 20, true);
    p.end();

    // Texture: low-frequency brightness variation plus fine grain, so the map does not look flat.
    const Noise broad(7), grain(11);
    for (int y = 0; y < img.height(); ++y) {
        auto* row = reinterpret_cast<QRgb*>(img.scanLine(y));
        for (int x = 0; x < img.width(); ++x) {
            const double f = 0.88 + 0.24 * broad.fbm(x / 180.0, y / 180.0, 4) + 0.10 * (grain.at(x * 0.7, y * 0.7) - 0.5);
            const QRgb v = row[x];
            row[x] = qRgb(std::clamp(int(qRed(v) * f), 0, 255), std::clamp(int(qGreen(v) * f), 0, 255),
                          std::clamp(int(qBlue(v) * f), 0, 255));
        }
    }
    return img;
}

bool writeGeoTiff(const QImage& img, const Canvas& c, const char* path) {
    GDALAllRegister();
    GDALDriverH mem = GDALGetDriverByName("MEM");
    GDALDriverH gtiff = GDALGetDriverByName("GTiff");
    if (!mem || !gtiff) {
        std::fprintf(stderr, "GDAL has no MEM or GTiff driver\n");
        return false;
    }
    GDALDatasetH ds = GDALCreate(mem, "", img.width(), img.height(), 3, GDT_Byte, nullptr);
    double gt[6] = {c.x0, kPixelSize, 0.0, c.y0, 0.0, -kPixelSize};
    GDALSetGeoTransform(ds, gt);
    OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
    OSRImportFromEPSG(srs, 3857);
    GDALSetSpatialRef(ds, srs);
    OSRDestroySpatialReference(srs);
    // QImage RGB32 is stored as B, G, R, A bytes on little-endian machines; qRed() etc. are portable.
    std::vector<std::uint8_t> band(std::size_t(img.width()) * img.height());
    for (int b = 0; b < 3; ++b) {
        for (int y = 0; y < img.height(); ++y) {
            const auto* row = reinterpret_cast<const QRgb*>(img.constScanLine(y));
            for (int x = 0; x < img.width(); ++x) {
                const QRgb v = row[x];
                band[std::size_t(y) * img.width() + x] = std::uint8_t(b == 0 ? qRed(v) : b == 1 ? qGreen(v) : qBlue(v));
            }
        }
        if (GDALRasterIO(GDALGetRasterBand(ds, b + 1), GF_Write, 0, 0, img.width(), img.height(), band.data(),
                         img.width(), img.height(), GDT_Byte, 0, 0) != CE_None)
            return false;
    }
    const char* description = "SYNTHETIC demo map of the fictional Rheinhafen training ground, generated "
                              "procedurally by Photoflight's maps/demo_map_generator. Not real imagery.";
    GDALSetMetadataItem(ds, "TIFFTAG_IMAGEDESCRIPTION", description, nullptr);
    GDALSetMetadataItem(ds, "TIFFTAG_SOFTWARE", "Photoflight demo map generator", nullptr);
    GDALSetMetadataItem(ds, "PF_SYNTHETIC", "YES", nullptr);
    GDALSetMetadataItem(ds, "PF_DESCRIPTION", description, nullptr);

    const char* options[] = {"TILED=YES", "COMPRESS=JPEG", "PHOTOMETRIC=YCBCR", "JPEG_QUALITY=85", nullptr};
    GDALDatasetH out = GDALCreateCopy(gtiff, path, ds, FALSE, const_cast<char**>(options), nullptr, nullptr);
    GDALClose(ds);
    if (!out) {
        std::fprintf(stderr, "cannot write %s: %s\n", path, CPLGetLastErrorMsg());
        return false;
    }
    // Internal overviews so that zoomed-out views read few pixels.
    CPLSetConfigOption("COMPRESS_OVERVIEW", "JPEG");
    CPLSetConfigOption("PHOTOMETRIC_OVERVIEW", "YCBCR");
    CPLSetConfigOption("INTERLEAVE_OVERVIEW", "PIXEL");
    int levels[] = {2, 4, 8, 16, 32};
    const CPLErr err = GDALBuildOverviews(out, "AVERAGE", 5, levels, 0, nullptr, nullptr, nullptr);
    GDALClose(out);
    if (err != CE_None) {
        std::fprintf(stderr, "cannot build overviews of %s: %s\n", path, CPLGetLastErrorMsg());
        return false;
    }
    return true;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s OUTPUT.tif\n", argv[0]);
        return 2;
    }
    // Text needs a font database, hence a GUI application; no window is ever shown.
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    QGuiApplication app(argc, argv);
    const Canvas canvas;
    const QImage img = paintTerrain(canvas);
    if (!writeGeoTiff(img, canvas, argv[1])) return 1;
    std::printf("wrote synthetic demo map %s (%dx%d px)\n", argv[1], img.width(), img.height());
    return 0;
}
