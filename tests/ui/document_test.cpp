// The mission document: undo commands, dirty state and title, save and reopen, recovery from autosave.
#include "core/io/mission_file.h"
#include "ui/autosave.h"
#include "ui/commands/add_aircraft_command.h"
#include "ui/commands/add_no_fly_zone_command.h"
#include "ui/commands/insert_vertex_command.h"
#include "ui/commands/move_shape_command.h"
#include "ui/commands/move_vertex_command.h"
#include "ui/commands/remove_no_fly_zone_command.h"
#include "ui/commands/remove_vertex_command.h"
#include "ui/commands/set_area_command.h"
#include "ui/commands/set_home_command.h"
#include "ui/mission_document.h"
#include "ui_test_util.h"

#include <QFile>
#include <QSettings>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <random>

using namespace pf;
using namespace pf::ui;

namespace {

geo::GeoPolygon square(double lon, double lat, double d) {
    return geo::GeoPolygon{{{lon, lat}, {lon + d, lat}, {lon + d, lat + d}, {lon, lat + d}}, {}};
}

mission::Mission sampleMission() {
    mission::Mission m;
    m.name = "Sample";
    m.area = square(8.3275, 49.0110, 0.004);
    m.noFlyZones.push_back({"Shed", square(8.3290, 49.0118, 0.0005)});
    m.home = geo::LonLat{8.3270554, 49.010741};
    return m;
}

} // namespace

TEST(MissionDocument, EveryCommandUndoesExactly) {
    // Random sequences of edits, then undo all: the mission is back to the start; redo all: back to the end.
    std::mt19937 rng(1234);
    for (int round = 0; round < 20; ++round) {
        MissionDocument doc;
        doc.reset(sampleMission(), QString());
        const mission::Mission start = doc.mission();
        auto* stack = doc.undoStack();
        std::uniform_int_distribution<int> pick(0, 6);
        std::uniform_real_distribution<double> jitter(-0.0005, 0.0005);
        for (int step = 0; step < 12; ++step) {
            const auto& m = doc.mission();
            switch (pick(rng)) {
            case 0:
                stack->push(new MoveVertexCommand(&doc, ShapeRef::area(), {0, int(rng() % m.area.outer.size())},
                                                  {8.33 + jitter(rng), 49.012 + jitter(rng)}));
                break;
            case 1:
                stack->push(new InsertVertexCommand(&doc, ShapeRef::area(), {0, int(rng() % m.area.outer.size())},
                                                    {8.33 + jitter(rng), 49.012 + jitter(rng)}));
                break;
            case 2:
                if (m.area.outer.size() > 3)
                    stack->push(new RemoveVertexCommand(&doc, ShapeRef::area(), {0, int(rng() % m.area.outer.size())}));
                break;
            case 3:
                stack->push(new AddNoFlyZoneCommand(&doc, {"Z", square(8.33 + jitter(rng), 49.012, 0.0002)}));
                break;
            case 4:
                if (!m.noFlyZones.empty())
                    stack->push(new RemoveNoFlyZoneCommand(&doc, int(rng() % m.noFlyZones.size())));
                break;
            case 5:
                stack->push(new SetHomeCommand(&doc, geo::LonLat{8.327 + jitter(rng), 49.0107}));
                break;
            case 6:
                if (!m.noFlyZones.empty())
                    stack->push(new MoveShapeCommand(&doc, ShapeRef::noFly(0), QPointF(jitter(rng) * 1e5, 0)));
                break;
            }
        }
        const mission::Mission end = doc.mission();
        while (stack->canUndo()) stack->undo();
        EXPECT_EQ(doc.mission(), start) << "round " << round;
        EXPECT_FALSE(doc.isDirty());
        while (stack->canRedo()) stack->redo();
        EXPECT_EQ(doc.mission(), end) << "round " << round;
    }
}

TEST(MissionDocument, SaveAndReopenRoundTripsAndClearsDirty) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    auto w = test::makeWindow();
    auto* doc = w->document();
    doc->reset(sampleMission(), QString());
    doc->undoStack()->push(new SetHomeCommand(doc, geo::LonLat{8.3271, 49.0106}));
    EXPECT_TRUE(doc->isDirty());
    EXPECT_EQ(w->windowTitle(), QStringLiteral("Sample[*] — Photoflight"));
    EXPECT_TRUE(w->isWindowModified());

    const QString path = dir.filePath(QStringLiteral("saved.json"));
    QString error;
    ASSERT_TRUE(w->saveMission(path, &error)) << error.toStdString();
    EXPECT_FALSE(doc->isDirty());
    EXPECT_FALSE(w->isWindowModified());
    EXPECT_EQ(doc->filePath(), QFileInfo(path).absoluteFilePath());
    const mission::Mission saved = doc->mission();

    // Reopen in a fresh window: the same mission, clean, with the file in the recent list.
    auto w2 = test::makeWindow();
    ASSERT_TRUE(w2->openMission(path, &error)) << error.toStdString();
    EXPECT_EQ(w2->document()->mission(), saved);
    EXPECT_FALSE(w2->document()->isDirty());
    EXPECT_EQ(QSettings().value(QStringLiteral("recentFiles")).toStringList().value(0), QFileInfo(path).absoluteFilePath());

    // Undoing after a save makes the document dirty again (it differs from the file).
    doc->undoStack()->undo();
    EXPECT_TRUE(doc->isDirty());
}

TEST(MissionDocument, OpeningABadFileKeepsTheDocumentAndSaysWhy) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("broken.json"));
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write("{ \"version\": 1, \"area\": ");
    f.close();
    MissionDocument doc;
    doc.reset(sampleMission(), QString());
    QString error;
    EXPECT_FALSE(doc.load(path, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("broken.json"))) << error.toStdString();
    EXPECT_EQ(doc.mission(), sampleMission());

    EXPECT_FALSE(doc.load(dir.filePath(QStringLiteral("missing.json")), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("missing.json"))) << error.toStdString();
}

TEST(MissionDocument, SavingIntoAMissingDirectoryFailsWithTheReason) {
    MissionDocument doc;
    doc.reset(sampleMission(), QString());
    doc.undoStack()->push(new SetHomeCommand(&doc, std::nullopt));
    QString error;
    EXPECT_FALSE(doc.save(QStringLiteral("/nonexistent-dir/x/mission.json"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("/nonexistent-dir/x/mission.json"))) << error.toStdString();
    EXPECT_TRUE(doc.isDirty());
}

TEST(Autosave, WritesAfterEditsAndRecoversLeftovers) {
    QTemporaryDir dir;
    MissionDocument doc;
    doc.reset(sampleMission(), QStringLiteral("/somewhere/sample.json"));
    Autosave autosave(&doc, dir.path(), 60000, 10);
    doc.undoStack()->push(new SetHomeCommand(&doc, geo::LonLat{8.3272, 49.0105}));
    // The debounce timer writes shortly after the edit.
    ASSERT_TRUE(QTest::qWaitFor([&] { return QFile::exists(autosave.filePath()); }, 3000));
    auto copy = io::readMissionFile(autosave.filePath().toStdString());
    ASSERT_TRUE(copy.ok()) << copy.error().message;
    EXPECT_EQ(*copy, doc.mission());
    EXPECT_TRUE(autosave.leftovers().isEmpty()); // its own file is not a leftover

    // Simulate a crashed session: its copy stays behind under another process id.
    const QString crashed = dir.filePath(QStringLiteral("mission-999999.json"));
    ASSERT_TRUE(QFile::copy(autosave.filePath(), crashed));
    ASSERT_TRUE(QFile::copy(autosave.filePath() + QStringLiteral(".origin"), crashed + QStringLiteral(".origin")));
    const mission::Mission crashedMission = doc.mission();

    MissionDocument other;
    Autosave second(&other, dir.path());
    const auto leftovers = second.leftovers();
    ASSERT_GE(leftovers.size(), 1);
    auto it = std::find_if(leftovers.begin(), leftovers.end(), [&](const Autosave::Recovery& r) {
        return r.autosavePath == QFileInfo(crashed).absoluteFilePath();
    });
    ASSERT_NE(it, leftovers.end());
    EXPECT_EQ(it->originalPath, QStringLiteral("/somewhere/sample.json"));
    QString error;
    ASSERT_TRUE(second.recover(*it, &error)) << error.toStdString();
    EXPECT_EQ(other.mission(), crashedMission);
    EXPECT_TRUE(other.isDirty()); // recovered changes are not on disk yet
    EXPECT_EQ(other.filePath(), QStringLiteral("/somewhere/sample.json"));
    EXPECT_FALSE(QFile::exists(crashed));

    // Saving removes this session's copy: nothing to recover after a clean save.
    doc.save(dir.filePath(QStringLiteral("saved.json")), &error);
    EXPECT_FALSE(QFile::exists(autosave.filePath()));
}

TEST(Startup, FirstStartOpensTheDemoThenTheMostRecentFile) {
    QSettings settings;
    settings.remove(QStringLiteral("startedBefore"));
    settings.remove(QStringLiteral("recentFiles"));
    {
        auto w = test::makeWindow();
        w->startup(QString());
        EXPECT_EQ(w->document()->mission().name, "Rheinhafen training ground");
        EXPECT_GE(w->document()->mission().noFlyZones.size(), 2u);
    }
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("last.json"));
    {
        auto w = test::makeWindow();
        w->document()->reset(sampleMission(), QString());
        ASSERT_TRUE(w->saveMission(path));
    }
    auto w = test::makeWindow();
    w->startup(QString());
    EXPECT_EQ(w->document()->mission(), sampleMission());
    EXPECT_EQ(w->document()->filePath(), QFileInfo(path).absoluteFilePath());
    // A path on the command line wins.
    auto w2 = test::makeWindow();
    w2->startup(QStringLiteral(PF_RESOURCES_DIR "/demo/demo_mission.json"));
    EXPECT_EQ(w2->document()->mission().name, "Rheinhafen training ground");
}
