// Corridors in the desktop application: drawn with the Corridor tool by clicks on the map, edited
// with the select tool (a point dragged, a point added, deleted), the width set in the Mission
// dock, every edit one undo step; a double grid toggled in the Planning tool bar.
#include "core/mission/corridor.h"
#include "ui/map/mission_layer.h"
#include "ui/mission_document.h"
#include "ui/planning/planning_toolbar.h"
#include "ui/tools/draw_corridor_tool.h"
#include "ui_test_util.h"

#include <QAction>
#include <QDoubleSpinBox>
#include <QSettings>
#include <QUndoStack>

#include <gtest/gtest.h>

using namespace pf;
using namespace pf::ui;
using pf::ui::test::click;
using pf::ui::test::drag;
using pf::ui::test::metresBetween;

namespace {

// A road bending twice across the demo site.
const geo::GeoRing kRoad{
    {8.3270, 49.0106}, {8.3292, 49.0115}, {8.3300, 49.0128}, {8.3325, 49.0131}};

void drawCorridor(MainWindow& w, const geo::GeoRing& line) {
    w.setTool(ToolId::DrawCorridor);
    for (const auto& p : line)
        click(w.mapView(), p);
    QTest::keyClick(w.mapView(), Qt::Key_Return);
}

QDoubleSpinBox* widthBox(MainWindow& w) {
    return w.findChild<QDoubleSpinBox*>(QStringLiteral("CorridorWidthBox"));
}

} // namespace

TEST(CorridorUi, DrawnFromClicksWithItsGroundAsTheArea) {
    QSettings().setValue(QStringLiteral("corridor/widthM"), 60.0);
    auto w = test::makeWindow();
    drawCorridor(*w, kRoad);
    const auto& m = w->document()->mission();
    ASSERT_TRUE(m.corridor.has_value());
    ASSERT_EQ(m.corridor->line.size(), kRoad.size());
    for (std::size_t i = 0; i < kRoad.size(); ++i)
        EXPECT_LT(metresBetween(m.corridor->line[i], kRoad[i]), 1.0) << i;
    EXPECT_EQ(m.corridor->widthM, 60.0);
    EXPECT_FALSE(m.area.outer.empty()); // the ground, derived
    EXPECT_EQ(w->document()->undoStack()->count(), 1);
    // The map shows it: inside the ground is the corridor, the line's items are there.
    auto* layer = w->missionLayer();
    const auto hit = layer->hitShape(toScene({8.3292, 49.0115}));
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(*hit, ShapeRef::corridor());
    ASSERT_NE(layer->itemFor(ShapeRef::corridor()), nullptr);
    EXPECT_TRUE(layer->itemFor(ShapeRef::corridor())->problem().isEmpty());
    // Undo brings back the empty mission, redo the corridor.
    w->document()->undoStack()->undo();
    EXPECT_FALSE(w->document()->mission().corridor.has_value());
    EXPECT_TRUE(w->document()->mission().area.outer.empty());
    w->document()->undoStack()->redo();
    EXPECT_TRUE(w->document()->mission().corridor.has_value());
}

TEST(CorridorUi, OnePointIsNotACorridor) {
    auto w = test::makeWindow();
    w->setTool(ToolId::DrawCorridor);
    click(w->mapView(), kRoad.front());
    QTest::keyClick(w->mapView(), Qt::Key_Return);
    EXPECT_FALSE(w->document()->mission().corridor.has_value());
    EXPECT_TRUE(w->statusText().contains(QStringLiteral("at least 2 points")))
        << w->statusText().toStdString();
    auto* tool = static_cast<DrawCorridorTool*>(w->tool(ToolId::DrawCorridor));
    EXPECT_EQ(tool->pointCount(), 1);
    QTest::keyClick(w->mapView(), Qt::Key_Escape);
    EXPECT_EQ(tool->pointCount(), 0);
}

TEST(CorridorUi, PointsDraggedAddedAndDeletedWidthSetEachUndoable) {
    auto w = test::makeWindow();
    drawCorridor(*w, kRoad);
    auto* doc = w->document();
    auto* stack = doc->undoStack();
    w->setTool(ToolId::Select);
    // Drag the second point.
    const geo::LonLat moved{8.3288, 49.0119};
    drag(w->mapView(), kRoad[1], moved);
    ASSERT_EQ(doc->mission().corridor->line.size(), kRoad.size());
    EXPECT_LT(metresBetween(doc->mission().corridor->line[1], moved), 1.0);
    EXPECT_EQ(stack->count(), 2);
    // A double-click on the line adds a point there (never on the edge from the last point back to
    // the first).
    const geo::LonLat onLine{(kRoad[2].lon + kRoad[3].lon) / 2, (kRoad[2].lat + kRoad[3].lat) / 2};
    QTest::mouseDClick(w->mapView()->viewport(), Qt::LeftButton, Qt::NoModifier,
                       test::viewPos(w->mapView(), onLine));
    ASSERT_EQ(doc->mission().corridor->line.size(), kRoad.size() + 1);
    EXPECT_LT(metresBetween(doc->mission().corridor->line[3], onLine), 1.0);
    // Delete the added point (it is selected), then the width in the Mission dock.
    w->missionLayer()->select(ShapeRef::corridor(), VertexRef{0, 3});
    QTest::keyClick(w->mapView(), Qt::Key_Delete);
    EXPECT_EQ(doc->mission().corridor->line.size(), kRoad.size());
    auto* box = widthBox(*w);
    ASSERT_NE(box, nullptr);
    const double before = doc->mission().corridor->widthM;
    const double groundBefore = geo::groundAreaM2(doc->mission().area);
    box->setValue(before + 40);
    EXPECT_EQ(doc->mission().corridor->widthM, before + 40);
    EXPECT_GT(geo::groundAreaM2(doc->mission().area), groundBefore * 1.3);
    stack->undo();
    EXPECT_EQ(doc->mission().corridor->widthM, before);
    EXPECT_NEAR(geo::groundAreaM2(doc->mission().area), groundBefore, 1e-6);
    // Delete with no point selected removes the corridor; undo brings it back.
    w->missionLayer()->select(ShapeRef::corridor());
    QTest::keyClick(w->mapView(), Qt::Key_Delete);
    EXPECT_FALSE(doc->mission().corridor.has_value());
    stack->undo();
    ASSERT_TRUE(doc->mission().corridor.has_value());
    // Back to the drawn corridor step by step.
    while (stack->index() > 1)
        stack->undo();
    for (std::size_t i = 0; i < kRoad.size(); ++i)
        EXPECT_LT(metresBetween(doc->mission().corridor->line[i], kRoad[i]), 1.0) << i;
}

// A corridor drawn over an area replaces it; undo gives the area back.
TEST(CorridorUi, ReplacesAnAreaUndoably) {
    auto w = test::makeWindow();
    w->setTool(ToolId::DrawArea);
    for (const auto& p : geo::GeoRing{{8.3275, 49.0110}, {8.3320, 49.0110}, {8.3320, 49.0132}})
        click(w->mapView(), p);
    QTest::keyClick(w->mapView(), Qt::Key_Return);
    const geo::GeoPolygon area = w->document()->mission().area;
    ASSERT_EQ(area.outer.size(), 3u);
    drawCorridor(*w, kRoad);
    EXPECT_TRUE(w->document()->mission().corridor.has_value());
    w->document()->undoStack()->undo();
    EXPECT_FALSE(w->document()->mission().corridor.has_value());
    EXPECT_EQ(w->document()->mission().area, area);
}

TEST(CorridorUi, DoubleGridToggleIsAnUndoableOption) {
    auto w = test::makeWindow();
    auto* action = w->findChild<QAction*>(QStringLiteral("DoubleGridAction"));
    ASSERT_NE(action, nullptr);
    EXPECT_FALSE(action->isChecked());
    action->trigger();
    EXPECT_TRUE(w->document()->mission().options.doubleGrid);
    w->document()->undoStack()->undo();
    EXPECT_FALSE(w->document()->mission().options.doubleGrid);
    EXPECT_FALSE(action->isChecked());
}

// File ▸ Import of a file with a line and no polygon: the line becomes the corridor's centre line.
TEST(CorridorUi, ImportingALineMakesTheCorridor) {
    auto w = test::makeWindow();
    QString error;
    const int n = w->importAreas(QStringLiteral(PF_TEST_DATA_DIR "/corridor/river.kml"),
                                 ImportRole::Ask, &error);
    EXPECT_EQ(n, 1) << error.toStdString();
    ASSERT_TRUE(w->document()->mission().corridor.has_value());
    EXPECT_EQ(w->document()->mission().corridor->line.size(), 6u);
    EXPECT_FALSE(w->document()->mission().area.outer.empty());
    w->document()->undoStack()->undo();
    EXPECT_FALSE(w->document()->mission().corridor.has_value());
    // A file with neither polygon nor line is still refused with the polygon importer's reason.
    EXPECT_EQ(w->importAreas(QStringLiteral(PF_TEST_DATA_DIR "/import/empty.geojson"),
                             ImportRole::Ask, &error),
              0);
    EXPECT_TRUE(error.contains(QStringLiteral("no polygon to import"))) << error.toStdString();
}
