// Planning from the GUI: background plans, the plan layer, waypoint editing with undo, export and
// re-import, replans that keep hand edits, the planner comparison and cancelling.
#include "core/io/waypoint_formats.h"
#include "core/mission/planner_kinds.h"
#include "ui/commands/edit_aircraft_command.h"
#include "ui/commands/move_vertex_command.h"
#include "ui/commands/move_waypoint_command.h"
#include "ui/map/plan_layer.h"
#include "ui/mission_document.h"
#include "ui/panels/problems_panel.h"
#include "ui/panels/statistics_panel.h"
#include "ui/panels/waypoint_panel.h"
#include "ui/panels/waypoint_table_model.h"
#include "ui/planning/plan_controller.h"
#include "ui/planning/route_export.h"
#include "ui_test_util.h"

#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QGraphicsScene>
#include <QListWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QThreadPool>
#include <QTimer>
#include <QUndoStack>

#include <gtest/gtest.h>

using namespace pf;
using namespace pf::ui;

namespace {

// The demo mission, planned through the GUI (auto-planning off so each test decides when to plan).
std::unique_ptr<MainWindow> plannedDemo() {
    auto w = test::makeWindow();
    w->planController()->setAutoPlan(false);
    QString error;
    EXPECT_TRUE(w->openDemoMission(&error)) << error.toStdString();
    w->planNow();
    EXPECT_TRUE(w->planController()->waitForIdle(120000));
    EXPECT_TRUE(w->planController()->lastError().isEmpty())
        << w->planController()->lastError().toStdString();
    return w;
}

const route::Route& routeOf(MainWindow* w, int i) {
    return w->document()->routes().at(std::size_t(i)).route;
}

// A photo waypoint in the middle of route 0.
int middlePhoto(const route::Route& r) {
    for (std::size_t i = r.waypoints.size() / 2; i < r.waypoints.size(); ++i)
        if (r.waypoints[i].kind == route::WaypointKind::Photo)
            return int(i);
    return 0;
}

geo::LonLat offset(const geo::LonLat& p, double eastM, double northM) {
    return {p.lon + eastM / (111319.49 * std::cos(p.lat * 3.14159265358979 / 180.0)),
            p.lat + northM / 111319.49};
}

} // namespace

TEST(Planning, DemoMissionPlannedFromTheGuiShowsEveryPathInTheScene) {
    auto w = plannedDemo();
    const auto& plan = w->planController()->plan();
    ASSERT_TRUE(plan.has_value());
    ASSERT_FALSE(plan->aircraft.empty());
    const auto& items = w->planLayer()->routeItems();
    ASSERT_EQ(items.size(), plan->aircraft.size());
    for (std::size_t a = 0; a < items.size(); ++a) {
        EXPECT_EQ(items[a]->scene(), w->mapView()->scene());
        EXPECT_TRUE(items[a]->isVisible());
        EXPECT_EQ(items[a]->data().points.size(), int(plan->aircraft[a].route.waypoints.size()));
        EXPECT_GT(items[a]->data().points.size(), 10);
        // The route is drawn in its aircraft's colour.
        for (const auto& ac : w->document()->mission().aircraft) {
            if (ac.name == plan->aircraft[a].aircraft) {
                EXPECT_EQ(items[a]->data().colour, QColor(QString::fromStdString(ac.colour)));
            }
        }
    }
    // Statistics: one row per aircraft and the total.
    EXPECT_EQ(w->statisticsPanel()->statistics()->rowCount(), int(plan->aircraft.size()) + 1);
    // The waypoint table shows the first route.
    EXPECT_EQ(w->waypointPanel()->model()->rowCount(), int(routeOf(w.get(), 0).waypoints.size()));
    // Planned routes keep clear of the no-fly zones: nothing is flagged.
    EXPECT_TRUE(w->planLayer()->routeProblems().isEmpty())
        << w->planLayer()->routeProblems().join('\n').toStdString();
    // Each layer hides with its View entry.
    w->planLayer()->setVisible(PlanLayer::Part::Paths, false);
    for (auto* item : items)
        EXPECT_FALSE(item->isVisible());
    w->planLayer()->setVisible(PlanLayer::Part::Paths, true);
    // Footprints are off by default and drawn when asked for, one per photo.
    w->planLayer()->setVisible(PlanLayer::Part::Footprints, true);
    EXPECT_EQ(w->planLayer()->footprintCount(), plan->totals.photos);
}

TEST(Planning, DragAWaypointOnTheMapAndUndo) {
    auto w = plannedDemo();
    w->setTool(ToolId::Waypoints);
    const route::Route before = routeOf(w.get(), 0);
    const int k = middlePhoto(before);
    const geo::LonLat from = before.waypoints[std::size_t(k)].position;
    const geo::LonLat to = offset(from, 12.0, -7.0);
    w->mapView()->centreOn(from);
    QApplication::processEvents();
    test::drag(w->mapView(), from, to);
    const auto& after = w->document()->routes().at(0);
    EXPECT_TRUE(after.edited);
    ASSERT_EQ(after.route.waypoints.size(), before.waypoints.size());
    EXPECT_LT(test::metresBetween(after.route.waypoints[std::size_t(k)].position, to), 1.0);
    for (std::size_t i = 0; i < before.waypoints.size(); ++i) {
        if (int(i) != k) {
            EXPECT_EQ(after.route.waypoints[i], before.waypoints[i]) << "waypoint " << i;
        }
    }
    EXPECT_EQ(w->planLayer()->routeItems()[0]->data().points[k],
              toScene(after.route.waypoints[std::size_t(k)].position));
    w->document()->undoStack()->undo();
    EXPECT_EQ(routeOf(w.get(), 0).waypoints, before.waypoints);
    EXPECT_FALSE(w->document()->routes().at(0).edited);
    w->document()->undoStack()->redo();
    EXPECT_LT(test::metresBetween(routeOf(w.get(), 0).waypoints[std::size_t(k)].position, to), 1.0);
}

TEST(Planning, SetAltitudeForAllWaypointsAndUndo) {
    auto w = plannedDemo();
    const route::Route before = routeOf(w.get(), 0);
    w->waypointPanel()->setAltitude(55.0, /*all=*/true);
    for (const auto& wp : routeOf(w.get(), 0).waypoints)
        EXPECT_DOUBLE_EQ(wp.altitudeM, 55.0);
    EXPECT_TRUE(w->document()->routes().at(0).edited);
    w->document()->undoStack()->undo();
    EXPECT_EQ(routeOf(w.get(), 0).waypoints, before.waypoints);

    // Selected rows only.
    auto* table = w->waypointPanel()->table();
    table->selectRow(2);
    ASSERT_EQ(w->waypointPanel()->selectedWaypoints(), QList<int>{2});
    EXPECT_EQ(w->planLayer()->selectedWaypoints(), QList<int>{2}); // the map follows the table
    w->waypointPanel()->setAltitude(61.5, /*all=*/false);
    for (std::size_t i = 0; i < before.waypoints.size(); ++i)
        EXPECT_DOUBLE_EQ(routeOf(w.get(), 0).waypoints[i].altitudeM,
                         i == 2 ? 61.5 : before.waypoints[i].altitudeM);
}

TEST(Planning, TableEditsReverseInsertAndDeleteAreUndoable) {
    auto w = plannedDemo();
    auto* model = w->waypointPanel()->model();
    const route::Route before = routeOf(w.get(), 0);
    auto* stack = w->document()->undoStack();
    const int start = stack->index();
    // The first photo waypoint after the first waypoint (where the plan begins with transits from
    // home, they come first).
    int k = 1;
    while (k < int(before.waypoints.size()) && before.waypoints[std::size_t(k)].kind != route::WaypointKind::Photo)
        ++k;
    ASSERT_LT(k, int(before.waypoints.size()));
    EXPECT_TRUE(model->setData(model->index(k, WaypointTableModel::Heading), 370.0));
    EXPECT_DOUBLE_EQ(routeOf(w.get(), 0).waypoints[std::size_t(k)].headingDeg, 10.0);
    EXPECT_TRUE(
        model->setData(model->index(k, WaypointTableModel::Action), QStringLiteral("transit")));
    EXPECT_EQ(routeOf(w.get(), 0).waypoints[std::size_t(k)].kind, route::WaypointKind::Transit);
    EXPECT_TRUE(model->setData(model->index(k, WaypointTableModel::Latitude), 49.0111));
    EXPECT_DOUBLE_EQ(routeOf(w.get(), 0).waypoints[std::size_t(k)].position.lat, 49.0111);
    // Bad values are refused without an undo step.
    EXPECT_FALSE(model->setData(model->index(k, WaypointTableModel::Altitude), -3.0));
    EXPECT_FALSE(model->setData(model->index(k, WaypointTableModel::Latitude), 95.0));
    EXPECT_FALSE(
        model->setData(model->index(k, WaypointTableModel::Action), QStringLiteral("loiter")));
    EXPECT_EQ(stack->index(), start + 3);

    w->waypointPanel()->reverseRoute();
    const auto& rev = routeOf(w.get(), 0).waypoints;
    ASSERT_EQ(rev.size(), before.waypoints.size());
    EXPECT_EQ(rev.front().position, before.waypoints.back().position);
    EXPECT_NEAR(rev.front().headingDeg,
                std::fmod(before.waypoints.back().headingDeg + 180.0, 360.0), 1e-9);

    w->waypointPanel()->table()->selectRow(4);
    w->waypointPanel()->insertAfterSelected();
    EXPECT_EQ(routeOf(w.get(), 0).waypoints.size(), before.waypoints.size() + 1);
    EXPECT_EQ(routeOf(w.get(), 0).waypoints[5].kind, route::WaypointKind::Turn);
    w->waypointPanel()->table()->selectRow(0);
    w->waypointPanel()->deleteSelected();
    EXPECT_EQ(routeOf(w.get(), 0).waypoints.size(), before.waypoints.size());
    EXPECT_EQ(model->rowCount(), int(before.waypoints.size()));
    // The statistics measure the edited route: one photo fewer when the deleted waypoint took one.
    const int planned = w->planController()->plan()->aircraft[0].metrics.photos;
    int photos = 0;
    for (const auto& wp : routeOf(w.get(), 0).waypoints)
        photos += wp.kind == route::WaypointKind::Photo ? 1 : 0;
    EXPECT_LT(photos, planned);
    EXPECT_EQ(w->statisticsPanel()->statistics()->item(0, 1)->text().toInt(), photos);
    EXPECT_TRUE(w->statisticsPanel()->statistics()->item(0, 0)->text().endsWith(
        QStringLiteral("(edited)")));

    while (stack->index() > start)
        stack->undo();
    EXPECT_EQ(routeOf(w.get(), 0).waypoints, before.waypoints);
    EXPECT_FALSE(w->document()->routes().at(0).edited);
}

TEST(Planning, AWaypointMovedIntoANoFlyZoneIsFlaggedOnTheMapTheTableAndTheProblems) {
    auto w = plannedDemo();
    auto* doc = w->document();
    const int k = middlePhoto(routeOf(w.get(), 0));
    const geo::LonLat warehouse{8.32945, 49.0120};
    doc->undoStack()->push(new MoveWaypointCommand(doc, 0, k, warehouse));
    const auto& issues = w->planLayer()->issues().at(0);
    EXPECT_TRUE(issues.waypoint[std::size_t(k)].contains(QStringLiteral("Warehouse")))
        << issues.waypoint[std::size_t(k)].toStdString();
    EXPECT_TRUE(w->planLayer()->routeItems()[0]->data().badPoint[k]);
    // Both legs touching it cross the zone's margin.
    EXPECT_TRUE(w->planLayer()->routeItems()[0]->data().badLeg[k - 1]);
    EXPECT_TRUE(w->planLayer()->routeItems()[0]->data().badLeg[k]);
    auto* model = w->waypointPanel()->model();
    EXPECT_TRUE(model->data(model->index(k, WaypointTableModel::Problem))
                    .toString()
                    .contains(QStringLiteral("Warehouse")));
    EXPECT_TRUE(model->data(model->index(k, 0), Qt::BackgroundRole).isValid());
    EXPECT_FALSE(model->data(model->index(0, 0), Qt::BackgroundRole).isValid());
    bool listed = false;
    for (int i = 0; i < w->problemsList()->count(); ++i)
        listed |= w->problemsList()->item(i)->text().contains(
            QStringLiteral("waypoint %1: inside no-fly zone Warehouse").arg(k + 1));
    EXPECT_TRUE(listed);
    doc->undoStack()->undo();
    EXPECT_TRUE(w->planLayer()->routeProblems().isEmpty());
}

TEST(Planning, ExportAndReimportPlanAndWaypointsFiles) {
    auto w = plannedDemo();
    auto* doc = w->document();
    // An edit first: the files carry what the user changed.
    w->waypointPanel()->table()->selectRow(3);
    w->waypointPanel()->setAltitude(70.0, false);
    std::vector<route::Route> routes;
    for (const auto& r : doc->routes())
        routes.push_back(r.route);
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    ExportRequest req;
    req.folder = dir.path();
    req.formats = {io::WaypointFormat::QgcPlan, io::WaypointFormat::QgcWpl};
    QString error;
    const QStringList written = exportRoutes(doc->mission(), routes, req, &error);
    ASSERT_TRUE(error.isEmpty()) << error.toStdString();
    ASSERT_EQ(written.size(), int(2 * routes.size())); // neither format holds several vehicles
    for (const QString& ext : {QStringLiteral(".plan"), QStringLiteral(".waypoints")}) {
        for (std::size_t r = 0; r < routes.size(); ++r) {
            const io::ExportContext ctx = io::makeExportContext(doc->mission(), routes);
            const QString expected =
                QStringLiteral("mission-") +
                QString::fromStdString(io::routeFileName(ctx, r,
                                                         ext == QLatin1String(".plan")
                                                             ? io::WaypointFormat::QgcPlan
                                                             : io::WaypointFormat::QgcWpl));
            QString file;
            for (const QString& f : written)
                if (QFileInfo(f).fileName() == expected)
                    file = f;
            ASSERT_FALSE(file.isEmpty());
            // Start from a fresh plan: the file brings the edit back, onto the aircraft it names.
            w->planNow();
            ASSERT_TRUE(w->planController()->waitForIdle(120000));
            if (doc->anyRouteEdited())
                w->replaceEditedPaths();
            ASSERT_FALSE(doc->anyRouteEdited());
            ASSERT_EQ(w->openWaypointFile(file, -1, &error), 1) << error.toStdString();
            const auto& back = doc->routes().at(r);
            EXPECT_TRUE(back.edited);
            EXPECT_EQ(back.route.aircraft, routes[r].aircraft);
            ASSERT_EQ(back.route.waypoints.size(), routes[r].waypoints.size())
                << file.toStdString();
            for (std::size_t i = 0; i < routes[r].waypoints.size(); ++i) {
                EXPECT_LT(test::metresBetween(back.route.waypoints[i].position,
                                              routes[r].waypoints[i].position),
                          0.05)
                    << file.toStdString() << " waypoint " << i;
                EXPECT_NEAR(back.route.waypoints[i].altitudeM, routes[r].waypoints[i].altitudeM,
                            0.01);
            }
            doc->undoStack()->undo(); // the import is one undo step
            EXPECT_FALSE(doc->routes().at(r).edited);
        }
    }
    // Bad input: a file that does not exist, an export with no format.
    EXPECT_EQ(w->openWaypointFile(dir.filePath(QStringLiteral("missing.plan")), -1, &error), 0);
    EXPECT_FALSE(error.isEmpty());
    req.formats.clear();
    EXPECT_TRUE(exportRoutes(doc->mission(), routes, req, &error).isEmpty());
    EXPECT_EQ(error, QStringLiteral("Choose at least one format."));
    req.formats = {io::WaypointFormat::Gpx};
    EXPECT_TRUE(exportRoutes(doc->mission(), {}, req, &error).isEmpty());
    EXPECT_EQ(error, QStringLiteral("Nothing to export: no route is planned or chosen."));
}

TEST(Planning, AnAutomaticReplanNeverDiscardsEditedPaths) {
    auto w = plannedDemo();
    auto* doc = w->document();
    auto* planner = w->planController();
    const int k = middlePhoto(routeOf(w.get(), 0));
    const geo::LonLat moved = offset(routeOf(w.get(), 0).waypoints[std::size_t(k)].position, 5, 5);
    doc->undoStack()->push(new MoveWaypointCommand(doc, 0, k, moved));
    const route::Route edited = routeOf(w.get(), 0);
    planner->setAutoPlan(true);
    // An edit of the area triggers an automatic plan after the debounce.
    geo::LonLat v = doc->mission().area.outer[1];
    doc->undoStack()->push(
        new MoveVertexCommand(doc, ShapeRef::area(), VertexRef{0, 1}, offset(v, 3, 0)));
    ASSERT_TRUE(planner->waitForIdle(120000));
    EXPECT_TRUE(w->planNoticeVisible());
    EXPECT_TRUE(planner->hasPendingPlan());
    EXPECT_EQ(routeOf(w.get(), 0).waypoints, edited.waypoints); // the edited path is kept
    EXPECT_TRUE(doc->routes().at(0).edited);
    // A manual plan in a window that cannot ask waits in the same way.
    w->planNow();
    ASSERT_TRUE(planner->waitForIdle(120000));
    EXPECT_EQ(routeOf(w.get(), 0).waypoints, edited.waypoints);
    // Only the user's word replaces it.
    w->replaceEditedPaths();
    EXPECT_FALSE(w->planNoticeVisible());
    EXPECT_FALSE(doc->routes().at(0).edited);
    EXPECT_NE(routeOf(w.get(), 0).waypoints, edited.waypoints);
    // An edit recorded against the replaced plan cannot bring it back.
    const auto planned = routeOf(w.get(), 0).waypoints;
    doc->undoStack()->undo(); // the area edit
    planner->cancel();
    doc->undoStack()->undo(); // the waypoint move: obsolete now
    EXPECT_EQ(routeOf(w.get(), 0).waypoints, planned);
}

TEST(Planning, ComparisonFillsARowPerPlannerKind) {
    auto w = plannedDemo();
    w->planController()->compare();
    EXPECT_TRUE(w->planController()->isComparing());
    ASSERT_TRUE(w->planController()->waitForIdle(180000));
    auto* table = w->statisticsPanel()->comparison();
    const auto& kinds = mission::plannerKinds();
    ASSERT_EQ(table->rowCount(), int(kinds.size()));
    for (std::size_t r = 0; r < kinds.size(); ++r)
        EXPECT_EQ(table->item(int(r), 0)->text(), QString::fromUtf8(kinds[r].label));
    for (const auto& row : w->planController()->comparison()) {
        EXPECT_TRUE(row.ok) << row.error.toStdString();
        EXPECT_GT(row.totals.photos, 0);
    }
    // The turns shown are the flown routes' (those the Plan tab and the CLI show), per planner.
    const auto& rows = w->planController()->comparison();
    for (std::size_t r = 0; r < rows.size(); ++r)
        if (rows[r].ok) {
            EXPECT_EQ(table->item(int(r), StatisticsPanel::CTurns)->text(), QString::number(rows[r].totals.flightTurns))
                << kinds[r].id;
        }
    // Every metric column has its best value highlighted (the last column holds the Use buttons).
    for (int c = 1; c < StatisticsPanel::CUse; ++c) {
        int bold = 0;
        for (int r = 0; r < table->rowCount(); ++r)
            bold += table->item(r, c)->font().bold() ? 1 : 0;
        EXPECT_GE(bold, 1) << "column " << c;
    }
}

TEST(Planning, CancelLeavesTheUiResponsiveAndShowsNoStalePlan) {
    auto w = test::makeWindow();
    auto* planner = w->planController();
    planner->setAutoPlan(false);
    QString error;
    ASSERT_TRUE(w->openDemoMission(&error));
    w->planNow();
    EXPECT_TRUE(planner->isBusy());
    planner->cancel();
    EXPECT_FALSE(planner->isBusy());
    // The event loop runs while the abandoned computation finishes on its worker.
    int ticks = 0;
    QTimer timer;
    QObject::connect(&timer, &QTimer::timeout, [&] { ++ticks; });
    timer.start(5);
    QThreadPool::globalInstance()->waitForDone(120000);
    QTest::qWait(100);
    EXPECT_GT(ticks, 0);
    EXPECT_FALSE(planner->plan().has_value());
    EXPECT_TRUE(w->document()->routes().empty());
    EXPECT_TRUE(w->planLayer()->routeItems().empty());
    // A plan superseded by a newer one is dropped too: only the newest arrives.
    int applied = 0;
    QObject::connect(planner, &PlanController::planChanged, [&] { ++applied; });
    w->planNow();
    w->planNow();
    ASSERT_TRUE(planner->waitForIdle(120000));
    QThreadPool::globalInstance()->waitForDone(120000);
    QTest::qWait(50);
    EXPECT_EQ(applied, 1);
    EXPECT_TRUE(planner->plan().has_value());
}

TEST(Planning, PlannerAndAngleChoicesAreUndoableMissionEdits) {
    auto w = test::makeWindow();
    w->planController()->setAutoPlan(false);
    QString error;
    ASSERT_TRUE(w->openDemoMission(&error));
    auto* doc = w->document();
    auto* box = w->findChild<QComboBox*>(QStringLiteral("PlannerBox"));
    ASSERT_NE(box, nullptr);
    auto* angle = w->findChild<QDoubleSpinBox*>(QStringLiteral("GridAngleBox"));
    ASSERT_NE(angle, nullptr);
    const auto before = doc->mission().options;
    EXPECT_EQ(angle->text(), QStringLiteral("Auto angle"));
    angle->setValue(30);
    ASSERT_TRUE(doc->mission().options.gridAngleDeg.has_value());
    EXPECT_DOUBLE_EQ(*doc->mission().options.gridAngleDeg, 30.0);
    doc->undoStack()->undo();
    EXPECT_EQ(doc->mission().options, before);
    EXPECT_EQ(angle->value(), -1.0);
    // The planner list: choosing an entry is one undo step; undo brings the list back.
    const int raster = box->findData(int(mission::PlannerKind::Raster));
    box->setCurrentIndex(raster);
    emit box->activated(raster);
    EXPECT_EQ(doc->mission().options.planner, mission::PlannerKind::Raster);
    doc->undoStack()->undo();
    EXPECT_EQ(doc->mission().options.planner, before.planner);
    EXPECT_EQ(box->currentData().toInt(), int(before.planner));
    w->planNow();
    ASSERT_TRUE(w->planController()->waitForIdle(120000));
    // With a fixed angle, the plan uses it.
    angle->setValue(45);
    w->planNow();
    ASSERT_TRUE(w->planController()->waitForIdle(120000));
    for (const auto& a : w->planController()->plan()->aircraft) {
        EXPECT_NEAR(a.gridAngleDeg, 45.0, 1e-9);
        EXPECT_EQ(a.anglesTried, 1);
    }
}

TEST(Planning, ScreenshotOfThePlannedDemoShowsThePaths) {
    auto w = plannedDemo();
    w->setBaseMap(QStringLiteral("none"));
    w->zoomToMission();
    const QImage img = w->mapView()->viewport()->grab().toImage();
    const QString dir = qEnvironmentVariable("PF_SCREENSHOT_DIR");
    if (!dir.isEmpty())
        img.save(QDir(dir).filePath(QStringLiteral("planned_map.png")));
    for (std::size_t a = 0; a < w->planLayer()->routeItems().size(); ++a) {
        const QColor c = w->planLayer()->colourOf(int(a));
        int n = 0;
        for (int y = 0; y < img.height(); ++y)
            for (int x = 0; x < img.width(); ++x) {
                const QColor p = img.pixelColor(x, y);
                n += std::abs(p.red() - c.red()) <= 20 && std::abs(p.green() - c.green()) <= 20 &&
                     std::abs(p.blue() - c.blue()) <= 20;
            }
        EXPECT_GT(n, 300) << "route " << a;
    }
}

TEST(Planning, ShortEnduranceShowsSortiesAndTheStatisticsCountThem) {
    auto w = test::makeWindow();
    w->planController()->setAutoPlan(false);
    QString error;
    ASSERT_TRUE(w->openDemoMission(&error));
    auto* doc = w->document();
    for (int i = 0; i < int(doc->mission().aircraft.size()); ++i) {
        auto a = doc->mission().aircraft[std::size_t(i)];
        // Short enough for several batteries, long enough for the farthest photo and back with the stop
        // at each turn (at 3 min the Falcon 8 could not reach its farthest photo and return).
        a.enduranceMin = 4.0;
        doc->undoStack()->push(new EditAircraftCommand(doc, i, a, QStringLiteral("endurance")));
    }
    w->planNow();
    ASSERT_TRUE(w->planController()->waitForIdle(120000));
    ASSERT_TRUE(w->planController()->lastError().isEmpty())
        << w->planController()->lastError().toStdString();
    const auto& plan = *w->planController()->plan();
    auto* stats = w->statisticsPanel()->statistics();
    int totalSorties = 0;
    for (std::size_t a = 0; a < plan.aircraft.size(); ++a) {
        const auto& ap = plan.aircraft[a];
        EXPECT_GT(ap.sorties.size(), 1u) << ap.aircraft;
        totalSorties += int(ap.sorties.size());
        // A badge per sortie on the map, at the sortie's first waypoint.
        const auto& starts = w->planLayer()->routeItems()[a]->data().sortieStarts;
        ASSERT_EQ(starts.size(), int(ap.sorties.size()));
        for (std::size_t s = 0; s < ap.sorties.size(); ++s)
            EXPECT_EQ(starts[int(s)], ap.sorties[s].firstWaypoint);
        EXPECT_EQ(stats->item(int(a), 5)->text(), QString::number(ap.sorties.size()));
    }
    EXPECT_EQ(stats->item(int(plan.aircraft.size()), 5)->text(), QString::number(totalSorties));
    // Uncovered patches of the coverage check: one item each, hidden with their View entry.
    EXPECT_EQ(w->planLayer()->uncoveredPatchCount(), int(plan.uncovered.size()));
}

TEST(Planning, DoubleClickOnALegInsertsAWaypointAndDeleteRemovesIt) {
    auto w = plannedDemo();
    w->setTool(ToolId::Waypoints);
    const route::Route before = routeOf(w.get(), 0);
    // The middle of a long leg between two waypoints.
    std::size_t leg = 0;
    double longest = 0;
    for (std::size_t i = 0; i + 1 < before.waypoints.size(); ++i) {
        const double d =
            test::metresBetween(before.waypoints[i].position, before.waypoints[i + 1].position);
        if (d > longest) {
            longest = d;
            leg = i;
        }
    }
    ASSERT_GT(longest, 10.0);
    const auto& a = before.waypoints[leg].position;
    const auto& b = before.waypoints[leg + 1].position;
    const geo::LonLat mid{(a.lon + b.lon) / 2, (a.lat + b.lat) / 2};
    w->mapView()->centreOn(mid);
    QApplication::processEvents();
    QTest::mouseDClick(w->mapView()->viewport(), Qt::LeftButton, Qt::NoModifier,
                       test::viewPos(w->mapView(), mid));
    const auto& after = routeOf(w.get(), 0).waypoints;
    ASSERT_EQ(after.size(), before.waypoints.size() + 1);
    EXPECT_LT(test::metresBetween(after[leg + 1].position, mid), 1.0);
    EXPECT_EQ(after[leg + 1].kind, route::WaypointKind::Turn);
    EXPECT_EQ(w->planLayer()->selectedWaypoints(), QList<int>{int(leg) + 1});
    // Delete on the map removes the selected waypoint again.
    QTest::keyClick(w->mapView(), Qt::Key_Delete);
    EXPECT_EQ(routeOf(w.get(), 0).waypoints, before.waypoints);
}

TEST(Planning, ClickingAProblemSelectsTheWaypointItNames) {
    auto w = plannedDemo();
    auto* doc = w->document();
    const int k = middlePhoto(routeOf(w.get(), 0));
    doc->undoStack()->push(new MoveWaypointCommand(doc, 0, k, geo::LonLat{8.32945, 49.0120}));
    QListWidgetItem* found = nullptr;
    for (int i = 0; i < w->problemsList()->count(); ++i)
        if (w->problemsList()->item(i)->text().contains(
                QStringLiteral("waypoint %1: inside").arg(k + 1)))
            found = w->problemsList()->item(i);
    ASSERT_NE(found, nullptr);
    w->problemsList()->scrollToItem(found);
    QTest::mouseClick(w->problemsList()->viewport(), Qt::LeftButton, Qt::NoModifier,
                      w->problemsList()->visualItemRect(found).center());
    EXPECT_EQ(w->planLayer()->selectedRoute(), 0);
    EXPECT_EQ(w->planLayer()->selectedWaypoints(), QList<int>{k});
    // The table follows the selection.
    EXPECT_EQ(w->waypointPanel()->selectedWaypoints(), QList<int>{k});
}
