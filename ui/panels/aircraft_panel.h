// AircraftPanel: the dock listing the mission's aircraft and editing one (camera, altitude <-> GSD, overlap, ...).
#pragma once

#include "core/io/catalog.h"
#include "core/mission/mission.h"

#include <QWidget>

#include <functional>

class QComboBox;
class QHBoxLayout;
class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QToolButton;
class QSpinBox;

namespace pf::ui {

class MissionDocument;

class AircraftPanel : public QWidget {
    Q_OBJECT
public:
    AircraftPanel(MissionDocument* doc, io::Catalog catalog, QWidget* parent = nullptr);

    // Every edit below pushes one undo command (consecutive edits of one field merge).
    void addFromCatalog(const QString& aircraftName);
    void addCustom();
    void removeCurrent();
    void setCurrent(int index);
    int current() const;

    // Widgets exposed for tests and keyboard-driven use.
    QDoubleSpinBox* altitudeBox() const { return m_altitude; }
    QDoubleSpinBox* gsdBox() const { return m_gsd; }
    QComboBox* cameraBox() const { return m_camera; }
    QDoubleSpinBox* frontOverlapBox() const { return m_front; }
    QDoubleSpinBox* sideOverlapBox() const { return m_side; }
    QDoubleSpinBox* speedBox() const { return m_speed; }
    QDoubleSpinBox* enduranceBox() const { return m_endurance; }
    // The kind (multirotor, fixed-wing, VTOL; items in fleet::AircraftKind order) and, shown for a
    // plane only, its minimum turn radius and bank limit (whichever is edited is stored, the other
    // follows from the speed), climb and sink rates and the run-in before each lane.
    QComboBox* kindBox() const { return m_kind; }
    QDoubleSpinBox* turnRadiusBox() const { return m_turnRadius; }
    QDoubleSpinBox* bankBox() const { return m_bank; }
    QDoubleSpinBox* climbBox() const { return m_climb; }
    QDoubleSpinBox* sinkBox() const { return m_sink; }
    QDoubleSpinBox* runInBox() const { return m_runIn; }
    QLabel* footprintLabel() const { return m_footprint; }
    // Why the last altitude or GSD typed was refused; empty when none was.
    QString altitudeError() const;
    void setColour(const QColor& colour);

private:
    void refreshList();
    void refreshForm(bool keepError = false);
    // The Footprint line of aircraft `a` at `alt` (HTML).
    QString footprintText(const mission::AircraftConfig& a, std::optional<double> alt) const;
    // Shows the plane's figures for a plane, hides them for a multirotor.
    void showPlaneRows(bool plane);
    void buildList();
    QHBoxLayout* buildButtons();
    void createFields();
    void buildForm();
    void connectFields();
    void connectPlaneFields();
    // Checks a typed altitude (or GSD) against the aircraft's limits (mission::altitudeErrors); a
    // refused value shows its reason and the box gets the stored value back.
    bool acceptAltitude(double value, bool isGsd);
    void editCurrent(const QString& field, const std::function<void(mission::AircraftConfig&)>& change);
    QString nextName(const QString& base) const;
    QString nextColour() const;

    MissionDocument* m_doc;
    io::Catalog m_catalog;
    bool m_updating = false;

    QListWidget* m_list;
    QToolButton* m_addButton;
    QPushButton* m_removeButton;
    QWidget* m_form;
    QLineEdit* m_name;
    QLabel* m_model;
    QComboBox* m_camera;
    QDoubleSpinBox* m_altitude;
    QDoubleSpinBox* m_gsd;
    QLabel* m_footprint;
    QLabel* m_altitudeError;
    QDoubleSpinBox* m_front;
    QDoubleSpinBox* m_side;
    QDoubleSpinBox* m_speed;
    QDoubleSpinBox* m_endurance;
    QComboBox* m_kind;
    QDoubleSpinBox* m_turnRadius;
    QDoubleSpinBox* m_bank;
    QDoubleSpinBox* m_climb;
    QDoubleSpinBox* m_sink;
    QDoubleSpinBox* m_runIn;
    QGroupBox* m_planeBox;
    QPushButton* m_colour;
};

} // namespace pf::ui
