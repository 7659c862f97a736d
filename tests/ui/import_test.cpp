// Importing areas and no-fly zones from files into the mission (one undo step).
#include "ui/map/base_maps.h"
#include "ui/mission_document.h"
#include "ui_test_util.h"

#include <QFile>
#include <QMimeData>
#include <QUrl>
#include <QTemporaryDir>
#include <QUndoStack>

#include <gtest/gtest.h>

using namespace pf;
using namespace pf::ui;

namespace {
const QString kTwoPolygons = QStringLiteral(PF_UI_TEST_DATA_DIR "/two_polygons.geojson");
}

TEST(Import, LargestPolygonBecomesTheAreaWhenThereIsNone) {
    auto w = test::makeWindow();
    QString error;
    EXPECT_EQ(w->importAreas(kTwoPolygons, MainWindow::ImportRole::Ask, &error), 2) << error.toStdString();
    const auto& m = w->document()->mission();
    ASSERT_EQ(m.area.outer.size(), 4u);
    EXPECT_NEAR(m.area.outer[0].lon, 8.3275, 1e-9); // the survey block, not the shed
    ASSERT_EQ(m.noFlyZones.size(), 1u);
    EXPECT_EQ(m.noFlyZones[0].name, "Small shed");
    // One undo step for the whole import.
    EXPECT_EQ(w->document()->undoStack()->count(), 1);
    w->document()->undoStack()->undo();
    EXPECT_TRUE(w->document()->mission().area.outer.empty());
    EXPECT_TRUE(w->document()->mission().noFlyZones.empty());
}

TEST(Import, WithAnAreaAlreadyThereTheRoleDecides) {
    auto w = test::makeWindow();
    w->importAreas(kTwoPolygons, MainWindow::ImportRole::Ask);
    const auto area = w->document()->mission().area;
    EXPECT_EQ(w->importAreas(kTwoPolygons, MainWindow::ImportRole::NoFlyZones), 2);
    EXPECT_EQ(w->document()->mission().area, area);
    EXPECT_EQ(w->document()->mission().noFlyZones.size(), 3u);
    EXPECT_EQ(w->importAreas(kTwoPolygons, MainWindow::ImportRole::Area), 2);
    EXPECT_EQ(w->document()->mission().noFlyZones.size(), 4u);
}

TEST(Import, UnreadableFileGivesTheImportersMessage) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("not_a_map.geojson"));
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write("this is not geojson");
    f.close();
    auto w = test::makeWindow();
    QString error;
    EXPECT_EQ(w->importAreas(path, MainWindow::ImportRole::Ask, &error), 0);
    EXPECT_TRUE(error.contains(QStringLiteral("not_a_map.geojson"))) << error.toStdString();
    EXPECT_TRUE(w->document()->mission().area.outer.empty());
    EXPECT_EQ(w->document()->undoStack()->count(), 0);
}

TEST(Import, DroppingFilesOnTheMapImportsPolygonsAndOpensRasters) {
    auto w = test::makeWindow();
    auto* viewport = w->mapView()->viewport();
    auto drop = [&](const QString& path) {
        QMimeData mime;
        mime.setUrls({QUrl::fromLocalFile(path)});
        const QPoint at = viewport->rect().center();
        QDragEnterEvent enter(at, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(viewport, &enter);
        EXPECT_TRUE(enter.isAccepted());
        QDropEvent dropEvent(QPointF(at), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(viewport, &dropEvent);
    };
    drop(kTwoPolygons);
    EXPECT_EQ(w->document()->mission().area.outer.size(), 4u);
    EXPECT_EQ(w->document()->mission().noFlyZones.size(), 1u);
    // A dropped raster becomes the base map.
    const QString map = pf::ui::demoMapPath();
    ASSERT_FALSE(map.isEmpty());
    w->setBaseMap(QStringLiteral("none"));
    drop(map);
    EXPECT_EQ(w->baseMapId(), map);
}
