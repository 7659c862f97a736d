// Base maps and the map canvas: the demo map's tiles, other rasters in other CRSs, zoom and pan.
#include "ui/map/base_maps.h"
#include "ui/map/gdal_tile_source.h"
#include "ui/map/tile_layer.h"
#include "ui/map/web_mercator.h"
#include "ui/mission_document.h"
#include "ui_test_util.h"

#include <cpl_conv.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <QFile>
#include <QTemporaryDir>
#include <QWheelEvent>

#include <gtest/gtest.h>

#include <set>

using namespace pf;
using namespace pf::ui;

namespace {

TileKey tileAt(const geo::LonLat& p, int z) {
    const QPointF s = toScene(p);
    const double span = mercator::tileSpan(z);
    return {z, int((s.x() + mercator::kHalfWorld) / span), int((s.y() + mercator::kHalfWorld) / span)};
}

int distinctColours(const QImage& img) {
    std::set<QRgb> colours;
    for (int y = 0; y < img.height(); y += 4)
        for (int x = 0; x < img.width(); x += 4) colours.insert(img.pixel(x, y));
    return int(colours.size());
}

// Writes a small GeoTIFF in UTM zone 32N (EPSG:25832) over the demo site: left half red, right half blue.
QString writeUtmRaster(const QString& dir) {
    GDALAllRegister();
    const QString path = dir + QStringLiteral("/utm.tif");
    GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), path.toUtf8().constData(), 200, 100, 3, GDT_Byte, nullptr);
    // The demo site is near E 456 000, N 5 429 000 in UTM 32N; 2 m pixels.
    double gt[6] = {455600.0, 2.0, 0.0, 5429300.0, 0.0, -2.0};
    GDALSetGeoTransform(ds, gt);
    OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
    OSRImportFromEPSG(srs, 25832);
    GDALSetSpatialRef(ds, srs);
    OSRDestroySpatialReference(srs);
    std::vector<unsigned char> band(200 * 100);
    for (int b = 0; b < 3; ++b) {
        for (int y = 0; y < 100; ++y)
            for (int x = 0; x < 200; ++x) band[std::size_t(y * 200 + x)] = (b == 0 && x < 100) || (b == 2 && x >= 100) ? 220 : 20;
        EXPECT_EQ(GDALRasterIO(GDALGetRasterBand(ds, b + 1), GF_Write, 0, 0, 200, 100, band.data(), 200, 100, GDT_Byte, 0, 0),
                  CE_None);
    }
    GDALClose(ds);
    return path;
}

} // namespace

TEST(DemoMap, IsFoundSyntheticAndRendersNonEmptyTiles) {
    const QString path = demoMapPath();
    ASSERT_FALSE(path.isEmpty()) << "the build generates maps/demo_map.tif";
    QString error;
    auto src = GdalTileSource::open(path, QStringLiteral("demo"), &error);
    ASSERT_TRUE(src) << error.toStdString();
    EXPECT_EQ(src->metadataItem(QStringLiteral("PF_SYNTHETIC")), QStringLiteral("YES"));
    EXPECT_GE(src->maxZoom(), 17);
    // The coverage is the demo map extent.
    EXPECT_TRUE(src->coverage().contains(toScene({8.3300, 49.0120})));
    EXPECT_FALSE(src->coverage().contains(toScene({8.3400, 49.0120})));

    // Tiles at several zooms over the site have real picture content (not one flat colour).
    for (int z : {14, 16, 18}) {
        const QImage tile = src->renderTile(tileAt({8.3300, 49.0120}, z));
        ASSERT_FALSE(tile.isNull()) << "z " << z;
        EXPECT_EQ(tile.size(), QSize(256, 256));
        EXPECT_GT(distinctColours(tile), 50) << "z " << z;
    }
    // A tile far away from the map is empty (null), not an error.
    EXPECT_TRUE(src->renderTile(tileAt({2.35, 48.85}, 16)).isNull());
}

TEST(DemoMap, TilesAreRenderedInTheBackgroundAndParentsFillTheGaps) {
    auto w = test::makeWindow();
    auto* tiles = w->tileLayer();
    ASSERT_TRUE(w->waitForMap(20000));
    EXPECT_GT(tiles->cachedCount(), 0);
    EXPECT_EQ(tiles->pendingCount(), 0);
    const int z = mercator::zoomForResolution(w->mapView()->metresPerPixel());
    const QImage tile = tiles->cachedTile(tileAt({8.3300, 49.0120}, std::min(z, tiles->source()->maxZoom())));
    ASSERT_FALSE(tile.isNull());
    EXPECT_GT(distinctColours(tile), 50);

    // Zoom in one level: the first paint has no tiles of the new level yet and draws their scaled
    // parents instead of blanks; then the real tiles arrive.
    w->mapView()->zoomBy(2.0);
    w->mapView()->viewport()->grab();
    EXPECT_GT(tiles->lastFallbackCount(), 0);
    EXPECT_EQ(tiles->lastFallbackCount(), tiles->lastMissingCount());
    ASSERT_TRUE(w->waitForMap(20000));
    EXPECT_EQ(tiles->lastMissingCount(), 0);

    // The rendered window shows the map: many colours, not a flat background.
    const QImage shot = w->mapView()->viewport()->grab().toImage();
    EXPECT_GT(distinctColours(shot), 200);
}

TEST(BaseMaps, RasterInAnotherCrsIsWarpedOnTheFly) {
    QTemporaryDir dir;
    const QString path = writeUtmRaster(dir.path());
    QString error;
    auto src = openMapFile(path, &error);
    ASSERT_TRUE(src) << error.toStdString();
    // The raster's centre line in UTM (E 455 800) is about lon 8.3965; left is red, right is blue.
    const QRectF cov = src->coverage();
    ASSERT_FALSE(cov.isEmpty());
    const int z = 17;
    const geo::LonLat centre = fromScene(cov.center());
    const QImage tile = src->renderTile(tileAt(centre, z));
    ASSERT_FALSE(tile.isNull());
    int red = 0, blue = 0, transparent = 0;
    for (int y = 0; y < 256; y += 8)
        for (int x = 0; x < 256; x += 8) {
            const QColor c = tile.pixelColor(x, y);
            if (c.alpha() == 0) ++transparent;
            else if (c.red() > 150 && c.blue() < 60) ++red;
            else if (c.blue() > 150 && c.red() < 60) ++blue;
        }
    EXPECT_GT(red + blue, 50);
    // Tiles are cut on the Web Mercator grid, so the tile around the centre holds both halves or
    // at least data; outside the raster it is transparent, never garbage.
    const QImage outside = src->renderTile(tileAt({8.20, 49.0}, z));
    EXPECT_TRUE(outside.isNull());
}

TEST(BaseMaps, BadFilesAreRefusedWithAReason) {
    QTemporaryDir dir;
    QString error;
    EXPECT_FALSE(openMapFile(dir.filePath(QStringLiteral("missing.tif")), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("missing.tif"))) << error.toStdString();

    // A picture without georeferencing cannot be placed on the map.
    const QString png = dir.filePath(QStringLiteral("photo.png"));
    QImage img(16, 16, QImage::Format_RGB32);
    img.fill(Qt::green);
    ASSERT_TRUE(img.save(png));
    EXPECT_FALSE(openMapFile(png, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("no coordinate reference system"))) << error.toStdString();

    const QString text = dir.filePath(QStringLiteral("notes.tif"));
    QFile f(text);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write("hello");
    f.close();
    EXPECT_FALSE(openMapFile(text, &error));
    EXPECT_TRUE(error.startsWith(QStringLiteral("Cannot use notes.tif as a map"))) << error.toStdString();
}

TEST(BaseMaps, OnlineServiceDescriptionUsesTheCacheAndAShortTimeout) {
    // Only the description is checked: tests never touch the network.
    const QString xml = GdalTileSource::xyzServiceXml(QStringLiteral("https://tile.example.org/{z}/{x}/{y}.png"),
                                                      QStringLiteral("/tmp/cache dir"), 19, 5);
    EXPECT_TRUE(xml.contains(QStringLiteral("https://tile.example.org/${z}/${x}/${y}.png")));
    EXPECT_TRUE(xml.contains(QStringLiteral("<Cache><Path>/tmp/cache dir</Path></Cache>")));
    EXPECT_TRUE(xml.contains(QStringLiteral("<Timeout>5</Timeout>")));
    EXPECT_TRUE(xml.contains(QStringLiteral("<TileLevel>19</TileLevel>")));
    EXPECT_TRUE(xml.contains(QStringLiteral("<Projection>EPSG:3857</Projection>")));
}

TEST(BaseMaps, UnreachableTileServiceFailsQuietly) {
    // Nothing listens on port 9 of this machine: the same as being offline, without the network.
    QTemporaryDir cache;
    auto src = GdalTileSource::openXyz(QStringLiteral("local"), QStringLiteral("http://127.0.0.1:9/{z}/{x}/{y}.png"),
                                       cache.path(), QStringLiteral("test"), 19, 2);
    ASSERT_TRUE(src);
    EXPECT_TRUE(src->isOnline());
    const QImage tile = src->renderTile(tileAt({8.33, 49.012}, 16));
    // A missing tile is empty (null or fully transparent), never an error dialog or a crash.
    bool empty = tile.isNull();
    if (!empty) {
        empty = true;
        for (int y = 0; y < tile.height() && empty; ++y)
            for (int x = 0; x < tile.width() && empty; ++x) empty = qAlpha(tile.pixel(x, y)) == 0;
    }
    EXPECT_TRUE(empty);
}

TEST(MapView, WheelZoomKeepsThePointUnderTheCursor) {
    auto w = test::makeWindow();
    auto* view = w->mapView();
    const QPoint cursor(300, 200);
    const QPointF before = view->mapToScene(cursor);
    const double mpp = view->metresPerPixel();
    QWheelEvent e(QPointF(cursor), QPointF(view->viewport()->mapToGlobal(cursor)), QPoint(), QPoint(0, 120),
                  Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(view->viewport(), &e);
    EXPECT_NEAR(view->metresPerPixel(), mpp / 1.25, mpp * 1e-6);
    const QPointF after = view->mapToScene(cursor);
    // QGraphicsView scrolls by whole pixels, so the point stays under the cursor to within a pixel.
    EXPECT_LT(std::hypot(after.x() - before.x(), after.y() - before.y()), 1.5 * view->metresPerPixel());
}

TEST(MapView, KeyboardZoomPanAndScale) {
    auto w = test::makeWindow();
    auto* view = w->mapView();
    const double mpp = view->metresPerPixel();
    QTest::keyClick(view, Qt::Key_Plus);
    EXPECT_NEAR(view->metresPerPixel(), mpp / 1.5, mpp * 1e-6);
    QTest::keyClick(view, Qt::Key_Minus);
    EXPECT_NEAR(view->metresPerPixel(), mpp, mpp * 1e-6);
    const geo::LonLat c = view->centreLonLat();
    QTest::keyClick(view, Qt::Key_Right);
    EXPECT_GT(view->centreLonLat().lon, c.lon);
    // Ground metres per pixel are Web Mercator metres times the Mercator scale on the WGS84 ellipsoid,
    // cos(lat) / sqrt(1 - e^2 sin^2(lat)).
    const double lat = view->centreLonLat().lat * M_PI / 180.0;
    const double e2 = 0.00669437999014;
    EXPECT_NEAR(view->groundMetresPerPixel() / view->metresPerPixel(),
                std::cos(lat) / std::sqrt(1 - e2 * std::sin(lat) * std::sin(lat)), 2e-5);
    // The middle button pans with any tool.
    w->setTool(ToolId::DrawArea);
    const QPoint a(400, 300);
    QTest::mousePress(view->viewport(), Qt::MiddleButton, Qt::NoModifier, a);
    test::moveWithButton(view, a + QPoint(100, 0), Qt::MiddleButton);
    QTest::mouseRelease(view->viewport(), Qt::MiddleButton, Qt::NoModifier, a + QPoint(100, 0));
    EXPECT_TRUE(w->document()->mission().area.outer.empty());
}

TEST(MapView, ClosestZoomStillWorksWithIntScrollBars) {
    // At centimetre zoom the world is billions of pixels wide; the view must still map correctly.
    auto w = test::makeWindow();
    auto* view = w->mapView();
    view->applyView(toScene({8.33, 49.012}), 0.01);
    const geo::LonLat c = fromScene(view->mapToScene(view->viewport()->rect().center()));
    EXPECT_LT(test::metresBetween(c, {8.33, 49.012}), 0.05);
}
