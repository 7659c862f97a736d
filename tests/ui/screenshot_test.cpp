// What the map shows: the mission's styles in a rendered window (set PF_SCREENSHOT_DIR to keep the PNGs).
#include "ui/commands/add_no_fly_zone_command.h"
#include "ui/commands/set_area_command.h"
#include "ui/commands/set_home_command.h"
#include "ui/map/mission_layer.h"
#include "ui/mission_document.h"
#include "ui_test_util.h"

#include <QDir>
#include <QProcess>
#include <QTemporaryDir>
#include <QUndoStack>

#include <gtest/gtest.h>

using namespace pf;
using namespace pf::ui;

namespace {

void keep(const QImage& img, const QString& name) {
    const QString dir = qEnvironmentVariable("PF_SCREENSHOT_DIR");
    if (!dir.isEmpty()) img.save(QDir(dir).filePath(name));
}

// Pixels within `tol` of `colour` in each channel.
int countNear(const QImage& img, const QColor& colour, int tol) {
    int n = 0;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const QColor c = img.pixelColor(x, y);
            if (std::abs(c.red() - colour.red()) <= tol && std::abs(c.green() - colour.green()) <= tol &&
                std::abs(c.blue() - colour.blue()) <= tol)
                ++n;
        }
    return n;
}

} // namespace

TEST(Screenshot, MissionStylesAreVisibleOnTheMap) {
    auto w = test::makeWindow();
    w->setBaseMap(QStringLiteral("none")); // only the mission's own colours on a plain background
    auto* doc = w->document();
    const geo::GeoPolygon area{{{8.3275, 49.0110}, {8.3320, 49.0110}, {8.3320, 49.0132}, {8.3275, 49.0132}}, {}};
    const geo::GeoPolygon zone{{{8.3290, 49.0118}, {8.3298, 49.0118}, {8.3298, 49.0122}, {8.3290, 49.0122}}, {}};
    doc->undoStack()->push(new SetAreaCommand(doc, area, QStringLiteral("area")));
    const QImage plainArea = w->mapView()->viewport()->grab().toImage();
    doc->undoStack()->push(new AddNoFlyZoneCommand(doc, {"Warehouse", zone}));
    doc->undoStack()->push(new SetHomeCommand(doc, geo::LonLat{8.3270554, 49.010741}));
    const QImage withZone = w->mapView()->viewport()->grab().toImage();
    keep(withZone, QStringLiteral("styles_valid.png"));

    const QColor areaStroke(0, 110, 230), zoneStroke(210, 30, 35), warning(245, 130, 0), homeGreen(20, 120, 60);
    EXPECT_GT(countNear(plainArea, areaStroke, 12), 500);   // the area's outline
    EXPECT_LT(countNear(plainArea, zoneStroke, 12), 10);    // no red before the zone exists
    EXPECT_GT(countNear(withZone, zoneStroke, 12), 200);    // the zone's outline and hatching
    EXPECT_GT(countNear(withZone, homeGreen, 12), 20);      // the home marker
    EXPECT_LT(countNear(withZone, warning, 12), 10);        // nothing invalid yet

    // A self-intersecting area switches to the warning style.
    const geo::GeoPolygon bowTie{{{8.3275, 49.0110}, {8.3320, 49.0110}, {8.3275, 49.0132}, {8.3320, 49.0132}}, {}};
    doc->undoStack()->push(new SetAreaCommand(doc, bowTie, QStringLiteral("bow tie")));
    const QImage invalid = w->mapView()->viewport()->grab().toImage();
    keep(invalid, QStringLiteral("styles_invalid.png"));
    EXPECT_GT(countNear(invalid, warning, 12), 300);
    EXPECT_LT(countNear(invalid, areaStroke, 12), 50);
}

TEST(Screenshot, DemoMissionWindowAtReadmeSize) {
    auto w = test::makeWindow();
    w->resize(1600, 1000);
    QString error;
    ASSERT_TRUE(w->openDemoMission(&error)) << error.toStdString();
    EXPECT_FALSE(w->document()->isDirty());
    EXPECT_TRUE(w->document()->filePath().isEmpty()); // saving the demo asks for a new place
    ASSERT_GE(w->document()->mission().noFlyZones.size(), 2u);
    ASSERT_TRUE(w->waitForMap(20000));
    const QImage shot = w->grab().toImage();
    keep(shot, QStringLiteral("demo_window.png"));
    EXPECT_EQ(shot.size(), QSize(1600, 1000));
    // Every no-fly zone of the demo is on screen.
    const QRectF visible = w->mapView()->mapToScene(w->mapView()->viewport()->rect()).boundingRect();
    for (const auto& z : w->document()->mission().noFlyZones)
        for (const auto& p : z.polygon.outer) EXPECT_TRUE(visible.contains(toScene(p)));
}

TEST(Screenshot, SelectedShapeShowsItsVertexHandles) {
    auto w = test::makeWindow();
    QString error;
    ASSERT_TRUE(w->openDemoMission(&error)) << error.toStdString();
    ASSERT_TRUE(w->waitForMap(20000));
    const QImage before = w->mapView()->viewport()->grab().toImage();
    w->setTool(ToolId::Select);
    const auto& ring = w->document()->mission().area.outer;
    test::click(w->mapView(), ring[0]);
    ASSERT_TRUE(w->missionLayer()->selectedVertex().has_value());
    const QImage after = w->mapView()->viewport()->grab().toImage();
    keep(after, QStringLiteral("editing.png"));
    // The selected vertex is drawn as a filled handle in the area's colour over the map: look just
    // south-west of the south-west corner, off the outline, where the map showed before.
    const QPoint v = test::viewPos(w->mapView(), ring[0]) + QPoint(-3, 3);
    const QColor c = after.pixelColor(v);
    EXPECT_NEAR(c.red(), 0, 30);
    EXPECT_NEAR(c.green(), 110, 30);
    EXPECT_NEAR(c.blue(), 230, 30);
    EXPECT_NE(before.pixelColor(v), c);
}

// `photoflight --screenshot FILE --dialog export|help` (the user guide's pictures): the program
// plans the demo and renders that window, not the main window; a wrong name is refused in words.
TEST(Screenshot, DialogOptionRendersTheNamedWindowOfThePlannedDemo) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    env.insert(QStringLiteral("HOME"), dir.path()); // no settings or autosave of the user
    auto run = [&](const QStringList& args, QString* err) {
        QProcess p;
        p.setProcessEnvironment(env);
        p.start(QStringLiteral(PF_PHOTOFLIGHT_PATH), args);
        EXPECT_TRUE(p.waitForFinished(120000));
        *err = QString::fromUtf8(p.readAllStandardError());
        return p.exitCode();
    };
    QString err;
    const QString exportPng = dir.filePath(QStringLiteral("export.png"));
    const QString demo = QStringLiteral(PF_RESOURCES_DIR "/demo/demo_mission.json");
    ASSERT_EQ(run({QStringLiteral("--screenshot"), exportPng, QStringLiteral("--dialog"),
                   QStringLiteral("export"), demo},
                  &err),
              0)
        << err.toStdString();
    const QImage exported(exportPng);
    ASSERT_FALSE(exported.isNull());
    EXPECT_LT(exported.width(), 1600); // the dialog, not the 1600 x 1000 main window
    EXPECT_GT(exported.width(), 300);
    EXPECT_GT(exported.height(), 200);
    const QString helpPng = dir.filePath(QStringLiteral("help.png"));
    ASSERT_EQ(run({QStringLiteral("--screenshot"), helpPng, QStringLiteral("--dialog"),
                   QStringLiteral("help"), demo},
                  &err),
              0)
        << err.toStdString();
    EXPECT_EQ(QImage(helpPng).size(), QSize(900, 760)); // the user guide's window
    EXPECT_EQ(run({QStringLiteral("--screenshot"), helpPng, QStringLiteral("--dialog"),
                   QStringLiteral("map"), demo},
                  &err),
              2);
    EXPECT_TRUE(err.contains(QStringLiteral("--dialog must be export or help")))
        << err.toStdString();
}
