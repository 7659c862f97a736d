// File > Terrain model: a DEM chosen for the mission (undoable), the plan follows the terrain, the
// Terrain profile dock shows ground, aircraft and clearance, a bad DEM is refused with the reason,
// and the choice is saved with the mission (file version 4).
#include "core/io/mission_file.h"
#include "core/mission/terrain_stage.h"
#include "ui/mission_document.h"
#include "ui/planning/plan_controller.h"
#include "ui/terrain/terrain_controller.h"
#include "ui/terrain/terrain_profile_widget.h"
#include "ui_test_util.h"

#include <QComboBox>
#include <QDockWidget>
#include <QFile>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QTemporaryDir>
#include <QUndoStack>

#include <gtest/gtest.h>

using namespace pf;
using namespace pf::ui;

namespace {

QAction* findIn(QMenu* menu, const QString& text) {
    for (QAction* a : menu->actions()) {
        if (a->text() == text)
            return a;
        if (a->menu())
            if (QAction* sub = findIn(a->menu(), text))
                return sub;
    }
    return nullptr;
}

TEST(TerrainGui, ChoosingTheDemoDemFollowsTheTerrainAndShowsTheProfile) {
    const QString dem = QString::fromStdString(mission::demoDemPath());
    if (dem.isEmpty())
        GTEST_SKIP() << "no demo DEM built";
    auto w = test::makeWindow();
    w->planController()->setAutoPlan(false);
    QString error;
    ASSERT_TRUE(w->openDemoMission(&error)) << error.toStdString();
    TerrainController* tc = w->terrainController();
    ASSERT_NE(tc, nullptr);
    // Reachable from the File menu.
    QMenu* file = nullptr;
    for (QAction* a : w->menuBar()->actions())
        if (a->text() == QStringLiteral("&File"))
            file = a->menu();
    ASSERT_NE(file, nullptr);
    QAction* follow = findIn(file, QStringLiteral("&Follow the terrain"));
    ASSERT_NE(follow, nullptr);
    EXPECT_NE(findIn(file, QStringLiteral("&Choose terrain model (DEM)…")), nullptr);
    EXPECT_FALSE(follow->isChecked());

    // A file GDAL cannot read is refused, the mission unchanged.
    QTemporaryDir dir;
    const QString junk = dir.filePath(QStringLiteral("junk.tif"));
    {
        QFile f(junk);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write("not a raster");
    }
    EXPECT_FALSE(tc->useDem(junk));
    EXPECT_TRUE(tc->lastError().contains(QStringLiteral("cannot be read"))) << tc->lastError().toStdString();
    EXPECT_FALSE(w->document()->mission().terrain.follows());

    // The demo DEM: one undoable edit that turns following on.
    ASSERT_TRUE(tc->useDem(dem)) << tc->lastError().toStdString();
    EXPECT_TRUE(w->document()->mission().terrain.follows());
    EXPECT_TRUE(follow->isChecked());
    w->document()->undoStack()->undo();
    EXPECT_FALSE(w->document()->mission().terrain.follows());
    EXPECT_FALSE(follow->isChecked());
    w->document()->undoStack()->redo();
    EXPECT_TRUE(w->document()->mission().terrain.follows());

    w->planNow();
    ASSERT_TRUE(w->planController()->waitForIdle(120000));
    const auto& plan = w->planController()->plan();
    ASSERT_TRUE(plan.has_value()) << w->planController()->lastError().toStdString();
    ASSERT_TRUE(plan->aircraft[0].terrain.active);
    EXPECT_TRUE(plan->aircraft[0].route.hasTerrain());

    // The dock: the summary and a profile that keeps the clearance.
    QApplication::processEvents();
    EXPECT_TRUE(tc->summaryLabel()->text().contains(QStringLiteral("40.0 m above the ground under every photo")))
        << tc->summaryLabel()->text().toStdString();
    const TerrainProfile& prof = tc->profileWidget()->profile();
    ASSERT_FALSE(prof.empty());
    EXPECT_GE(prof.lowestClearanceM(), w->document()->mission().terrain.minClearanceM - 0.1);
    tc->dock()->show();
    tc->dock()->raise();
    tc->profileWidget()->resize(600, 200);
    const QImage img = tc->profileWidget()->grab().toImage();
    int groundPixels = 0; // the brown fill of the ground
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const QColor c = img.pixelColor(x, y);
            groundPixels += c.red() > c.blue() + 30 && c.green() > c.blue() && c.red() < 235;
        }
    EXPECT_GT(groundPixels, 1000);
    // The second aircraft's profile on request.
    tc->aircraftBox()->setCurrentIndex(1);
    emit tc->aircraftBox()->activated(1);
    EXPECT_TRUE(tc->summaryLabel()->text().contains(QStringLiteral("60.0 m above the ground")))
        << tc->summaryLabel()->text().toStdString();

    // Saved with the mission, as version 4.
    const QString path = dir.filePath(QStringLiteral("terrain.json"));
    ASSERT_TRUE(w->saveMission(path, &error)) << error.toStdString();
    auto back = io::readMissionFile(path.toStdString());
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_TRUE(back->terrain.follows());
    EXPECT_EQ(back->terrain.demPath, dem.toStdString());
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    EXPECT_TRUE(f.readAll().contains("\"version\":4"));
}

} // namespace
