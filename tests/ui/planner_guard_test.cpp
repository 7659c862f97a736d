// The lawnmower stays visible in Compare planners as the yardstick, but where the mission has
// no-fly zones its routes cross it is not offered as the mission's planner: its Use button is
// disabled and says why (naming the zones), the note below the table too, and the planner box does
// not offer it. Without zones it is used with one click, as every planner.
#include "tests/ui/ui_test_util.h"

#include "core/mission/planner_kinds.h"
#include "ui/commands/remove_no_fly_zone_command.h"
#include "ui/mission_document.h"
#include "ui/panels/statistics_panel.h"
#include "ui/planning/plan_controller.h"

#include <QComboBox>
#include <QPushButton>
#include <QStandardItemModel>

#include <gtest/gtest.h>

using namespace pf;
using namespace pf::ui;

namespace {

std::unique_ptr<MainWindow> demoWindow() {
    auto w = test::makeWindow();
    w->planController()->setAutoPlan(false);
    QString error;
    EXPECT_TRUE(w->openDemoMission(&error)) << error.toStdString();
    return w;
}

// The planner box's item for `kind`.
QStandardItem* boxItem(MainWindow* w, mission::PlannerKind kind) {
    auto* box = w->findChild<QComboBox*>(QStringLiteral("PlannerBox"));
    if (!box)
        return nullptr;
    auto* model = qobject_cast<QStandardItemModel*>(box->model());
    const int i = box->findData(int(kind));
    return model && i >= 0 ? model->item(i) : nullptr;
}

} // namespace

TEST(PlannerGuard, TheLawnmowerIsTheYardstickWhereItCrossesTheMissionsZones) {
    auto w = demoWindow();
    auto* doc = w->document();
    auto* panel = w->statisticsPanel();
    const auto before = doc->mission().options.planner;
    // Before any comparison: not offered, and the reason says how to find out.
    auto* use = panel->useButton(mission::PlannerKind::Lawnmower);
    ASSERT_NE(use, nullptr);
    EXPECT_FALSE(use->isEnabled());
    EXPECT_EQ(use->text(), QStringLiteral("Yardstick"));
    EXPECT_TRUE(use->toolTip().contains(QStringLiteral("Compare planners")))
        << use->toolTip().toStdString();
    ASSERT_NE(boxItem(w.get(), mission::PlannerKind::Lawnmower), nullptr);
    EXPECT_FALSE(boxItem(w.get(), mission::PlannerKind::Lawnmower)->isEnabled());
    EXPECT_TRUE(boxItem(w.get(), mission::PlannerKind::Stride)->isEnabled());

    w->planController()->compare();
    ASSERT_TRUE(w->planController()->waitForIdle(180000));
    use = panel->useButton(mission::PlannerKind::Lawnmower);
    EXPECT_FALSE(use->isEnabled());
    EXPECT_TRUE(use->toolTip().contains(QStringLiteral("its routes cross Warehouse, Radio mast")))
        << use->toolTip().toStdString();
    EXPECT_TRUE(panel->compareNote().contains(QStringLiteral("Warehouse, Radio mast")))
        << panel->compareNote().toStdString();
    // Every other planner keeps out of the zones and stays offered.
    for (const auto& k : mission::plannerKinds())
        if (k.kind != mission::PlannerKind::Lawnmower && k.kind != before) {
            EXPECT_TRUE(panel->useButton(k.kind)->isEnabled()) << k.id;
        }
    QTest::mouseClick(use, Qt::LeftButton);
    EXPECT_FALSE(panel->usePlanner(mission::PlannerKind::Lawnmower));
    EXPECT_EQ(doc->mission().options.planner, before);
    EXPECT_FALSE(boxItem(w.get(), mission::PlannerKind::Lawnmower)->isEnabled());
    EXPECT_TRUE(boxItem(w.get(), mission::PlannerKind::Lawnmower)
                    ->toolTip()
                    .contains(QStringLiteral("Warehouse, Radio mast")));
}

TEST(PlannerGuard, WithoutZonesTheLawnmowerIsUsedWithOneClick) {
    auto w = demoWindow();
    auto* doc = w->document();
    auto* panel = w->statisticsPanel();
    while (!doc->mission().noFlyZones.empty())
        doc->undoStack()->push(new RemoveNoFlyZoneCommand(doc, 0));
    auto* use = panel->useButton(mission::PlannerKind::Lawnmower);
    ASSERT_NE(use, nullptr);
    EXPECT_TRUE(use->isEnabled());
    EXPECT_EQ(use->text(), QStringLiteral("Use"));
    EXPECT_TRUE(panel->compareNote().isEmpty());
    EXPECT_TRUE(boxItem(w.get(), mission::PlannerKind::Lawnmower)->isEnabled());
    QTest::mouseClick(use, Qt::LeftButton);
    EXPECT_EQ(doc->mission().options.planner, mission::PlannerKind::Lawnmower);
    EXPECT_EQ(panel->useButton(mission::PlannerKind::Lawnmower)->text(), QStringLiteral("In use"));
    // A zone brought back (undo of the removal): the planner in use is kept and shown as such, but
    // it is not offered again once another is chosen.
    doc->undoStack()->undo(); // the planner change
    doc->undoStack()->undo(); // one zone back
    EXPECT_FALSE(panel->useButton(mission::PlannerKind::Lawnmower)->isEnabled());
}
