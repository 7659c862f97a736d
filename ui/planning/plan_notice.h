// PlanNotice: the status bar's notice that a new plan waits because routes were edited by hand,
// with its two answers: replace the edited paths, or keep them.
#pragma once

#include <QWidget>

namespace pf::ui {

class PlanController;

class PlanNotice : public QWidget {
    Q_OBJECT
public:
    // Hidden until `planner` holds a pending plan; hidden again once it is answered.
    explicit PlanNotice(PlanController* planner, QWidget* parent = nullptr);
};

} // namespace pf::ui
