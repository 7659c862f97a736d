// The terrain model on the map: a DEM dropped on the map becomes the mission's terrain model (one
// undoable edit, File > Terrain model's messages), other dropped rasters stay base maps, and the
// hillshade layer shows the DEM's relief lit from the north-west and is toggled from the View menu.
#include "core/mission/terrain_stage.h"
#include "ui/map/base_maps.h"
#include "ui/map/hillshade_layer.h"
#include "ui/map/web_mercator.h"
#include "ui/mission_document.h"
#include "ui/planning/plan_controller.h"
#include "ui/terrain/terrain_controller.h"
#include "ui_test_util.h"

#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFile>
#include <QGraphicsPixmapItem>
#include <QMenu>
#include <QMenuBar>
#include <QMimeData>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QUrl>

#include <gtest/gtest.h>

#include <cmath>

using namespace pf;
using namespace pf::ui;

namespace {

// Drags `paths` onto the middle of the map and drops them, as a file manager does.
void dropFiles(MapView* view, const QStringList& paths) {
    QMimeData mime;
    QList<QUrl> urls;
    for (const QString& p : paths)
        urls << QUrl::fromLocalFile(p);
    mime.setUrls(urls);
    const QPoint pos = view->viewport()->rect().center();
    QDragEnterEvent enter(pos, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(view->viewport(), &enter);
    ASSERT_TRUE(enter.isAccepted());
    QDropEvent drop(QPointF(pos), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(view->viewport(), &drop);
    EXPECT_TRUE(drop.isAccepted());
}

QAction* viewAction(MainWindow* w, const QString& objectName) {
    for (QAction* a : w->menuBar()->actions())
        if (a->text() == QStringLiteral("&View"))
            for (QAction* b : a->menu()->actions())
                if (b->objectName() == objectName)
                    return b;
    return nullptr;
}

// The demo DEM's hill: 35 m, 80 m sigma, 150 m west and 90 m north of (8.3300, 49.0120).
geo::LonLat nearHill(double eastM, double northM) {
    return {8.3300 + (-150 + eastM) / (111'320.0 * std::cos(49.012 * M_PI / 180)),
            49.0120 + (90 + northM) / 111'200.0};
}

int shadeAt(const ShadedRelief& r, const geo::LonLat& p) {
    const QPointF s = mercator::toScene(p.lon, p.lat);
    const int x =
        static_cast<int>((s.x() - r.sceneRect.left()) / r.sceneRect.width() * r.image.width());
    const int y =
        static_cast<int>((s.y() - r.sceneRect.top()) / r.sceneRect.height() * r.image.height());
    return qRed(r.image.pixel(x, y));
}

// On the demo mission (flat: no terrain model yet), planning by hand only, with the demo DEM at
// hand.
class TerrainMap : public ::testing::Test {
protected:
    void SetUp() override {
        dem = QString::fromStdString(mission::demoDemPath());
        if (dem.isEmpty())
            GTEST_SKIP() << "no demo DEM built";
        w = test::makeWindow();
        w->planController()->setAutoPlan(false);
        QString error;
        ASSERT_TRUE(w->openDemoMission(&error)) << error.toStdString();
    }
    QString dem;
    std::unique_ptr<MainWindow> w;
};

} // namespace

TEST_F(TerrainMap, DroppingADemOnTheMapMakesItTheTerrainModel) {
    MissionDocument* doc = w->document();
    ASSERT_FALSE(doc->mission().terrain.follows());
    const int undoBefore = doc->undoStack()->count();
    const QString mapBefore = w->baseMapId();

    dropFiles(w->mapView(), {dem});
    EXPECT_TRUE(doc->mission().terrain.follows());
    EXPECT_EQ(QString::fromStdString(doc->mission().terrain.demPath), dem);
    EXPECT_EQ(doc->undoStack()->count(), undoBefore + 1);
    EXPECT_TRUE(doc->isDirty());
    EXPECT_EQ(w->baseMapId(), mapBefore); // a DEM is not opened as a base map
    doc->undoStack()->undo();
    EXPECT_FALSE(doc->mission().terrain.follows());
    EXPECT_TRUE(doc->mission().terrain.demPath.empty());
    doc->undoStack()->redo();
    EXPECT_TRUE(doc->mission().terrain.follows());
    doc->undoStack()->undo();

    // An unreadable .hgt is refused with File > Terrain model's message; the mission is unchanged.
    QTemporaryDir dir;
    const QString junk = dir.filePath(QStringLiteral("N49E008.hgt"));
    {
        QFile f(junk);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write("not a terrain model");
    }
    dropFiles(w->mapView(), {junk});
    EXPECT_FALSE(doc->mission().terrain.follows());
    EXPECT_TRUE(w->terrainController()->lastError().contains(QStringLiteral("cannot be read")))
        << w->terrainController()->lastError().toStdString();

    // A picture (the demo map: 8-bit RGB GeoTIFF) still opens as the base map, beside a DEM
    // dropped with it.
    const QString map = demoMapPath();
    ASSERT_FALSE(map.isEmpty());
    EXPECT_FALSE(terrain::Dem::looksLikeDem(map.toStdString()));
    EXPECT_TRUE(terrain::Dem::looksLikeDem(dem.toStdString()));
    dropFiles(w->mapView(), {map, dem});
    EXPECT_EQ(w->baseMapId(), map);
    EXPECT_EQ(QString::fromStdString(doc->mission().terrain.demPath), dem);
}

TEST_F(TerrainMap, HillshadeShowsTheDemUnderThePlanAndToggles) {
    auto* layer = w->findChild<HillshadeLayer*>();
    ASSERT_NE(layer, nullptr);
    QAction* toggle = viewAction(w.get(), QStringLiteral("HillshadeAction"));
    ASSERT_NE(toggle, nullptr);
    toggle->setChecked(true);
    ASSERT_TRUE(layer->waitUntilReady(20000));
    EXPECT_FALSE(layer->hasRelief()); // no DEM yet
    EXPECT_FALSE(layer->item()->isVisible());

    ASSERT_TRUE(w->terrainController()->useDem(dem));
    ASSERT_TRUE(layer->waitUntilReady(20000));
    ASSERT_TRUE(layer->hasRelief()) << layer->relief().error.toStdString();
    const ShadedRelief& r = layer->relief();
    EXPECT_TRUE(layer->item()->isVisible());
    EXPECT_LE(std::max(r.image.width(), r.image.height()), HillshadeLayer::kMaxSidePx);
    // Under the mission, semi-transparent, over the whole area.
    EXPECT_LT(layer->item()->zValue(), 10.0);
    EXPECT_GT(layer->item()->zValue(), -100.0);
    EXPECT_GT(layer->item()->opacity(), 0.2);
    EXPECT_LT(layer->item()->opacity(), 0.8);
    for (const auto& p : w->document()->mission().area.outer)
        EXPECT_TRUE(r.sceneRect.contains(mercator::toScene(p.lon, p.lat)));
    // The hill's north-west flank faces the light, its south-east flank turns away; the plain is
    // nearly flat (255 sin 45° = 180; its 3 % rise to the north turns it slightly away).
    const int lit = shadeAt(r, nearHill(-70, 70)), dark = shadeAt(r, nearHill(70, -70));
    EXPECT_GT(lit, 200);
    EXPECT_LT(dark, 150);
    EXPECT_NEAR(shadeAt(r, nearHill(-150, -340)), 180, 6);

    toggle->setChecked(false);
    EXPECT_FALSE(layer->item()->isVisible());
    toggle->setChecked(true);
    EXPECT_TRUE(layer->item()->isVisible());

    // Removing the terrain model removes its relief.
    w->terrainController()->removeDem();
    ASSERT_TRUE(layer->waitUntilReady(20000));
    EXPECT_FALSE(layer->hasRelief());
    EXPECT_FALSE(layer->item()->isVisible());
}
