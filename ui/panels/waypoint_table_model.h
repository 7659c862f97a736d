// WaypointTableModel: one route's waypoints as a table (sortie, latitude, longitude, altitude,
// heading, action, problem); edits go through undo commands.
#pragma once

#include <QAbstractTableModel>

#include <vector>

namespace pf::ui {

class MissionDocument;
class PlanLayer;

class WaypointTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column {
        Number,
        Sortie,
        Latitude,
        Longitude,
        Altitude,
        Heading,
        Action,
        Problem,
        ColumnCount
    };

    WaypointTableModel(MissionDocument* doc, PlanLayer* layer, QObject* parent = nullptr);

    void setRoute(int routeIndex);
    int route() const { return m_route; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;

    static QString actionName(int kind);

private:
    void refresh();
    void updateSorties();
    MissionDocument* m_doc;
    PlanLayer* m_layer;
    int m_route = -1;
    int m_rows = 0;
    std::vector<int> m_sortie; // per row its sortie (0-based), -1 at home between two
    int m_sorties = 1;
};

} // namespace pf::ui
