// Drawing and editing with the map tools, driven by simulated mouse input on the map's viewport.
#include "ui/map/mission_layer.h"
#include "ui/mission_document.h"
#include "ui/tools/draw_polygon_tool.h"
#include "ui_test_util.h"

#include <QUndoStack>

#include <gtest/gtest.h>

using namespace pf;
using namespace pf::ui;
using pf::ui::test::click;
using pf::ui::test::drag;
using pf::ui::test::metresBetween;

namespace {

const geo::GeoRing kArea{{8.3275, 49.0110}, {8.3320, 49.0110}, {8.3320, 49.0132}, {8.3275, 49.0132}};
const geo::GeoRing kZone{{8.3290, 49.0118}, {8.3298, 49.0118}, {8.3298, 49.0122}, {8.3290, 49.0122}};

// One screen pixel at this zoom is well under a metre; a click lands within a pixel of its target.
constexpr double kClickToleranceM = 1.0;

void drawPolygon(MainWindow& w, ToolId tool, const geo::GeoRing& ring) {
    w.setTool(tool);
    for (const auto& p : ring) click(w.mapView(), p);
    QTest::keyClick(w.mapView(), Qt::Key_Return);
}

void expectRingNear(const geo::GeoRing& actual, const geo::GeoRing& expected) {
    ASSERT_EQ(actual.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
        EXPECT_LT(metresBetween(actual[i], expected[i]), kClickToleranceM) << "vertex " << i;
}

} // namespace

TEST(Drawing, AreaAndNoFlyZoneFromClicks) {
    auto w = test::makeWindow();
    drawPolygon(*w, ToolId::DrawArea, kArea);
    expectRingNear(w->document()->mission().area.outer, kArea);
    drawPolygon(*w, ToolId::DrawNoFly, kZone);
    ASSERT_EQ(w->document()->mission().noFlyZones.size(), 1u);
    expectRingNear(w->document()->mission().noFlyZones[0].polygon.outer, kZone);
    EXPECT_TRUE(w->document()->isDirty());
    EXPECT_TRUE(w->isWindowModified());
    EXPECT_TRUE(w->windowTitle().endsWith(QStringLiteral("— Photoflight")));

    // Each shape is one undo step.
    auto* stack = w->document()->undoStack();
    EXPECT_EQ(stack->count(), 2);
    stack->undo();
    EXPECT_TRUE(w->document()->mission().noFlyZones.empty());
    EXPECT_FALSE(w->document()->mission().area.outer.empty());
    stack->undo();
    EXPECT_TRUE(w->document()->mission().area.outer.empty());
    EXPECT_FALSE(w->document()->isDirty());
    stack->redo();
    stack->redo();
    expectRingNear(w->document()->mission().area.outer, kArea);
    ASSERT_EQ(w->document()->mission().noFlyZones.size(), 1u);

    // The scene shows them: hit-testing inside the zone finds the zone, elsewhere the area.
    auto* layer = w->missionLayer();
    const auto inZone = layer->hitShape(toScene({8.3294, 49.0120}));
    ASSERT_TRUE(inZone.has_value());
    EXPECT_EQ(*inZone, ShapeRef::noFly(0));
    const auto inArea = layer->hitShape(toScene({8.3280, 49.0112}));
    ASSERT_TRUE(inArea.has_value());
    EXPECT_EQ(*inArea, ShapeRef::area());
    EXPECT_FALSE(layer->hitShape(toScene({8.3330, 49.0105})).has_value());
}

TEST(Drawing, DoubleClickFinishesAndEscapeCancels) {
    auto w = test::makeWindow();
    w->setTool(ToolId::DrawArea);
    auto* view = w->mapView();
    for (std::size_t i = 0; i + 1 < kArea.size(); ++i) click(view, kArea[i]);
    QTest::keyClick(view, Qt::Key_Escape);
    EXPECT_TRUE(w->document()->mission().area.outer.empty());
    for (const auto& p : kArea) click(view, p);
    QTest::mouseDClick(view->viewport(), Qt::LeftButton, Qt::NoModifier, test::viewPos(view, kArea.back()));
    expectRingNear(w->document()->mission().area.outer, kArea);
}

TEST(Drawing, ClickingTheFirstVertexClosesTheRing) {
    auto w = test::makeWindow();
    w->setTool(ToolId::DrawNoFly);
    for (const auto& p : kZone) click(w->mapView(), p);
    click(w->mapView(), kZone.front());
    ASSERT_EQ(w->document()->mission().noFlyZones.size(), 1u);
    expectRingNear(w->document()->mission().noFlyZones[0].polygon.outer, kZone);
}

TEST(Drawing, SelfIntersectingPolygonIsRefusedWithTheReason) {
    auto w = test::makeWindow();
    // A bow tie: edges 2-3 and 4-1 cross.
    const geo::GeoRing bowTie{{8.3275, 49.0110}, {8.3320, 49.0110}, {8.3275, 49.0132}, {8.3320, 49.0132}};
    drawPolygon(*w, ToolId::DrawArea, bowTie);
    EXPECT_TRUE(w->document()->mission().area.outer.empty());
    EXPECT_TRUE(w->statusText().contains(QStringLiteral("intersects itself"))) << w->statusText().toStdString();
    auto* tool = static_cast<DrawPolygonTool*>(w->tool(ToolId::DrawArea));
    EXPECT_EQ(tool->vertexCount(), 4); // still drawing: the user can fix it
    QTest::keyClick(w->mapView(), Qt::Key_Backspace);
    EXPECT_EQ(tool->vertexCount(), 3);
    QTest::keyClick(w->mapView(), Qt::Key_Return);
    EXPECT_EQ(w->document()->mission().area.outer.size(), 3u);
}

TEST(Drawing, TooFewVerticesIsNotAShape) {
    auto w = test::makeWindow();
    drawPolygon(*w, ToolId::DrawNoFly, {kZone[0], kZone[1]});
    EXPECT_TRUE(w->document()->mission().noFlyZones.empty());
    EXPECT_TRUE(w->statusText().contains(QStringLiteral("at least 3 vertices"))) << w->statusText().toStdString();
}

TEST(Editing, DragVertexInsertOnEdgeDeleteVertexMoveShape) {
    auto w = test::makeWindow();
    drawPolygon(*w, ToolId::DrawArea, kArea);
    w->setTool(ToolId::Select);
    auto* view = w->mapView();
    auto* doc = w->document();
    auto* stack = doc->undoStack();
    const int base = stack->count();

    // Drag vertex 3 (north-east corner) 30 m further north-east.
    const geo::LonLat to{8.3324, 49.0134};
    drag(view, kArea[2], to);
    EXPECT_EQ(stack->count(), base + 1);
    EXPECT_LT(metresBetween(doc->mission().area.outer[2], to), kClickToleranceM);
    stack->undo();
    EXPECT_LT(metresBetween(doc->mission().area.outer[2], kArea[2]), kClickToleranceM);
    stack->redo();

    // Double-click on the middle of the south edge inserts a vertex there.
    const geo::LonLat mid{(kArea[0].lon + kArea[1].lon) / 2, kArea[0].lat};
    QTest::mouseDClick(view->viewport(), Qt::LeftButton, Qt::NoModifier, test::viewPos(view, mid));
    ASSERT_EQ(doc->mission().area.outer.size(), 5u);
    EXPECT_LT(metresBetween(doc->mission().area.outer[1], mid), kClickToleranceM);

    // Select that vertex and delete it.
    click(view, mid);
    ASSERT_TRUE(w->missionLayer()->selectedVertex().has_value());
    QTest::keyClick(view, Qt::Key_Delete);
    EXPECT_EQ(doc->mission().area.outer.size(), 4u);

    // Move the whole area by dragging its inside: every vertex moves by the same amount.
    const auto before = doc->mission().area.outer;
    drag(view, {8.3285, 49.0115}, {8.3290, 49.0115});
    const auto& after = doc->mission().area.outer;
    ASSERT_EQ(after.size(), before.size());
    for (std::size_t i = 0; i < after.size(); ++i) {
        EXPECT_NEAR(after[i].lon - before[i].lon, 0.0005, 2e-5);
        EXPECT_NEAR(after[i].lat, before[i].lat, 1e-9);
    }
    stack->undo();
    EXPECT_EQ(doc->mission().area.outer, before);
}

TEST(Editing, DeleteRefusesToLeaveFewerThanThreeVertices) {
    auto w = test::makeWindow();
    const geo::GeoRing tri{kArea[0], kArea[1], kArea[2]};
    drawPolygon(*w, ToolId::DrawArea, tri);
    w->setTool(ToolId::Select);
    click(w->mapView(), tri[1]);
    QTest::keyClick(w->mapView(), Qt::Key_Delete);
    EXPECT_EQ(w->document()->mission().area.outer.size(), 3u);
    EXPECT_TRUE(w->statusText().contains(QStringLiteral("at least 3 vertices")));
    // With the shape (not a vertex) selected, Delete removes the whole shape, undoably.
    click(w->mapView(), {8.3300, 49.0113});
    ASSERT_FALSE(w->missionLayer()->selectedVertex().has_value());
    QTest::keyClick(w->mapView(), Qt::Key_Delete);
    EXPECT_TRUE(w->document()->mission().area.outer.empty());
    w->document()->undoStack()->undo();
    EXPECT_EQ(w->document()->mission().area.outer.size(), 3u);
}

TEST(Editing, DeleteNoFlyZoneAndUndo) {
    auto w = test::makeWindow();
    drawPolygon(*w, ToolId::DrawNoFly, kZone);
    w->document()->undoStack()->clear();
    w->setTool(ToolId::Select);
    click(w->mapView(), {8.3294, 49.0120});
    QTest::keyClick(w->mapView(), Qt::Key_Delete);
    EXPECT_TRUE(w->document()->mission().noFlyZones.empty());
    w->document()->undoStack()->undo();
    ASSERT_EQ(w->document()->mission().noFlyZones.size(), 1u);
    EXPECT_EQ(w->document()->mission().noFlyZones[0].name, "No-fly zone 1");
}

TEST(Editing, CircleToolMakesAGeodesicCircle) {
    auto w = test::makeWindow();
    w->setTool(ToolId::DrawCircle);
    const geo::LonLat centre{8.3316435, 49.0115504};
    const geo::LonLat edge{8.3316435 + 20.0 / (111319.49 * std::cos(49.0115504 * M_PI / 180.0)), 49.0115504};
    drag(w->mapView(), centre, edge);
    ASSERT_EQ(w->document()->mission().noFlyZones.size(), 1u);
    const auto& ring = w->document()->mission().noFlyZones[0].polygon.outer;
    EXPECT_GE(ring.size(), 16u);
    for (const auto& p : ring) EXPECT_NEAR(metresBetween(centre, p), 20.0, 1.0);
}

TEST(Editing, HomeToolSetsHomeAndSelectToolMovesIt) {
    auto w = test::makeWindow();
    w->setTool(ToolId::Home);
    const geo::LonLat home{8.3270554, 49.010741};
    click(w->mapView(), home);
    ASSERT_TRUE(w->document()->mission().home.has_value());
    EXPECT_LT(metresBetween(*w->document()->mission().home, home), kClickToleranceM);
    w->setTool(ToolId::Select);
    const geo::LonLat moved{8.3272, 49.0106};
    drag(w->mapView(), home, moved);
    EXPECT_LT(metresBetween(*w->document()->mission().home, moved), kClickToleranceM);
    w->document()->undoStack()->undo();
    EXPECT_LT(metresBetween(*w->document()->mission().home, home), kClickToleranceM);
}

TEST(Editing, InvalidDragShowsWarningStyleAndReason) {
    auto w = test::makeWindow();
    drawPolygon(*w, ToolId::DrawArea, kArea);
    w->setTool(ToolId::Select);
    // Drag the north-east corner across the west edge: the ring crosses itself.
    drag(w->mapView(), kArea[2], {8.3265, 49.0120});
    const QStringList problems = w->missionLayer()->problems();
    ASSERT_EQ(problems.size(), 1);
    EXPECT_TRUE(problems[0].contains(QStringLiteral("the area intersects itself"))) << problems[0].toStdString();
    ASSERT_NE(w->missionLayer()->itemFor(ShapeRef::area()), nullptr);
    EXPECT_FALSE(w->missionLayer()->itemFor(ShapeRef::area())->problem().isEmpty());
    w->document()->undoStack()->undo();
    EXPECT_TRUE(w->missionLayer()->problems().isEmpty());
}
