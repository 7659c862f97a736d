// PlanProgressWidget: the status bar's progress of a running plan (stage, percentage, Cancel).
#pragma once

#include <QTimer>
#include <QWidget>

class QLabel;
class QProgressBar;
class QToolButton;

namespace pf::ui {

class PlanController;

// Shown once a plan has run for kShowAfterMs (short plans do not flicker it), hidden when planning
// ends; Cancel cancels the running plan.
class PlanProgressWidget : public QWidget {
    Q_OBJECT
public:
    explicit PlanProgressWidget(PlanController* controller, QWidget* parent = nullptr);
    static constexpr int kShowAfterMs = 500;

    QProgressBar* bar() const { return m_bar; }
    QLabel* stage() const { return m_stage; }
    QToolButton* cancelButton() const { return m_cancel; }

private:
    void setBusy(bool busy);

    PlanController* m_controller;
    QLabel* m_stage;
    QProgressBar* m_bar;
    QToolButton* m_cancel;
    QTimer m_showTimer;
};

} // namespace pf::ui
