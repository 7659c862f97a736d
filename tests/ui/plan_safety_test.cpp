// What an operator is never handed (issue 14): an outdated plan without a mark, a route into a no-fly
// margin without a confirmation, an altitude out of limits, a mission file without its extension, a
// planner comparison one cannot act on. Driven through the real widgets, offscreen.
#include "core/io/waypoint_formats.h"
#include "core/mission/planner_kinds.h"
#include "ui/commands/add_no_fly_zone_command.h"
#include "ui/commands/edit_aircraft_command.h"
#include "ui/commands/move_waypoint_command.h"
#include "ui/commands/remove_waypoints_command.h"
#include "ui/dialogs/export_dialog.h"
#include "ui/map/plan_layer.h"
#include "ui/mission_document.h"
#include "ui/mission_files.h"
#include "ui/panels/aircraft_panel.h"
#include "ui/panels/problems_panel.h"
#include "ui/panels/statistics_panel.h"
#include "ui/planning/plan_controller.h"
#include "ui_test_util.h"

#include <QAction>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QMessageBox>
#include <QFileInfo>
#include <QLabel>
#include <QPointer>
#include <QPushButton>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QUndoStack>

#include <gtest/gtest.h>

#include <memory>

using namespace pf;
using namespace pf::ui;

namespace {

std::unique_ptr<MainWindow> plannedDemo() {
    auto w = test::makeWindow();
    w->planController()->setAutoPlan(false);
    QString error;
    EXPECT_TRUE(w->openDemoMission(&error)) << error.toStdString();
    w->planNow();
    EXPECT_TRUE(w->planController()->waitForIdle(120000));
    EXPECT_FALSE(w->planController()->isOutdated());
    return w;
}

void setAltitude(MissionDocument* doc, int aircraft, double altitudeM) {
    auto a = doc->mission().aircraft.at(std::size_t(aircraft));
    a.altitudeM = altitudeM;
    a.gsdCm.reset();
    doc->undoStack()->push(new EditAircraftCommand(doc, aircraft, a, QStringLiteral("altitude")));
}

std::vector<route::Route> routesOf(MissionDocument* doc) {
    std::vector<route::Route> out;
    for (const auto& r : doc->routes()) out.push_back(r.route);
    return out;
}

// Altitudes of the waypoints of a .plan file, as the autopilot reads them.
std::vector<double> planAltitudes(const QString& path) {
    std::vector<double> out;
    auto imported = io::importWaypoints(path.toStdString());
    EXPECT_TRUE(imported.ok()) << (imported.ok() ? "" : imported.error().message);
    if (imported.ok())
        for (const auto& w : imported->routes.at(0).waypoints) out.push_back(w.altitudeM);
    return out;
}

QString planFileOf(const QStringList& written, const std::string& aircraft) {
    QString name = QString::fromStdString(aircraft);
    for (QChar& c : name)
        if (!c.isLetterOrNumber()) c = QLatin1Char('_');
    for (const QString& f : written)
        if (f.endsWith(name + QStringLiteral(".plan"))) return f;
    return {};
}

} // namespace

// Item 1: while a replan runs the old plan is faded and marked outdated; Export waits for the new one.
TEST(PlanSafety, AnOutdatedPlanIsFadedMarkedAndExportWaitsForTheNewPlan) {
    auto w = plannedDemo();
    auto* doc = w->document();
    auto* planner = w->planController();
    const std::string falcon = doc->mission().aircraft[0].name;
    for (auto* item : w->planLayer()->routeItems()) EXPECT_DOUBLE_EQ(item->opacity(), 1.0);
    EXPECT_TRUE(w->statisticsPanel()->stateText().isEmpty());

    setAltitude(doc, 0, 52.0);
    EXPECT_TRUE(planner->isOutdated());
    for (auto* item : w->planLayer()->routeItems()) EXPECT_LT(item->opacity(), 0.5);
    EXPECT_TRUE(w->statisticsPanel()->stateText().contains(QStringLiteral("Outdated"))) << w->statisticsPanel()->stateText().toStdString();
    EXPECT_FALSE(w->statisticsPanel()->statistics()->isEnabled());

    QTemporaryDir dir;
    ExportDialog dialog(doc, planner, dir.path());
    EXPECT_TRUE(dialog.bannerText().contains(QStringLiteral("Outdated plan"))) << dialog.bannerText().toStdString();
    QSignalSpy exported(&dialog, &ExportDialog::exported);
    auto answer = test::answerNextMessageBox(QStringLiteral("Wait for the new plan"));
    EXPECT_TRUE(dialog.runExport().isEmpty()); // nothing written while the plan is outdated
    EXPECT_TRUE(answer->answered);
    EXPECT_TRUE(answer->text.contains(QStringLiteral("outdated")));
    EXPECT_TRUE(dialog.isWaiting());
    EXPECT_TRUE(planner->isBusy()); // waiting started the new plan
    EXPECT_TRUE(QDir(dir.path()).entryList(QDir::Files).isEmpty());
    ASSERT_TRUE(planner->waitForIdle(120000));
    ASSERT_TRUE(exported.wait(5000) || exported.count() > 0);
    const QStringList written = exported.takeFirst().at(0).toStringList();
    ASSERT_FALSE(written.isEmpty());
    EXPECT_FALSE(planner->isOutdated());
    EXPECT_FALSE(dialog.isWaiting());
    // The file flies what the dock says.
    const auto alts = planAltitudes(planFileOf(written, falcon));
    ASSERT_FALSE(alts.empty());
    for (double a : alts) EXPECT_NEAR(a, 52.0, 0.01);
    for (auto* item : w->planLayer()->routeItems()) EXPECT_DOUBLE_EQ(item->opacity(), 1.0);
}

// Item 1: a cancelled replan leaves the plan outdated (and says so); a new zone marks it too.
TEST(PlanSafety, ACancelledReplanOrANewZoneLeavesThePlanVisiblyOutdated) {
    auto w = plannedDemo();
    auto* doc = w->document();
    auto* planner = w->planController();
    setAltitude(doc, 0, 1.0 + doc->mission().aircraft[0].altitudeM.value_or(40.0));
    w->planNow();
    planner->cancel();
    EXPECT_TRUE(planner->isOutdated());
    EXPECT_TRUE(w->statisticsPanel()->stateText().contains(QStringLiteral("Press F5")))
        << w->statisticsPanel()->stateText().toStdString();
    // Undo back to what was planned: the plan is current again.
    doc->undoStack()->undo();
    EXPECT_FALSE(planner->isOutdated());
    for (auto* item : w->planLayer()->routeItems()) EXPECT_DOUBLE_EQ(item->opacity(), 1.0);

    mission::NoFlyZone crane;
    crane.name = "Crane";
    const auto mid = doc->routes()[0].route.waypoints[doc->routes()[0].route.waypoints.size() / 2].position;
    const double d = 0.0001;
    crane.polygon.outer = {{mid.lon - d, mid.lat - d}, {mid.lon + d, mid.lat - d}, {mid.lon + d, mid.lat + d}, {mid.lon - d, mid.lat + d}};
    doc->undoStack()->push(new AddNoFlyZoneCommand(doc, crane));
    EXPECT_TRUE(planner->isOutdated());
    for (auto* item : w->planLayer()->routeItems()) EXPECT_LT(item->opacity(), 0.5);
    // The old routes across the new zone are flagged as well.
    EXPECT_FALSE(w->planLayer()->routeProblems().isEmpty());
}

// Item 1: after "Keep edits" every route shown is the one that will be exported.
TEST(PlanSafety, KeepEditsGivesTheOtherAircraftTheNewPlan) {
    auto w = plannedDemo();
    auto* doc = w->document();
    auto* planner = w->planController();
    ASSERT_GE(doc->routes().size(), 2u);
    auto r0 = doc->routes()[0].route;
    const auto moved = r0.waypoints[r0.waypoints.size() / 2].position;
    doc->undoStack()->push(new MoveWaypointCommand(doc, 0, int(r0.waypoints.size() / 2), {moved.lon + 0.00002, moved.lat}));
    const auto edited = doc->routes()[0].route.waypoints;
    setAltitude(doc, 1, 65.0);
    w->planNow(); // a window that cannot ask: the plan waits
    ASSERT_TRUE(planner->waitForIdle(120000));
    ASSERT_TRUE(planner->hasPendingPlan());
    EXPECT_TRUE(planner->isOutdated());
    planner->keepEditsWithPendingPlan();
    EXPECT_FALSE(planner->hasPendingPlan());
    EXPECT_FALSE(planner->isOutdated());
    EXPECT_EQ(doc->routes()[0].route.waypoints, edited);
    EXPECT_TRUE(doc->routes()[0].edited);
    const std::string other = doc->mission().aircraft[1].name;
    for (std::size_t r = 0; r < doc->routes().size(); ++r) {
        if (doc->routes()[r].route.aircraft != other) continue;
        EXPECT_FALSE(doc->routes()[r].edited);
        for (const auto& wp : doc->routes()[r].route.waypoints) EXPECT_NEAR(wp.altitudeM, 65.0, 1e-9);
        // What is drawn is that route.
        const auto& drawn = w->planLayer()->routeItems()[r]->data().points;
        ASSERT_EQ(drawn.size(), int(doc->routes()[r].route.waypoints.size()));
        EXPECT_EQ(drawn.front(), toScene(doc->routes()[r].route.waypoints.front().position));
    }
}

// Item 2: a route into a no-fly margin is exported only after a confirmation that lists the problems.
TEST(PlanSafety, ExportListsRouteErrorsAndWritesOnlyWhenConfirmed) {
    auto w = plannedDemo();
    auto* doc = w->document();
    const auto& r0 = doc->routes()[0].route;
    doc->undoStack()->push(new MoveWaypointCommand(doc, 0, int(r0.waypoints.size() / 2), geo::LonLat{8.32945, 49.0120}));
    QTemporaryDir dir;
    ExportDialog dialog(doc, w->planController(), dir.path());
    EXPECT_TRUE(dialog.bannerText().contains(QStringLiteral("route problem"))) << dialog.bannerText().toStdString();
    auto no = test::answerNextMessageBox(QStringLiteral("Cancel"));
    EXPECT_TRUE(dialog.runExport().isEmpty());
    EXPECT_TRUE(no->answered);
    EXPECT_TRUE(no->informative.contains(QStringLiteral("inside no-fly zone Warehouse"))) << no->informative.toStdString();
    EXPECT_TRUE(QDir(dir.path()).entryList(QDir::Files).isEmpty());
    auto yes = test::answerNextMessageBox(QStringLiteral("Export anyway"));
    EXPECT_FALSE(dialog.runExport().isEmpty());
    EXPECT_TRUE(yes->answered);
    EXPECT_FALSE(QDir(dir.path()).entryList(QDir::Files).isEmpty());
    // The function the dialog runs refuses on its own, naming every problem.
    ExportRequest req;
    req.folder = dir.path() + QStringLiteral("/again");
    req.formats = {io::WaypointFormat::QgcPlan};
    QString error;
    QStringList problems;
    EXPECT_TRUE(exportRoutes(doc->mission(), routesOf(doc), req, &error, &problems).isEmpty());
    EXPECT_TRUE(error.startsWith(QStringLiteral("Not exported: the route check found")));
    EXPECT_FALSE(problems.isEmpty());
    EXPECT_FALSE(QFileInfo::exists(req.folder));
}

// Item 3: altitudes out of limits are refused where they are typed, with the reason.
TEST(PlanSafety, AbsurdAltitudesAreRefusedWithTheReason) {
    auto w = test::makeWindow();
    auto* panel = w->aircraftPanel();
    auto* doc = w->document();
    panel->addCustom();
    const auto before = doc->mission().aircraft[0];
    const int steps = doc->undoStack()->count();
    panel->altitudeBox()->setValue(5000);
    EXPECT_EQ(doc->mission().aircraft[0], before);
    EXPECT_TRUE(panel->altitudeError().contains(QStringLiteral("above its maximum of 120.0 m"))) << panel->altitudeError().toStdString();
    EXPECT_DOUBLE_EQ(panel->altitudeBox()->value(), *before.altitudeM); // the stored value is back
    panel->altitudeBox()->setValue(0);
    EXPECT_TRUE(panel->altitudeError().contains(QStringLiteral("0 m is on the ground"))) << panel->altitudeError().toStdString();
    panel->altitudeBox()->setValue(1);
    EXPECT_TRUE(panel->altitudeError().contains(QStringLiteral("minimum safe altitude"))) << panel->altitudeError().toStdString();
    panel->gsdBox()->setValue(0);
    EXPECT_TRUE(panel->altitudeError().contains(QStringLiteral("greater than 0 cm/px"))) << panel->altitudeError().toStdString();
    EXPECT_EQ(doc->undoStack()->count(), steps);
    panel->altitudeBox()->setValue(5);
    EXPECT_TRUE(panel->altitudeError().isEmpty());
    EXPECT_DOUBLE_EQ(*doc->mission().aircraft[0].altitudeM, 5.0);
}

// Item 3: a mission out of limits is not planned; an aircraft without waypoints shows dashes; the
// total time is the longest aircraft's.
TEST(PlanSafety, OutOfLimitsIsNotPlannedAndStatisticsStayHonest) {
    auto w = plannedDemo();
    auto* doc = w->document();
    auto* planner = w->planController();
    auto* stats = w->statisticsPanel()->statistics();
    // The total time is the longest row's.
    const int n = int(planner->plan()->aircraft.size());
    QString longest;
    for (int r = 0; r < n; ++r) longest = std::max(longest, stats->item(r, StatisticsPanel::Time)->text().rightJustified(8));
    EXPECT_EQ(stats->item(n, StatisticsPanel::Time)->text().rightJustified(8), longest);
    // Per-aircraft planning times add up to the total's; the line below says what else took time.
    double sum = 0;
    for (int r = 0; r < n; ++r) sum += stats->item(r, StatisticsPanel::PlanMs)->text().toDouble();
    EXPECT_NEAR(stats->item(n, StatisticsPanel::PlanMs)->text().toDouble(), sum, n + 0.5);
    EXPECT_TRUE(w->statisticsPanel()->planTimeLabel()->text().startsWith(QStringLiteral("Planned in")));

    // Route 1 loses every waypoint: dashes, not figures of a flight that does not exist.
    QList<int> all;
    for (int i = 0; i < int(doc->routes()[1].route.waypoints.size()); ++i) all << i;
    doc->undoStack()->push(new RemoveWaypointsCommand(doc, 1, all));
    int row = -1;
    for (int r = 0; r < n; ++r)
        if (stats->item(r, 0)->text().startsWith(QString::fromStdString(doc->routes()[1].route.aircraft))) row = r;
    ASSERT_GE(row, 0);
    for (int c = StatisticsPanel::Photos; c < StatisticsPanel::PlanMs; ++c)
        EXPECT_EQ(stats->item(row, c)->text(), QStringLiteral("–")) << c;

    // 5000 m (e.g. from a file): not planned, the reason is an error in Problems.
    setAltitude(doc, 0, 5000.0);
    planner->planNow(true);
    ASSERT_TRUE(planner->waitForIdle(60000));
    EXPECT_TRUE(planner->lastError().contains(QStringLiteral("above its maximum"))) << planner->lastError().toStdString();
    EXPECT_TRUE(planner->isOutdated());
    bool listed = false;
    for (int i = 0; i < w->problemsList()->count(); ++i)
        listed |= w->problemsList()->item(i)->text().contains(QStringLiteral("above its maximum")) &&
                  w->problemsList()->severityOf(i) == ProblemsPanel::Severity::Error;
    EXPECT_TRUE(listed);
    EXPECT_TRUE(w->aircraftPanel()->footprintLabel()->text().contains(QStringLiteral("Not plannable")));
}

// Item 4: Save as "incident_site" writes incident_site.json, which File > Open's default filter shows.
TEST(PlanSafety, SavedMissionsGetTheirExtensionAndOpenShowsThem) {
    MainWindow w(nullptr, true);
    w.resize(1200, 800);
    w.show();
    w.newMission();
    QTemporaryDir dir;
    // Saving as "incident_site" (what Save as... passes on: askMissionSavePath returns the dialog's
    // choice through withMissionExtension, and so does every other way a mission is saved) writes
    // incident_site.json and the document takes that name.
    EXPECT_EQ(withMissionExtension(QStringLiteral("/x/incident_site")), QStringLiteral("/x/incident_site.json"));
    EXPECT_EQ(withMissionExtension(QStringLiteral("/x/site.JSON")), QStringLiteral("/x/site.JSON"));
    EXPECT_TRUE(w.saveMission(dir.filePath(QStringLiteral("incident_site"))));
    EXPECT_TRUE(QFileInfo::exists(dir.filePath(QStringLiteral("incident_site.json"))))
        << QDir(dir.path()).entryList().join(' ').toStdString();
    EXPECT_FALSE(QFileInfo::exists(dir.filePath(QStringLiteral("incident_site"))));
    EXPECT_EQ(w.document()->filePath(), QFileInfo(dir.filePath(QStringLiteral("incident_site.json"))).absoluteFilePath());
    EXPECT_TRUE(w.saveMission(dir.filePath(QStringLiteral("copy"))));
    EXPECT_TRUE(QFileInfo::exists(dir.filePath(QStringLiteral("copy.json"))));

    // File > Open: its dialog's default filter shows every mission file. The dialog is found by its
    // name among the visible windows, read, and cancelled; after 10 s whatever stands in the way is
    // closed, so the suite never hangs.
    QAction* open = nullptr;
    for (auto* a : w.findChildren<QAction*>())
        if (a->text().remove(QLatin1Char('&')).startsWith(QStringLiteral("Open mission")))
            open = a;
    ASSERT_NE(open, nullptr);
    QString filter;
    QStringList shown;
    int ticks = 0;
    QTimer timer;
    timer.setInterval(20);
    QObject::connect(&timer, &QTimer::timeout, [&] {
        for (QWidget* t : QApplication::topLevelWidgets()) {
            auto* d = qobject_cast<QFileDialog*>(t);
            if (!d || !d->isVisible() || d->objectName() != QStringLiteral("MissionOpenDialog"))
                continue;
            filter = d->selectedNameFilter();
            // "Photoflight missions (*.json)": the patterns in the brackets, as the dialog applies them.
            const QString patterns = filter.section(QLatin1Char('('), 1).section(QLatin1Char(')'), 0, 0);
            shown = QDir(dir.path()).entryList(patterns.split(QLatin1Char(' '), Qt::SkipEmptyParts), QDir::Files);
            timer.stop();
            d->reject();
            return;
        }
        if (++ticks > 500) {
            timer.stop();
            ADD_FAILURE() << "the open dialog did not appear within 10 s";
            if (auto* m = QApplication::activeModalWidget())
                m->close();
        }
    });
    timer.start();
    open->trigger();
    EXPECT_TRUE(shown.contains(QStringLiteral("incident_site.json"))) << filter.toStdString();
    EXPECT_TRUE(shown.contains(QStringLiteral("copy.json")));
}

// Item 5: every planner kind has a row with "Use"; using one is an undoable mission edit.
TEST(PlanSafety, TheComparisonListsEveryKindAndUseMakesItTheMissionsPlanner) {
    auto w = plannedDemo();
    auto* doc = w->document();
    auto* panel = w->statisticsPanel();
    auto* table = panel->comparison();
    EXPECT_EQ(table->rowCount(), int(mission::plannerKinds().size())); // rows come from the table of kinds
    EXPECT_EQ(table->horizontalHeaderItem(StatisticsPanel::CNoFly)->text(), QStringLiteral("No-fly"));
    w->planController()->compare();
    ASSERT_TRUE(w->planController()->waitForIdle(180000));
    for (const auto& row : w->planController()->comparison()) {
        ASSERT_TRUE(row.ok) << row.error.toStdString();
        // Only the yardstick flies over the zones (that is what it is for): its crossings are shown.
        if (row.planner == mission::PlannerKind::Lawnmower)
            EXPECT_GT(row.noFlyCrossings, 0);
        else
            EXPECT_EQ(row.noFlyCrossings, 0) << plannerName(row.planner).toStdString();
    }
    const auto inUse = doc->mission().options.planner; // the demo's: the automatic choice
    auto* current = panel->useButton(inUse);
    auto* raster = panel->useButton(mission::PlannerKind::Raster);
    ASSERT_TRUE(current && raster);
    ASSERT_NE(inUse, mission::PlannerKind::Raster);
    EXPECT_FALSE(current->isEnabled()); // the mission's planner
    EXPECT_EQ(current->text(), QStringLiteral("In use"));
    QTest::mouseClick(raster, Qt::LeftButton);
    EXPECT_EQ(doc->mission().options.planner, mission::PlannerKind::Raster);
    EXPECT_EQ(panel->useButton(mission::PlannerKind::Raster)->text(), QStringLiteral("In use"));
    EXPECT_TRUE(panel->useButton(inUse)->isEnabled());
    EXPECT_TRUE(w->planController()->isOutdated()); // the plan shown was made with the other planner
    EXPECT_FALSE(w->planController()->isComparisonOutdated()); // it compared raster too
    doc->undoStack()->undo();
    EXPECT_EQ(doc->mission().options.planner, inUse);
    EXPECT_FALSE(w->planController()->isOutdated());
}

// Item 6: keep-inside is one click away, and waypoints outside the area are explained.
TEST(PlanSafety, KeepInsideIsOneClickAwayAndOutsideWaypointsAreExplained) {
    auto w = plannedDemo();
    auto* doc = w->document();
    auto* act = w->findChild<QAction*>(QStringLiteral("KeepInsideAction"));
    ASSERT_NE(act, nullptr);
    EXPECT_FALSE(act->isChecked());
    int outside = 0;
    for (const auto& is : w->planLayer()->issues()) outside += is.check.outsideArea;
    bool explained = false;
    for (int i = 0; i < w->problemsList()->count(); ++i)
        explained |= w->problemsList()->item(i)->text().contains(QStringLiteral("turn on Keep inside area"));
    EXPECT_EQ(explained, outside > 0);
    act->trigger();
    EXPECT_TRUE(doc->mission().options.keepInsideArea);
    doc->undoStack()->undo();
    EXPECT_FALSE(doc->mission().options.keepInsideArea);
    EXPECT_FALSE(act->isChecked());
}

// Item 8: Ctrl+E reaches Export while a spin box of the Aircraft dock has the focus.
TEST(PlanSafety, CtrlEExportsWhileASpinBoxHasTheFocus) {
    auto w = test::makeWindow();
    w->aircraftPanel()->addCustom();
    auto* box = w->aircraftPanel()->altitudeBox();
    w->activateWindow();
    box->setFocus();
    QApplication::processEvents();
    w->statusBar()->clearMessage();
    QTest::keyClick(box, Qt::Key_E, Qt::ControlModifier);
    // Nothing planned yet: the export says so (a window without dialogs shows it in the status bar).
    EXPECT_TRUE(w->statusText().contains(QStringLiteral("Nothing to export yet"))) << w->statusText().toStdString();
}

// Item 9: after a new plan replaces the routes the waypoint selection does not jump to another
// waypoint; each kind of zone is numbered on its own; the greyed form of no aircraft is empty.
TEST(PlanSafety, SelectionNamesAndEmptyFormAfterNew) {
    auto w = plannedDemo();
    auto* doc = w->document();
    w->planLayer()->selectWaypoints(0, {5});
    ASSERT_EQ(w->planLayer()->selectedWaypoints(), QList<int>{5});
    setAltitude(doc, 0, 47.0);
    w->planNow();
    ASSERT_TRUE(w->planController()->waitForIdle(120000));
    EXPECT_EQ(w->planLayer()->selectedRoute(), -1);
    EXPECT_TRUE(w->planLayer()->selectedWaypoints().isEmpty());

    EXPECT_EQ(doc->nextNoFlyZoneName(QStringLiteral("Circle")), QStringLiteral("Circle 1"));
    mission::NoFlyZone z;
    z.name = "Circle 1";
    z.polygon = doc->mission().noFlyZones.at(0).polygon;
    doc->undoStack()->push(new AddNoFlyZoneCommand(doc, z));
    EXPECT_EQ(doc->nextNoFlyZoneName(QStringLiteral("Circle")), QStringLiteral("Circle 2"));
    EXPECT_EQ(doc->nextNoFlyZoneName(QStringLiteral("No-fly zone")), QStringLiteral("No-fly zone 1"));

    w->newMission();
    EXPECT_FALSE(w->aircraftPanel()->altitudeBox()->isEnabled());
    EXPECT_TRUE(w->aircraftPanel()->altitudeBox()->text().trimmed().isEmpty() ||
                w->aircraftPanel()->altitudeBox()->cleanText().isEmpty());
}
