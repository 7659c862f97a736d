// No data loss: an edit autosaved by the application survives SIGKILL, and the next start of the real
// photoflight offers it back. Everything runs in a temporary HOME / XDG tree, never the user's files.
//
// 1. An editor process (this test binary in its editor role, see KillRecoveryEditor) opens a copy of
//    the demo mission in a MissionDocument with the application's Autosave, moves a vertex of the
//    area through the undo stack, waits for the autosave and is killed with SIGKILL.
// 2. The real photoflight starts in the same HOME: it must offer the autosaved mission. Under Xvfb the
//    test sees the "Recover mission" question on screen and, with xdotool, answers it with Return;
//    the application then holds the recovered mission and autosaves it under its own process id.
//    It is SIGKILLed as well. (Without Xvfb the application runs offscreen and the test checks that it
//    waits for the answer without touching the autosaved copy.)
// 3. The autosave left behind is recovered into a document: it holds the edit and is marked modified.
#include "ui/autosave.h"
#include "ui/commands/move_vertex_command.h"
#include "ui/mission_document.h"

#include "core/io/mission_file.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <functional>
#include <sys/types.h>

using namespace pf;
using namespace pf::ui;

namespace {

// Where the edit moves the area's first vertex (the demo site's south-west corner, moved ~30 m).
constexpr double kEditedLon = 8.3268;
constexpr double kEditedLat = 49.0107;

bool hasTheEdit(const mission::Mission& m) {
    return !m.area.outer.empty() && std::abs(m.area.outer[0].lon - kEditedLon) < 1e-9 &&
           std::abs(m.area.outer[0].lat - kEditedLat) < 1e-9;
}

QString demoMission() { return QStringLiteral(PF_RESOURCES_DIR "/demo/demo_mission.json"); }

// A private HOME and XDG tree; photoflight's AppDataLocation inside it is data/Photoflight/Photoflight.
struct Sandbox {
    QTemporaryDir root;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    QString mission;     // the copy the user "works on"
    QString autosaveDir; // photoflight's autosave folder in this sandbox

    Sandbox() {
        const QString r = root.path();
        for (const char* d : {"home", "data", "config", "cache", "runtime"}) QDir(r).mkpath(QString::fromLatin1(d));
        QFile::setPermissions(r + QStringLiteral("/runtime"), QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
        env.insert(QStringLiteral("HOME"), r + QStringLiteral("/home"));
        env.insert(QStringLiteral("XDG_DATA_HOME"), r + QStringLiteral("/data"));
        env.insert(QStringLiteral("XDG_CONFIG_HOME"), r + QStringLiteral("/config"));
        env.insert(QStringLiteral("XDG_CACHE_HOME"), r + QStringLiteral("/cache"));
        env.insert(QStringLiteral("XDG_RUNTIME_DIR"), r + QStringLiteral("/runtime"));
        mission = r + QStringLiteral("/home/site.json");
        QFile::copy(demoMission(), mission);
        QFile::setPermissions(mission, QFileDevice::ReadOwner | QFileDevice::WriteOwner);
        autosaveDir = r + QStringLiteral("/data/Photoflight/Photoflight/autosave");
    }
};

void sigkill(QProcess& p) {
    if (p.state() == QProcess::NotRunning) return;
    ::kill(static_cast<pid_t>(p.processId()), SIGKILL);
    p.waitForFinished(10000);
}

QStringList autosaves(const QString& dir) {
    return QDir(dir).entryList({QStringLiteral("mission-*.json")}, QDir::Files, QDir::Name);
}

bool waitFor(const std::function<bool()>& done, int timeoutMs) {
    return QTest::qWaitFor(done, timeoutMs);
}

// A window whose title contains `title` on the X display, as listed by xwininfo.
bool windowShown(const QString& display, const QString& title) {
    QProcess xwininfo;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("DISPLAY"), display);
    xwininfo.setProcessEnvironment(env);
    xwininfo.start(QStringLiteral("xwininfo"), {QStringLiteral("-root"), QStringLiteral("-tree")});
    if (!xwininfo.waitForFinished(5000)) return false;
    return QString::fromLocal8Bit(xwininfo.readAllStandardOutput()).contains(title);
}

} // namespace

// The editor role of step 1; skipped unless the kill test starts this binary in that role.
TEST(KillRecoveryEditor, EditsAndWaitsToBeKilled) {
    const QString mission = qEnvironmentVariable("PF_KILL_RECOVERY_MISSION");
    const QString dir = qEnvironmentVariable("PF_KILL_RECOVERY_AUTOSAVE_DIR");
    if (mission.isEmpty() || dir.isEmpty()) GTEST_SKIP() << "only run as the editor of KillRecovery.*";
    MissionDocument doc;
    QString error;
    ASSERT_TRUE(doc.load(mission, &error)) << error.toStdString();
    Autosave autosave(&doc, dir, /*periodMs=*/60000, /*debounceMs=*/200);
    doc.undoStack()->push(new MoveVertexCommand(&doc, ShapeRef::area(), VertexRef{0, 0}, geo::LonLat{kEditedLon, kEditedLat}));
    ASSERT_TRUE(doc.isDirty());
    ASSERT_TRUE(waitFor([&] { return QFile::exists(autosave.filePath()); }, 20000));
    std::printf("AUTOSAVED %s\n", qPrintable(autosave.filePath()));
    std::fflush(stdout);
    QTest::qWait(120000); // killed long before
}

TEST(KillRecovery, NextStartOffersTheAutosavedMissionWithTheLastEdit) {
    Sandbox box;
    ASSERT_TRUE(box.root.isValid());
    ASSERT_TRUE(QFileInfo::exists(box.mission));

    // --- 1. edit, autosave, SIGKILL ---
    QProcess editor;
    QProcessEnvironment env = box.env;
    env.insert(QStringLiteral("PF_KILL_RECOVERY_MISSION"), box.mission);
    env.insert(QStringLiteral("PF_KILL_RECOVERY_AUTOSAVE_DIR"), box.autosaveDir);
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    editor.setProcessEnvironment(env);
    editor.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    editor.start(QCoreApplication::applicationFilePath(),
                 {QStringLiteral("--gtest_filter=KillRecoveryEditor.EditsAndWaitsToBeKilled")});
    ASSERT_TRUE(editor.waitForStarted(10000));
    QString line;
    ASSERT_TRUE(waitFor([&] {
        line += QString::fromLocal8Bit(editor.readAllStandardOutput());
        return line.contains(QStringLiteral("AUTOSAVED ")) && line.contains(QLatin1Char('\n'));
    }, 60000)) << "the editor never reported its autosave; output: " << line.toStdString();
    sigkill(editor);
    EXPECT_EQ(editor.exitStatus(), QProcess::CrashExit);

    const QStringList left = autosaves(box.autosaveDir);
    ASSERT_EQ(left.size(), 1) << "autosave folder: " << left.join(QStringLiteral(", ")).toStdString();
    const QString leftover = box.autosaveDir + QLatin1Char('/') + left.first();
    {
        auto saved = io::readMissionFile(leftover.toStdString());
        ASSERT_TRUE(saved) << saved.error().message;
        EXPECT_TRUE(hasTheEdit(saved.value())) << "the autosave lacks the last edit";
        QFile origin(leftover + QStringLiteral(".origin"));
        ASSERT_TRUE(origin.open(QIODevice::ReadOnly));
        EXPECT_EQ(QString::fromUtf8(origin.readAll()).trimmed(), QFileInfo(box.mission).absoluteFilePath());
        // The edit was never saved: the file on disk is still the demo mission.
        auto onDisk = io::readMissionFile(box.mission.toStdString());
        ASSERT_TRUE(onDisk);
        EXPECT_FALSE(hasTheEdit(onDisk.value()));
    }

    // --- 2. the real photoflight starts again ---
    QProcess app;
    QProcessEnvironment appEnv = box.env;
    QProcess xvfb;
    QString display;
    const bool haveX = !QStandardPaths::findExecutable(QStringLiteral("Xvfb")).isEmpty() &&
                       !QStandardPaths::findExecutable(QStringLiteral("xwininfo")).isEmpty();
    if (haveX) {
        display = QStringLiteral(":%1").arg(90 + QCoreApplication::applicationPid() % 400);
        xvfb.start(QStringLiteral("Xvfb"), {display, QStringLiteral("-screen"), QStringLiteral("0"),
                                            QStringLiteral("1280x1024x24"), QStringLiteral("-nolisten"), QStringLiteral("tcp")});
        if (!xvfb.waitForStarted(5000) || !waitFor([&] { return windowShown(display, QStringLiteral("root window")); }, 10000)) {
            sigkill(xvfb);
            display.clear();
        }
    }
    if (!display.isEmpty()) {
        appEnv.insert(QStringLiteral("DISPLAY"), display);
        appEnv.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("xcb"));
    } else {
        appEnv.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    }
    app.setProcessEnvironment(appEnv);
    app.setProcessChannelMode(QProcess::ForwardedChannels);
    app.start(QStringLiteral(PF_PHOTOFLIGHT_PATH), {QStringLiteral("--map"), QStringLiteral("none")});
    ASSERT_TRUE(app.waitForStarted(10000));

    if (!display.isEmpty()) {
        EXPECT_TRUE(waitFor([&] { return windowShown(display, QStringLiteral("Recover mission")); }, 60000))
            << "photoflight did not offer to recover the autosaved mission";
        if (!QStandardPaths::findExecutable(QStringLiteral("xdotool")).isEmpty()) {
            // Return answers the question with its default button, Yes. (Xvfb has no window manager, so
            // the dialog gets the keyboard focus directly rather than being activated.)
            QProcess xdotool;
            QProcessEnvironment xenv = QProcessEnvironment::systemEnvironment();
            xenv.insert(QStringLiteral("DISPLAY"), display);
            xdotool.setProcessEnvironment(xenv);
            xdotool.start(QStringLiteral("xdotool"),
                          {QStringLiteral("search"), QStringLiteral("--onlyvisible"), QStringLiteral("--name"),
                           QStringLiteral("Recover mission"), QStringLiteral("windowfocus"), QStringLiteral("sleep"),
                           QStringLiteral("0.5"), QStringLiteral("key"), QStringLiteral("Return")});
            xdotool.waitForFinished(10000);
            // Recovered: the leftover is gone and the application autosaves the recovered mission
            // under its own process id.
            const QString own = box.autosaveDir + QStringLiteral("/mission-%1.json").arg(app.processId());
            // The copy is written first, then its .origin (the file it belongs to): wait for both.
            EXPECT_TRUE(waitFor([&] {
                return QFile::exists(own) && QFile::exists(own + QStringLiteral(".origin")) && !QFile::exists(leftover);
            }, 30000))
                << "photoflight did not recover the autosave; folder: "
                << autosaves(box.autosaveDir).join(QStringLiteral(", ")).toStdString();
            auto recovered = io::readMissionFile(own.toStdString());
            ASSERT_TRUE(recovered) << recovered.error().message;
            EXPECT_TRUE(hasTheEdit(recovered.value()));
        }
    } else {
        // Offscreen the question cannot be seen: the application must wait for it and keep the copy.
        QTest::qWait(5000);
        EXPECT_EQ(app.state(), QProcess::Running);
        EXPECT_TRUE(QFile::exists(leftover));
    }
    sigkill(app); // killed during the session as well: nothing may be lost
    sigkill(xvfb);

    // --- 3. what is left is recovered with the edit ---
    const QStringList after = autosaves(box.autosaveDir);
    ASSERT_EQ(after.size(), 1) << after.join(QStringLiteral(", ")).toStdString();
    MissionDocument doc;
    Autosave next(&doc, box.autosaveDir);
    const auto offers = next.leftovers();
    ASSERT_EQ(offers.size(), 1);
    EXPECT_EQ(offers.first().originalPath, QFileInfo(box.mission).absoluteFilePath());
    QString error;
    ASSERT_TRUE(next.recover(offers.first(), &error)) << error.toStdString();
    EXPECT_TRUE(hasTheEdit(doc.mission()));
    EXPECT_TRUE(doc.isDirty()) << "a recovered mission differs from the file on disk";
    EXPECT_EQ(doc.filePath(), QFileInfo(box.mission).absoluteFilePath());
    next.removeOwn();
}
