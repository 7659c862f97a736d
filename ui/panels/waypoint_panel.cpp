#include "ui/panels/waypoint_panel.h"

#include "ui/commands/insert_waypoint_command.h"
#include "ui/commands/remove_waypoints_command.h"
#include "ui/commands/reverse_route_command.h"
#include "ui/commands/set_waypoint_altitude_command.h"
#include "ui/map/plan_layer.h"
#include "ui/mission_document.h"
#include "ui/panels/waypoint_table_model.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QItemSelectionModel>
#include <QLabel>
#include <QMenu>
#include <QStyledItemDelegate>
#include <QTableView>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>

namespace pf::ui {

namespace {

// The action column is edited with a list of the three actions rather than free text.
class ActionDelegate : public QStyledItemDelegate {
public:
    using QStyledItemDelegate::QStyledItemDelegate;
    QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem&,
                          const QModelIndex&) const override {
        auto* box = new QComboBox(parent);
        for (int k = 0; k < 3; ++k)
            box->addItem(WaypointTableModel::actionName(k));
        return box;
    }
    void setEditorData(QWidget* editor, const QModelIndex& index) const override {
        static_cast<QComboBox*>(editor)->setCurrentText(index.data(Qt::EditRole).toString());
    }
    void setModelData(QWidget* editor, QAbstractItemModel* model,
                      const QModelIndex& index) const override {
        model->setData(index, static_cast<QComboBox*>(editor)->currentText());
    }
};

} // namespace

WaypointPanel::WaypointPanel(MissionDocument* doc, PlanLayer* layer, QWidget* parent)
    : QWidget(parent), m_doc(doc), m_layer(layer) {
    setObjectName(QStringLiteral("WaypointPanel"));
    m_model = new WaypointTableModel(doc, layer, this);
    m_routes = new QComboBox;
    m_state = new QLabel;
    m_table = new QTableView;
    m_table->setModel(m_model);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setDefaultSectionSize(22);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setItemDelegateForColumn(WaypointTableModel::Action, new ActionDelegate(m_table));
    m_table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                             QAbstractItemView::AnyKeyPressed);

    auto button = [this](const QString& text, const QString& tip, auto slot) {
        auto* b = new QToolButton;
        b->setText(text);
        b->setToolTip(tip);
        connect(b, &QToolButton::clicked, this, slot);
        return b;
    };
    auto* top = new QHBoxLayout;
    top->addWidget(new QLabel(tr("Route:")));
    top->addWidget(m_routes, 1);
    top->addWidget(m_state);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(button(tr("Insert"), tr("Insert a waypoint after the selected one"),
                              [this] { insertAfterSelected(); }));
    buttons->addWidget(
        button(tr("Delete"), tr("Delete the selected waypoints"), [this] { deleteSelected(); }));
    buttons->addWidget(
        button(tr("Set altitude…"),
               tr("One altitude for the selected waypoints, or all when none is selected"),
               [this] { askAltitude(); }));
    buttons->addWidget(
        button(tr("Reverse"), tr("Fly the route the other way round"), [this] { reverseRoute(); }));
    buttons->addStretch();
    auto* lay = new QVBoxLayout(this);
    lay->setContentsMargins(4, 4, 4, 4);
    lay->addLayout(top);
    lay->addWidget(m_table, 1);
    lay->addLayout(buttons);

    connect(m_routes, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this](int i) {
        m_model->setRoute(i);
        rebuildRouteList();
    });
    connect(m_doc, &MissionDocument::routesChanged, this, &WaypointPanel::rebuildRouteList);
    connect(m_layer, &PlanLayer::waypointSelectionChanged, this, &WaypointPanel::syncFromLayer);
    connect(m_table->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &WaypointPanel::syncToLayer);
    connect(m_model, &QAbstractItemModel::modelReset, this, [this] {
        // A new selection model is not created on reset, but its rows are gone: redo the link.
        syncFromLayer();
        m_table->resizeColumnsToContents();
    });
    rebuildRouteList();
}

int WaypointPanel::currentRoute() const {
    return m_routes->currentIndex();
}

void WaypointPanel::setCurrentRoute(int route) {
    m_routes->setCurrentIndex(route);
}

void WaypointPanel::rebuildRouteList() {
    const auto& routes = m_doc->routes();
    const int keep = std::max(0, m_routes->currentIndex());
    {
        const QSignalBlocker block(m_routes);
        m_routes->clear();
        for (const auto& r : routes)
            m_routes->addItem(QString::fromStdString(
                r.route.aircraft.empty() ? tr("Route").toStdString() : r.route.aircraft));
        if (!routes.empty())
            m_routes->setCurrentIndex(std::min(keep, int(routes.size()) - 1));
    }
    const int cur = m_routes->currentIndex();
    if (m_model->route() != cur)
        m_model->setRoute(cur);
    const bool edited = cur >= 0 && routes[std::size_t(cur)].edited;
    m_state->setText(cur < 0  ? tr("no plan yet")
                     : edited ? tr("<b>edited</b> · %n waypoint(s)", nullptr,
                                   int(routes[std::size_t(cur)].route.waypoints.size()))
                              : tr("as planned · %n waypoint(s)", nullptr,
                                   int(routes[std::size_t(cur)].route.waypoints.size())));
}

QList<int> WaypointPanel::selectedWaypoints() const {
    QList<int> rows;
    for (const auto& idx : m_table->selectionModel()->selectedRows())
        rows << idx.row();
    std::sort(rows.begin(), rows.end());
    return rows;
}

void WaypointPanel::syncFromLayer() {
    if (m_syncing)
        return;
    m_syncing = true;
    const int r = m_layer->selectedRoute();
    if (r >= 0 && r != m_routes->currentIndex())
        m_routes->setCurrentIndex(r);
    QItemSelection sel;
    if (r == m_model->route())
        for (int i : m_layer->selectedWaypoints())
            if (i < m_model->rowCount())
                sel.select(m_model->index(i, 0),
                           m_model->index(i, WaypointTableModel::ColumnCount - 1));
    m_table->selectionModel()->select(sel, QItemSelectionModel::ClearAndSelect);
    if (!sel.isEmpty())
        m_table->scrollTo(sel.indexes().first());
    m_syncing = false;
}

void WaypointPanel::syncToLayer() {
    if (m_syncing)
        return;
    m_syncing = true;
    m_layer->selectWaypoints(m_model->route(), selectedWaypoints());
    m_syncing = false;
}

void WaypointPanel::setAltitude(double altitudeM, bool all) {
    const int r = m_model->route();
    if (r < 0)
        return;
    m_doc->undoStack()->push(new SetWaypointAltitudeCommand(
        m_doc, r, all ? QList<int>() : selectedWaypoints(), altitudeM));
}

void WaypointPanel::askAltitude() {
    const int r = m_model->route();
    if (r < 0)
        return;
    const QList<int> sel = selectedWaypoints();
    const auto& wps = m_doc->routes()[std::size_t(r)].route.waypoints;
    const double current =
        !wps.empty() ? wps[std::size_t(sel.isEmpty() ? 0 : sel.first())].altitudeM : 40.0;
    bool ok = false;
    const double alt = QInputDialog::getDouble(
        this, tr("Set altitude"),
        sel.isEmpty() ? tr("Altitude for all %1 waypoints (m above take-off):").arg(wps.size())
                      : tr("Altitude for the %n selected waypoint(s) (m above take-off):", nullptr,
                           sel.size()),
        current, 1.0, 500.0, 1, &ok);
    if (ok)
        setAltitude(alt, sel.isEmpty());
}

void WaypointPanel::reverseRoute() {
    const int r = m_model->route();
    if (r >= 0)
        m_doc->undoStack()->push(new ReverseRouteCommand(m_doc, r));
}

void WaypointPanel::deleteSelected() {
    const int r = m_model->route();
    const QList<int> sel = selectedWaypoints();
    if (r < 0 || sel.isEmpty())
        return;
    m_layer->selectWaypoints(-1, {});
    m_doc->undoStack()->push(new RemoveWaypointsCommand(m_doc, r, sel));
}

void WaypointPanel::insertAfterSelected() {
    const int r = m_model->route();
    if (r < 0)
        return;
    const auto& wps = m_doc->routes()[std::size_t(r)].route.waypoints;
    if (wps.empty())
        return;
    const QList<int> sel = selectedWaypoints();
    const int after = sel.isEmpty() ? int(wps.size()) - 1 : sel.last();
    // Halfway to the next waypoint (or a copy of the last one), as a turn point.
    route::Waypoint w = wps[std::size_t(after)];
    if (after + 1 < int(wps.size())) {
        const auto& n = wps[std::size_t(after + 1)].position;
        w.position = {(w.position.lon + n.lon) / 2, (w.position.lat + n.lat) / 2};
    }
    w.kind = route::WaypointKind::Turn;
    m_doc->undoStack()->push(new InsertWaypointCommand(m_doc, r, after + 1, w));
    m_layer->selectWaypoints(r, {after + 1});
}

} // namespace pf::ui
