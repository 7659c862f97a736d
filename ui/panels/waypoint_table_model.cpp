#include "ui/panels/waypoint_table_model.h"

#include "core/mission/route_check.h"
#include "core/route/route_sorties.h"
#include "ui/commands/edit_waypoint_command.h"
#include "ui/map/plan_layer.h"
#include "ui/mission_document.h"

#include <QBrush>
#include <QColor>

#include <algorithm>
#include <cmath>

namespace pf::ui {

WaypointTableModel::WaypointTableModel(MissionDocument* doc, PlanLayer* layer, QObject* parent)
    : QAbstractTableModel(parent), m_doc(doc), m_layer(layer) {
    // The layer revalidates after every change of the routes or the mission; follow it.
    connect(m_layer, &PlanLayer::routeProblemsChanged, this, &WaypointTableModel::refresh);
}

QString WaypointTableModel::actionName(int kind) {
    switch (route::WaypointKind(kind)) {
    case route::WaypointKind::Photo:
        return tr("photo");
    case route::WaypointKind::Turn:
        return tr("turn");
    case route::WaypointKind::Transit:
        return tr("transit");
    }
    return {};
}

void WaypointTableModel::setRoute(int routeIndex) {
    beginResetModel();
    m_route = routeIndex;
    m_rows = (m_route >= 0 && m_route < int(m_doc->routes().size()))
                 ? int(m_doc->routes()[std::size_t(m_route)].route.waypoints.size())
                 : 0;
    updateSorties();
    endResetModel();
}

// The sorties as the files and uploads cut them: at the transit waypoint at home.
void WaypointTableModel::updateSorties() {
    m_sortie.clear();
    m_sorties = 1;
    if (m_route < 0 || m_route >= int(m_doc->routes().size()))
        return;
    const auto& r = m_doc->routes()[std::size_t(m_route)].route;
    m_sortie = route::sortieOfWaypoints(r, mission::routeLimits(m_doc->mission(), r).home);
    for (int s : m_sortie)
        m_sorties = std::max(m_sorties, s + 1);
}

void WaypointTableModel::refresh() {
    if (m_route >= int(m_doc->routes().size()))
        m_route = m_doc->routes().empty() ? -1 : 0;
    const int rows =
        m_route >= 0 ? int(m_doc->routes()[std::size_t(m_route)].route.waypoints.size()) : 0;
    if (rows != m_rows) {
        setRoute(m_route);
        return;
    }
    updateSorties();
    if (rows > 0)
        emit dataChanged(index(0, 0), index(rows - 1, ColumnCount - 1));
}

int WaypointTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : m_rows;
}

int WaypointTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant WaypointTableModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || m_route < 0 || m_route >= int(m_doc->routes().size()))
        return {};
    const auto& wps = m_doc->routes()[std::size_t(m_route)].route.waypoints;
    if (index.row() >= int(wps.size()))
        return {};
    const auto& w = wps[std::size_t(index.row())];
    QString problem;
    const auto& issues = m_layer->issues();
    if (m_route < int(issues.size())) {
        const auto& is = issues[std::size_t(m_route)];
        if (index.row() < int(is.waypoint.size()))
            problem = is.waypoint[std::size_t(index.row())];
        if (problem.isEmpty() && index.row() < int(is.leg.size()))
            problem = is.leg[std::size_t(index.row())];
    }
    const int sortie = index.row() < int(m_sortie.size()) ? m_sortie[std::size_t(index.row())] : 0;
    if (role == Qt::BackgroundRole && !problem.isEmpty())
        return QBrush(QColor(255, 205, 205));
    if (role == Qt::ToolTipRole && !problem.isEmpty())
        return problem;
    if (role == Qt::ToolTipRole && index.column() == Sortie)
        return sortie < 0
                   ? tr("Home: the battery is changed here; each sortie is a flight of its own")
                   : tr("Sortie %1 of %2 (battery %1)").arg(sortie + 1).arg(m_sorties);
    if (role == Qt::ForegroundRole && index.column() == Sortie && sortie < 0)
        return QBrush(QColor(120, 120, 120));
    if (role == Qt::TextAlignmentRole && index.column() != Action && index.column() != Problem)
        return int(Qt::AlignRight | Qt::AlignVCenter);
    if (role == Qt::DisplayRole) {
        switch (index.column()) {
        case Number:
            return index.row() + 1;
        case Sortie:
            return sortie < 0 ? tr("home") : QString::number(sortie + 1);
        case Latitude:
            return QString::number(w.position.lat, 'f', 7);
        case Longitude:
            return QString::number(w.position.lon, 'f', 7);
        case Altitude:
            return QString::number(w.altitudeM, 'f', 1);
        case Heading:
            return QString::number(w.headingDeg, 'f', 1);
        case Action:
            return actionName(int(w.kind));
        case Problem:
            return problem;
        }
    }
    if (role == Qt::EditRole) {
        switch (index.column()) {
        case Latitude:
            return w.position.lat;
        case Longitude:
            return w.position.lon;
        case Altitude:
            return w.altitudeM;
        case Heading:
            return w.headingDeg;
        case Action:
            return actionName(int(w.kind));
        }
    }
    return {};
}

QVariant WaypointTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Number:
        return tr("#");
    case Sortie:
        return tr("Sortie");
    case Latitude:
        return tr("Latitude");
    case Longitude:
        return tr("Longitude");
    case Altitude:
        return tr("Alt (m)");
    case Heading:
        return tr("Heading (°)");
    case Action:
        return tr("Action");
    case Problem:
        return tr("Problem");
    }
    return {};
}

Qt::ItemFlags WaypointTableModel::flags(const QModelIndex& index) const {
    Qt::ItemFlags f = QAbstractTableModel::flags(index);
    if (index.column() >= Latitude && index.column() <= Action)
        f |= Qt::ItemIsEditable;
    return f;
}

bool WaypointTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (role != Qt::EditRole || m_route < 0 || m_route >= int(m_doc->routes().size()))
        return false;
    const auto& wps = m_doc->routes()[std::size_t(m_route)].route.waypoints;
    if (index.row() < 0 || index.row() >= int(wps.size()))
        return false;
    route::Waypoint w = wps[std::size_t(index.row())];
    bool ok = true;
    switch (index.column()) {
    case Latitude: {
        const double v = value.toDouble(&ok);
        if (!ok || v < -90 || v > 90)
            return false;
        w.position.lat = v;
        break;
    }
    case Longitude: {
        const double v = value.toDouble(&ok);
        if (!ok || v < -180 || v > 180)
            return false;
        w.position.lon = v;
        break;
    }
    case Altitude: {
        const double v = value.toDouble(&ok);
        if (!ok || v <= 0)
            return false;
        w.altitudeM = v;
        break;
    }
    case Heading: {
        const double v = value.toDouble(&ok);
        if (!ok)
            return false;
        w.headingDeg = std::fmod(std::fmod(v, 360.0) + 360.0, 360.0);
        break;
    }
    case Action: {
        const QString s = value.toString().trimmed().toLower();
        int found = -1;
        for (int k = 0; k < 3; ++k)
            if (s == actionName(k))
                found = k;
        if (found < 0)
            return false;
        w.kind = route::WaypointKind(found);
        break;
    }
    default:
        return false;
    }
    if (w == wps[std::size_t(index.row())])
        return true;
    m_doc->undoStack()->push(new EditWaypointCommand(m_doc, m_route, index.row(), w));
    return true;
}

} // namespace pf::ui
