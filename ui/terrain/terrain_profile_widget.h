// TerrainProfileWidget: the altitude profile of one route over the terrain: the ground, the aircraft
// and the minimum clearance above the ground, along the flight from home to home.
#pragma once

#include <QColor>
#include <QWidget>

#include <vector>

namespace pf::ui {

struct TerrainProfile {
    std::vector<double> distanceM;  // along the flight from home
    std::vector<double> groundM;    // above sea level (NaN where the terrain model has no data)
    std::vector<double> aircraftM;  // above sea level
    std::vector<double> waypointsM; // distance of each waypoint from home, for the ticks
    double minClearanceM = 0.0;
    QColor colour = QColor(230, 25, 75);
    bool empty() const { return distanceM.size() < 2; }
    // The lowest clearance (aircraft minus ground) and where it is.
    double lowestClearanceM(double* atM = nullptr) const;
};

class TerrainProfileWidget : public QWidget {
    Q_OBJECT
public:
    explicit TerrainProfileWidget(QWidget* parent = nullptr);
    void setProfile(TerrainProfile profile);
    const TerrainProfile& profile() const { return m_profile; }
    QSize sizeHint() const override { return {600, 180}; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    TerrainProfile m_profile;
};

} // namespace pf::ui
