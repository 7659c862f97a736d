// File > Build mosaic: the dialog builds in the background against the current plan, the mosaic
// shows on the map over the mission with its opacity, gaps are drawn, and cancel writes nothing.
#include "core/mosaic/planned_flight.h"
#include "tests/support/flight_simulator.h"
#include "ui/map/tile_layer.h"
#include "ui/mosaic/mosaic_controller.h"
#include "ui/mosaic/mosaic_dialog.h"
#include "ui/mosaic/mosaic_layer.h"
#include "ui/mosaic/mosaic_panel.h"
#include "ui/planning/plan_controller.h"
#include "ui_test_util.h"

#include <QCheckBox>
#include <QDir>
#include <QFileInfo>
#include <QGraphicsScene>
#include <QMenuBar>
#include <QProgressBar>
#include <QPushButton>
#include <QSlider>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace pf;
using namespace pf::ui;

namespace {

// The demo mission planned in the window, and small photos of the first `count` photo points of
// its first aircraft (Falcon 8, 40 m).
std::unique_ptr<MainWindow> plannedDemoWithPhotos(const QString& dir, int count,
                                                  QStringList* photos) {
    auto w = test::makeWindow();
    w->planController()->setAutoPlan(false);
    QString error;
    EXPECT_TRUE(w->openDemoMission(&error)) << error.toStdString();
    w->planNow();
    EXPECT_TRUE(w->planController()->waitForIdle(120000));
    const auto& plan = w->planController()->plan();
    EXPECT_TRUE(plan.has_value());
    if (!plan)
        return w;
    auto flight = mosaic::plannedFlightFromPlan(*plan);
    std::vector<mosaic::PlannedPhoto> some(flight.photos.begin(), flight.photos.begin() + count);
    auto ground = testsim::GroundImage::load(testsim::demoMapPath(), plan->frame->origin(), 320.0,
                                             240.0, 0.25);
    EXPECT_TRUE(ground.ok());
    testsim::SimOptions o;
    o.camera.widthPx = 240;
    o.camera.heightPx = 180;
    auto sim = testsim::simulateFlight(*ground, some, o, dir.toStdString());
    EXPECT_TRUE(sim.ok());
    if (sim)
        for (const auto& p : *sim)
            photos->append(QString::fromStdString(p.path));
    return w;
}

QAction* findAction(QMenuBar* bar, const QString& text) {
    for (QAction* menu : bar->actions())
        if (menu->menu())
            for (QAction* a : menu->menu()->actions())
                if (a->text() == text)
                    return a;
    return nullptr;
}

TEST(MosaicGui, BuildMosaicFromTheMenuShowsItOverTheMissionWithGaps) {
    if (testsim::demoMapPath().empty())
        GTEST_SKIP() << "no demo map";
    QTemporaryDir tmp;
    QStringList photos;
    auto w = plannedDemoWithPhotos(tmp.filePath(QStringLiteral("card")), 40, &photos);
    ASSERT_EQ(photos.size(), 40);

    QAction* menu = findAction(w->menuBar(), QStringLiteral("Build &mosaic from photos…"));
    ASSERT_TRUE(menu);
    menu->trigger();
    MosaicController* mc = w->mosaicController();
    MosaicDialog* d = mc->dialog();
    ASSERT_TRUE(d->isVisible());
    EXPECT_EQ(d->addPhotos({tmp.filePath(QStringLiteral("card"))}), 40); // the folder's photos
    EXPECT_EQ(d->addPhotos(photos), 0);                                  // already there
    EXPECT_TRUE(d->outputPath().endsWith(QStringLiteral("card/mosaic.tif")))
        << d->outputPath().toStdString();
    d->setOutputPath(tmp.filePath(QStringLiteral("site.tif")));
    d->useCurrentPlan();

    QTest::mouseClick(d->buildButton(), Qt::LeftButton);
    EXPECT_TRUE(d->isRunning());
    EXPECT_FALSE(d->buildButton()->isEnabled());
    EXPECT_TRUE(d->cancelButton()->isEnabled());
    ASSERT_TRUE(d->waitForFinished(120000));
    ASSERT_TRUE(d->lastReport().has_value())
        << d->statusText().toStdString() << d->reportText().toStdString();
    const mosaic::MosaicReport r = *d->lastReport(); // a copy: the next build replaces it
    EXPECT_EQ(r.photosUsed, 40);
    EXPECT_EQ(d->progressBar()->value(), 1000);
    EXPECT_TRUE(d->statusText().startsWith(QStringLiteral("Mosaic saved: ")))
        << d->statusText().toStdString();
    // The report is the CLI's: the other aircraft and the rest of the Falcon's points are missing.
    EXPECT_TRUE(d->reportText().contains(QStringLiteral("mosaic: 40 of 40 photos used")))
        << d->reportText().toStdString();
    EXPECT_TRUE(d->reportText().contains(QStringLiteral("Missing: ")))
        << d->reportText().toStdString();
    EXPECT_FALSE(r.gaps.empty()); // 40 photos of one aircraft do not cover the area

    // On the map: the mosaic between the base map and the mission, gaps above the area.
    MosaicLayer* layer = mc->layer();
    ASSERT_TRUE(layer->isShown());
    ASSERT_TRUE(layer->tiles());
    EXPECT_GT(layer->tiles()->zValue(), w->tileLayer()->zValue());
    EXPECT_LT(layer->tiles()->zValue(), 10.0);
    EXPECT_EQ(layer->gapItemCount(), static_cast<int>(r.gaps.size()));
    EXPECT_TRUE(w->mapView()
                    ->mapToScene(w->mapView()->viewport()->rect())
                    .boundingRect()
                    .intersects(layer->bounds()));
    // The mosaic's tiles render (from the GeoTIFF, warped to Web Mercator).
    w->mapView()->viewport()->grab();
    for (int i = 0; i < 200 && layer->tiles()->pendingCount() > 0; ++i)
        QTest::qWait(20);
    w->mapView()->viewport()->grab();
    EXPECT_GT(layer->tiles()->cachedCount(), 0);

    // The dock: opacity and gaps.
    MosaicPanel* panel = mc->panel();
    ASSERT_TRUE(panel);
    EXPECT_TRUE(panel->isVisible());
    EXPECT_TRUE(panel->summaryText().contains(QStringLiteral("40 of 40 photos used")))
        << panel->summaryText().toStdString();
    EXPECT_TRUE(panel->summaryText().contains(QStringLiteral("gap(s)")))
        << panel->summaryText().toStdString();
    panel->opacitySlider()->setValue(40);
    EXPECT_DOUBLE_EQ(layer->opacity(), 0.4);
    EXPECT_DOUBLE_EQ(layer->tiles()->opacity(), 0.4);
    panel->gapsBox()->setChecked(false);
    EXPECT_FALSE(layer->gapsVisible());
    panel->seamsBox()->setChecked(true);
    EXPECT_TRUE(layer->seamsVisible());

    // The photos are the Falcon's: matched to its points only, coverage over its part of the area.
    d->setAircraft(QStringLiteral("Falcon 8"));
    d->setOutputPath(tmp.filePath(QStringLiteral("falcon.tif")));
    ASSERT_TRUE(d->start());
    ASSERT_TRUE(d->waitForFinished(120000));
    ASSERT_TRUE(d->lastReport().has_value()) << d->statusText().toStdString();
    const auto& falcon = *d->lastReport();
    EXPECT_LT(falcon.areaM2, 0.8 * r.areaM2);
    EXPECT_GT(falcon.coveredRatio, r.coveredRatio)
        << falcon.areaM2 << " " << r.areaM2 << " " << falcon.gapAreaM2 << " " << r.gapAreaM2;
    for (const auto& m : falcon.missing)
        EXPECT_EQ(m.aircraft, "Falcon 8");
    EXPECT_TRUE(d->reportText().contains(
        QStringLiteral("measured over the part of the area planned for Falcon 8")))
        << d->reportText().toStdString();
    EXPECT_EQ(QFileInfo(QString::fromStdString(layer->report().outputPath)).fileName(),
              QStringLiteral("falcon.tif"));

    mc->removeMosaic();
    EXPECT_FALSE(layer->isShown());
    EXPECT_FALSE(layer->tiles());
}

TEST(MosaicGui, CancelStopsTheBuildAndWritesNothing) {
    if (testsim::demoMapPath().empty())
        GTEST_SKIP() << "no demo map";
    QTemporaryDir tmp;
    QStringList photos;
    auto w = plannedDemoWithPhotos(tmp.filePath(QStringLiteral("card")), 30, &photos);
    MosaicDialog* d = w->mosaicController()->dialog();
    d->addPhotos(photos);
    d->useNoPlan();
    d->setOutputPath(tmp.filePath(QStringLiteral("out/never.tif")));
    QDir().mkpath(tmp.filePath(QStringLiteral("out")));
    ASSERT_TRUE(d->start());
    d->cancel();
    ASSERT_TRUE(d->waitForFinished(60000));
    EXPECT_FALSE(d->lastReport().has_value());
    EXPECT_EQ(d->statusText(), QStringLiteral("Cancelled: nothing was written."));
    EXPECT_TRUE(QDir(tmp.filePath(QStringLiteral("out"))).isEmpty());
    EXPECT_FALSE(w->mosaicController()->layer()->isShown());
    EXPECT_TRUE(d->buildButton()->isEnabled());

    // Without photos or output it refuses with a reason.
    d->clearPhotos();
    EXPECT_FALSE(d->start());
    EXPECT_EQ(d->statusText(), QStringLiteral("Add the photos first."));
}

} // namespace
