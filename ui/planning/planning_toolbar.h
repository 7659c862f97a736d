// PlanningToolBar: the Planning tool bar and the actions the Plan menu shares with it: Plan (asking
// before edited routes are replaced), Cancel, planning after every edit, the planner, the grid
// angle (or Auto), Keep inside area, Double grid and the camera tilt, each edit of the mission's
// options one undo step.
#pragma once

#include <QToolBar>

class QAction;
class QComboBox;
class QDoubleSpinBox;

namespace pf::ui {

class MissionDocument;
class PlanController;

class PlanningToolBar : public QToolBar {
    Q_OBJECT
public:
    // `exportRoutes` is the Plan menu's export action, shown here too. `interactive` false: Plan never
    // asks (tests, --screenshot). `parent` (the main window) is the parent of the question.
    PlanningToolBar(MissionDocument* doc, PlanController* planner, QAction* exportRoutes, bool interactive,
                    QWidget* parent);

    QAction* planAction() const { return m_plan; }
    QAction* cancelAction() const { return m_cancel; }
    // Plan after every edit (checkable; remembered in the settings as "plan/auto").
    QAction* autoPlanAction() const { return m_autoPlan; }
    // The "Keep inside area" toggle (object name "KeepInsideAction").
    QAction* keepInsideAction() const { return m_keepInside; }
    // The "Double grid" toggle (object name "DoubleGridAction").
    QAction* doubleGridAction() const { return m_doubleGrid; }

    // Plans now; when routes were edited by hand, asks first (interactive windows) and otherwise
    // keeps the edits until the user replaces them from the notice.
    void planNow();

private:
    // Shows the document's options (after an edit, an undo or another mission).
    void syncControls();
    // The "Safety margin" box (object name "SafetyMarginBox").
    void makeSafetyMarginBox();
    // The camera tilt box for oblique photos (object name "CameraTiltBox").
    void makeCameraTiltBox();
    // Tool tips and "What's this?" texts of the planner options.
    void explainOptions();

    MissionDocument* m_doc;
    PlanController* m_planner;
    bool m_interactive;
    QAction* m_plan;
    QAction* m_cancel;
    QAction* m_autoPlan;
    QAction* m_keepInside;
    QAction* m_doubleGrid;
    QComboBox* m_plannerBox;
    QDoubleSpinBox* m_angleBox;
    QDoubleSpinBox* m_marginBox = nullptr;
    QDoubleSpinBox* m_tiltBox = nullptr;
};

} // namespace pf::ui
