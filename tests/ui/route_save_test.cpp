// Hand-edited routes survive save, reopen and crash recovery, and a new plan never silently replaces
// the routes a file brought back.
#include "core/io/mission_file.h"
#include "ui/autosave.h"
#include "ui/commands/edit_waypoint_command.h"
#include "ui/mission_document.h"
#include "ui/planning/plan_controller.h"
#include "ui_test_util.h"

#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <random>

using namespace pf;
using namespace pf::ui;

namespace {

QByteArray readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

mission::Mission sampleMission() {
    mission::Mission m;
    m.name = "Routes";
    m.area = geo::GeoPolygon{{{8.3275, 49.0110}, {8.3315, 49.0110}, {8.3315, 49.0150}, {8.3275, 49.0150}}, {}};
    m.home = geo::LonLat{8.3270554, 49.010741};
    // Only what version 1 of the file holds (the automatic planner choice came with version 3), so the
    // version written tells whether edited routes went in.
    m.options.planner = mission::PlannerKind::Stride;
    return m;
}

// Two "planned" routes of random waypoints (full-precision doubles), as a plan would set them.
std::vector<route::Route> randomRoutes(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> dLon(8.3275, 8.3315), dLat(49.0110, 49.0150), alt(20.0, 120.0),
        heading(0.0, 360.0);
    std::vector<route::Route> routes;
    for (const char* name : {"Falcon 8", "Matrice \"300\""}) {
        route::Route r;
        r.aircraft = name;
        r.home = geo::LonLat{8.3270554, 49.010741};
        r.cruiseSpeedMps = 5.0 + double(rng() % 1000) / 100.0;
        const int n = 8 + int(rng() % 30);
        for (int i = 0; i < n; ++i)
            r.waypoints.push_back({{dLon(rng), dLat(rng)}, alt(rng), heading(rng), route::WaypointKind(rng() % 3)});
        routes.push_back(r);
    }
    return routes;
}

// Changes every field of one waypoint through the command the waypoint table uses.
route::Waypoint editOne(MissionDocument& doc, int route, int waypoint) {
    route::Waypoint w = doc.routes().at(std::size_t(route)).route.waypoints.at(std::size_t(waypoint));
    w.position.lon += 1.234567891e-5;
    w.position.lat -= 9.87654321e-6;
    w.altitudeM += 3.3;
    w.headingDeg = std::fmod(w.headingDeg + 123.456, 360.0);
    w.kind = w.kind == route::WaypointKind::Turn ? route::WaypointKind::Photo : route::WaypointKind::Turn;
    doc.undoStack()->push(new EditWaypointCommand(&doc, route, waypoint, w));
    return w;
}

} // namespace

TEST(RouteSave, EditedRoutesSurviveSaveAndReopenExactly) {
    std::mt19937_64 rng(2026);
    for (int round = 0; round < 10; ++round) {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("m.json"));
        MissionDocument doc;
        doc.reset(sampleMission(), QString());
        doc.setPlannedRoutes(randomRoutes(rng));
        const int r = int(rng() % 2);
        const int k = int(rng() % doc.routes()[std::size_t(r)].route.waypoints.size());
        const route::Waypoint edited = editOne(doc, r, k);
        ASSERT_TRUE(doc.routes()[std::size_t(r)].edited);
        ASSERT_FALSE(doc.routes()[std::size_t(1 - r)].edited);
        ASSERT_TRUE(doc.isDirty());
        const route::Route saved = doc.routes()[std::size_t(r)].route;

        QString error;
        ASSERT_TRUE(doc.save(path, &error)) << error.toStdString();
        EXPECT_FALSE(doc.isDirty());

        // The file holds the edited route only (the other one is recomputed by the next plan).
        auto file = io::readMissionFile(path.toStdString());
        ASSERT_TRUE(file) << file.error().message;
        ASSERT_EQ(file->editedRoutes.size(), 1u);
        EXPECT_TRUE(mission::sameRoute(file->editedRoutes[0], saved));

        MissionDocument fresh;
        ASSERT_TRUE(fresh.load(path, &error)) << error.toStdString();
        ASSERT_EQ(fresh.routes().size(), 1u);
        EXPECT_TRUE(fresh.routes()[0].edited);
        EXPECT_TRUE(mission::sameRoute(fresh.routes()[0].route, saved));
        EXPECT_EQ(fresh.routes()[0].route.waypoints.at(std::size_t(k)), edited);
        EXPECT_TRUE(fresh.anyRouteEdited());
        EXPECT_FALSE(fresh.isDirty());
        // Planning never sees them: mission() is the definition alone.
        EXPECT_TRUE(fresh.mission().editedRoutes.empty());
        EXPECT_EQ(fresh.mission(), sampleMission());

        // Saving the reopened document writes the same bytes: nothing drifts or drops over saves.
        const QString again = dir.filePath(QStringLiteral("again.json"));
        ASSERT_TRUE(fresh.save(again, &error)) << error.toStdString();
        EXPECT_EQ(readAll(again), readAll(path));
    }
}

TEST(RouteSave, UndoingTheLastEditSavesAVersionOneFile) {
    std::mt19937_64 rng(5);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("m.json"));
    MissionDocument doc;
    doc.reset(sampleMission(), QString());
    doc.setPlannedRoutes(randomRoutes(rng));
    editOne(doc, 0, 1);
    doc.undoStack()->undo();
    EXPECT_FALSE(doc.anyRouteEdited());
    QString error;
    ASSERT_TRUE(doc.save(path, &error)) << error.toStdString();
    const QByteArray text = readAll(path);
    EXPECT_TRUE(text.contains("\"version\":1,")) << text.left(80).toStdString();
    EXPECT_FALSE(text.contains("\"routes\""));
}

TEST(RouteSave, ARouteThatCouldNotBeReadBackIsNotSaved) {
    std::mt19937_64 rng(8);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("m.json"));
    MissionDocument doc;
    doc.reset(sampleMission(), QString());
    doc.setPlannedRoutes(randomRoutes(rng));
    editOne(doc, 1, 0);
    QString error;
    ASSERT_TRUE(doc.save(path, &error)) << error.toStdString();
    const QByteArray good = readAll(path);

    route::Waypoint w = doc.routes()[1].route.waypoints[2];
    w.altitudeM = std::nan("");
    doc.undoStack()->push(new EditWaypointCommand(&doc, 1, 2, w));
    EXPECT_FALSE(doc.save(path, &error));
    EXPECT_EQ(error.toStdString(), path.toStdString() +
                                       ": not saved: routes[0] (\"Matrice \"300\"\"): waypoint 3: the altitude is "
                                       "not a finite number");
    EXPECT_TRUE(doc.isDirty());
    EXPECT_EQ(readAll(path), good); // the last good save is untouched
}

TEST(RouteSave, AutosaveAfterARouteEditCarriesItIntoRecovery) {
    std::mt19937_64 rng(77);
    QTemporaryDir dir;
    MissionDocument doc;
    doc.reset(sampleMission(), QStringLiteral("/somewhere/routes.json"));
    doc.setPlannedRoutes(randomRoutes(rng));
    // A long period: only the edit itself can trigger the copy.
    Autosave autosave(&doc, dir.path(), 600000, 10);
    editOne(doc, 0, 3);
    const route::Route edited = doc.routes()[0].route;
    ASSERT_TRUE(QTest::qWaitFor([&] { return QFile::exists(autosave.filePath()); }, 3000));
    auto copy = io::readMissionFile(autosave.filePath().toStdString());
    ASSERT_TRUE(copy) << copy.error().message;
    ASSERT_EQ(copy->editedRoutes.size(), 1u);
    EXPECT_TRUE(mission::sameRoute(copy->editedRoutes[0], edited));

    // The session dies: its copy stays behind under another process id.
    const QString crashed = dir.filePath(QStringLiteral("mission-999998.json"));
    ASSERT_TRUE(QFile::copy(autosave.filePath(), crashed));
    ASSERT_TRUE(QFile::copy(autosave.filePath() + QStringLiteral(".origin"), crashed + QStringLiteral(".origin")));

    MissionDocument other;
    Autosave second(&other, dir.path(), 600000, 10);
    const auto leftovers = second.leftovers();
    auto it = std::find_if(leftovers.begin(), leftovers.end(), [&](const Autosave::Recovery& r) {
        return r.autosavePath == QFileInfo(crashed).absoluteFilePath();
    });
    ASSERT_NE(it, leftovers.end());
    QString error;
    ASSERT_TRUE(second.recover(*it, &error)) << error.toStdString();
    ASSERT_EQ(other.routes().size(), 1u);
    EXPECT_TRUE(other.routes()[0].edited);
    EXPECT_TRUE(mission::sameRoute(other.routes()[0].route, edited));
    EXPECT_TRUE(other.isDirty());
    EXPECT_EQ(other.filePath(), QStringLiteral("/somewhere/routes.json"));
    // The recovered session's own copy carries the route on.
    auto own = io::readMissionFile(second.filePath().toStdString());
    ASSERT_TRUE(own) << own.error().message;
    ASSERT_EQ(own->editedRoutes.size(), 1u);
    EXPECT_TRUE(mission::sameRoute(own->editedRoutes[0], edited));
    second.removeOwn();
}

TEST(RouteSave, ANewPlanWaitsForConsentAfterOpeningEditedRoutes) {
    // Plan the demo, edit a waypoint, save; open the file in a new window: the plan that follows the
    // opening is held back behind the notice, and the edited route stays on the map until replaced.
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("demo-edited.json"));
    route::Route saved;
    {
        auto w = test::makeWindow();
        w->planController()->setAutoPlan(false);
        QString error;
        ASSERT_TRUE(w->openDemoMission(&error)) << error.toStdString();
        w->planNow();
        ASSERT_TRUE(w->planController()->waitForIdle(120000));
        auto* doc = w->document();
        ASSERT_FALSE(doc->routes().empty());
        editOne(*doc, 0, int(doc->routes()[0].route.waypoints.size() / 2));
        saved = doc->routes()[0].route;
        ASSERT_TRUE(w->saveMission(path, &error)) << error.toStdString();
    }
    auto w = test::makeWindow();
    w->planController()->setAutoPlan(true);
    QString error;
    ASSERT_TRUE(w->openMission(path, &error)) << error.toStdString();
    auto* doc = w->document();
    ASSERT_EQ(doc->routes().size(), 1u);
    EXPECT_TRUE(doc->routes()[0].edited);
    EXPECT_TRUE(mission::sameRoute(doc->routes()[0].route, saved));
    // The automatic plan after opening finishes but does not replace the edited route.
    ASSERT_TRUE(QTest::qWaitFor([&] { return w->planNoticeVisible(); }, 120000));
    ASSERT_TRUE(w->planController()->waitForIdle(120000));
    ASSERT_EQ(doc->routes().size(), 1u);
    EXPECT_TRUE(mission::sameRoute(doc->routes()[0].route, saved));
    EXPECT_FALSE(doc->isDirty());
    // With consent the fresh plan replaces it.
    w->replaceEditedPaths();
    EXPECT_FALSE(w->planNoticeVisible());
    EXPECT_FALSE(doc->anyRouteEdited());
    EXPECT_EQ(doc->routes().size(), doc->mission().aircraft.size());
}
