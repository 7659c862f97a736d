#include "ui/mosaic/mosaic_controller.h"

#include "core/mosaic/planned_flight.h"
#include "ui/map/map_view.h"
#include "ui/mosaic/mosaic_dialog.h"
#include "ui/mosaic/mosaic_layer.h"
#include "ui/mosaic/mosaic_panel.h"
#include "ui/planning/plan_controller.h"

#include <QDockWidget>
#include <QMainWindow>
#include <QStatusBar>

namespace pf::ui {

MosaicController::MosaicController(QMainWindow* window, MapView* view, QGraphicsScene* scene,
                                   PlanController* planner, const io::Catalog* catalog)
    : QObject(window), m_window(window), m_view(view), m_planner(planner), m_catalog(catalog),
      m_layer(new MosaicLayer(scene, this)) {}

MosaicController::~MosaicController() = default;

MosaicDialog* MosaicController::dialog() {
    if (!m_dialog) {
        auto currentPlan = [this]() -> std::optional<mosaic::PlannedFlight> {
            const auto& plan = m_planner ? m_planner->plan() : std::nullopt;
            if (!plan)
                return std::nullopt;
            auto flight = mosaic::plannedFlightFromPlan(*plan);
            if (flight.photos.empty())
                return std::nullopt;
            return flight;
        };
        m_dialog = new MosaicDialog(*m_catalog, currentPlan, m_window);
        connect(m_dialog, &MosaicDialog::mosaicReady, this, [this](const mosaic::MosaicReport& r) {
            QString error;
            if (!showMosaic(r, &error))
                m_window->statusBar()->showMessage(error, 8000);
        });
    }
    return m_dialog;
}

MosaicPanel* MosaicController::createPanel() {
    if (m_panel)
        return m_panel;
    m_panel = new MosaicPanel(m_layer, m_window);
    m_window->addDockWidget(Qt::RightDockWidgetArea, m_panel);
    // A tab beside the other docks of that side (Aircraft, Mission, History), with their height.
    QDockWidget* neighbour = nullptr;
    for (auto* d : m_window->findChildren<QDockWidget*>())
        if (d != m_panel && m_window->dockWidgetArea(d) == Qt::RightDockWidgetArea &&
            !d->isFloating())
            neighbour = d;
    if (neighbour)
        m_window->tabifyDockWidget(neighbour, m_panel);
    m_panel->hide();
    connect(m_panel, &MosaicPanel::zoomRequested, this, &MosaicController::zoomToMosaic);
    connect(m_panel, &MosaicPanel::removeRequested, this, &MosaicController::removeMosaic);
    connect(m_panel, &MosaicPanel::reportRequested, this, &MosaicController::showDialog);
    return m_panel;
}

void MosaicController::showDialog() {
    MosaicDialog* d = dialog();
    d->show();
    d->raise();
    d->activateWindow();
}

bool MosaicController::showMosaic(const mosaic::MosaicReport& report, QString* error) {
    if (!m_layer->show(report, error))
        return false;
    createPanel();
    m_panel->refresh();
    m_panel->show();
    m_panel->raise();
    zoomToMosaic();
    m_window->statusBar()->showMessage(
        tr("Mosaic of %1 photos shown over the mission (%2 gap(s) in the planned area)")
            .arg(report.photosUsed)
            .arg(report.gaps.size()),
        8000);
    emit mosaicShown();
    return true;
}

void MosaicController::zoomToMosaic() {
    const QRectF r = m_layer->bounds();
    if (!r.isEmpty())
        m_view->fitSceneRect(r, 30);
}

void MosaicController::removeMosaic() {
    m_layer->clear();
    if (m_panel)
        m_panel->refresh();
}

} // namespace pf::ui
