#include "ui/planning/plan_progress_widget.h"

#include "ui/planning/plan_controller.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QToolButton>

namespace pf::ui {

PlanProgressWidget::PlanProgressWidget(PlanController* controller, QWidget* parent)
    : QWidget(parent), m_controller(controller) {
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(4, 0, 4, 0);
    m_stage = new QLabel(this);
    m_bar = new QProgressBar(this);
    m_bar->setRange(0, 1000);
    m_bar->setFormat(tr("%p %"));
    m_bar->setMaximumWidth(140);
    m_bar->setMaximumHeight(16);
    m_cancel = new QToolButton(this);
    m_cancel->setText(tr("Cancel"));
    m_cancel->setToolTip(tr("Stop planning (Shift+F5)"));
    layout->addWidget(m_stage);
    layout->addWidget(m_bar);
    layout->addWidget(m_cancel);
    m_showTimer.setSingleShot(true);
    m_showTimer.setInterval(kShowAfterMs);
    connect(&m_showTimer, &QTimer::timeout, this, [this] {
        if (m_controller->isBusy())
            show();
    });
    connect(m_cancel, &QToolButton::clicked, m_controller, &PlanController::cancel);
    connect(m_controller, &PlanController::busyChanged, this, &PlanProgressWidget::setBusy);
    connect(m_controller, &PlanController::progressChanged, this, [this](double f, const QString& stage) {
        m_bar->setValue(static_cast<int>(f * 1000.0));
        m_stage->setText(tr("Planning: %1").arg(stage));
    });
    hide();
}

void PlanProgressWidget::setBusy(bool busy) {
    if (busy) {
        m_bar->setValue(0);
        m_stage->setText(tr("Planning…"));
        m_showTimer.start();
    } else {
        m_showTimer.stop();
        hide();
    }
}

} // namespace pf::ui
