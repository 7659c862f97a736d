// Oblique photos in the desktop application: the Tilt box beside Double grid is an undoable option,
// the Aircraft dock says how far ahead the photos are centred, and the plan it makes reaches its
// photos along their lanes (but where a detour round a zone ends at one). Offscreen, through the
// real widgets.
#include "core/geo/geodesic.h"
#include "ui/dialogs/export_dialog.h"
#include "ui/mission_document.h"
#include "ui/planning/plan_controller.h"
#include "ui_test_util.h"

#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QUndoStack>

#include <gtest/gtest.h>

#include <cmath>

using namespace pf;
using namespace pf::ui;

TEST(ObliqueUi, TiltBoxIsAnUndoableOptionAndTheDockSaysWherePhotosLook) {
    auto w = test::makeWindow();
    w->planController()->setAutoPlan(false);
    QString error;
    ASSERT_TRUE(w->openDemoMission(&error)) << error.toStdString();
    auto* tilt = w->findChild<QDoubleSpinBox*>(QStringLiteral("CameraTiltBox"));
    ASSERT_NE(tilt, nullptr);
    EXPECT_EQ(tilt->text(), QStringLiteral("Nadir photos"));
    auto* footprint = w->findChild<QLabel*>(QStringLiteral("FootprintLabel"));
    ASSERT_NE(footprint, nullptr);
    EXPECT_FALSE(footprint->text().contains(QStringLiteral("ahead")));

    tilt->setValue(30);
    EXPECT_EQ(w->document()->mission().options.cameraTiltDeg, 30.0);
    EXPECT_EQ(w->document()->undoStack()->undoText(), QStringLiteral("Camera tilt 30°"));
    EXPECT_TRUE(footprint->text().contains(QStringLiteral("camera tilted 30°: photos centred")))
        << footprint->text().toStdString();

    // Planned with the tilt: every photo is reached along its own heading (the lane's lead-in).
    w->planNow();
    ASSERT_TRUE(w->planController()->waitForIdle(120000));
    const auto& routes = w->document()->routes();
    ASSERT_FALSE(routes.empty());
    int photos = 0, across = 0;
    for (const auto& planned : routes) {
        const route::Route& r = planned.route;
        for (std::size_t i = 1; i < r.waypoints.size(); ++i) {
            if (r.waypoints[i].kind != route::WaypointKind::Photo)
                continue;
            ++photos;
            const double off = std::remainder(
                r.waypoints[i].headingDeg -
                    geo::initialBearingDeg(r.waypoints[i - 1].position, r.waypoints[i].position),
                360.0);
            if (std::abs(off) <= 10.0)
                continue;
            // Only where a detour round a zone's margin ends at the photo (no lead-in keeps it).
            ++across;
            EXPECT_EQ(r.waypoints[i - 1].kind, route::WaypointKind::Transit) << r.aircraft << " photo " << i;
        }
    }
    EXPECT_LE(across * 100, photos) << across << " of " << photos;
    EXPECT_GT(photos, 100);

    // The Export dialog says where the gimbal command points the camera.
    {
        ExportDialog dialog(w->document(), w->planController(), QDir::tempPath());
        auto* gimbal = dialog.findChild<QComboBox*>(QStringLiteral("ExportGimbal"));
        ASSERT_NE(gimbal, nullptr);
        EXPECT_EQ(gimbal->itemText(0), QStringLiteral("Camera tilted 30° forward (pitch -60°): DO_MOUNT_CONTROL"));
    }

    w->document()->undoStack()->undo();
    EXPECT_EQ(w->document()->mission().options.cameraTiltDeg, 0.0);
    EXPECT_EQ(tilt->text(), QStringLiteral("Nadir photos"));
}
