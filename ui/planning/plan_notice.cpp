#include "ui/planning/plan_notice.h"

#include "ui/planning/plan_controller.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

namespace pf::ui {

PlanNotice::PlanNotice(PlanController* planner, QWidget* parent) : QWidget(parent) {
    auto* nl = new QHBoxLayout(this);
    nl->setContentsMargins(6, 0, 6, 0);
    auto* text = new QLabel(tr("New plan ready — your edited paths are kept."));
    text->setStyleSheet(QStringLiteral("QLabel { color: #0b3d91; font-weight: bold; }"));
    auto* replace = new QPushButton(tr("Replace edited paths"));
    auto* keep = new QPushButton(tr("Keep edits"));
    nl->addWidget(text);
    nl->addWidget(replace);
    nl->addWidget(keep);
    // A QWidget subclass paints a style sheet's background only when asked to, as a plain QWidget does.
    setAttribute(Qt::WA_StyledBackground, true);
    setStyleSheet(QStringLiteral("QWidget { background: #dbe8ff; }"));
    hide();
    connect(replace, &QPushButton::clicked, planner, &PlanController::acceptPendingPlan);
    keep->setToolTip(tr("Keep the paths you edited; the other aircraft get the new plan"));
    replace->setToolTip(tr("The new plan replaces every path, the edited ones too"));
    connect(keep, &QPushButton::clicked, planner, &PlanController::keepEditsWithPendingPlan);
    connect(planner, &PlanController::pendingPlanChanged, this, &QWidget::setVisible);
}

} // namespace pf::ui
