// MosaicController: everything the desktop application does with mosaics, behind File > Build
// mosaic: the dialog, the map layer and the Mosaic dock.
#pragma once

#include "core/io/catalog.h"
#include "core/mosaic/mosaic_types.h"

#include <QObject>

class QGraphicsScene;
class QMainWindow;

namespace pf::ui {

class MapView;
class MosaicDialog;
class MosaicLayer;
class MosaicPanel;
class PlanController;

class MosaicController : public QObject {
    Q_OBJECT
public:
    // `catalog` must outlive the controller (the main window's).
    MosaicController(QMainWindow* window, MapView* view, QGraphicsScene* scene,
                     PlanController* planner, const io::Catalog* catalog);
    ~MosaicController() override;

    // File > Build mosaic: shows the dialog (created on first use, kept with its choices).
    void showDialog();
    MosaicDialog* dialog();
    MosaicLayer* layer() const { return m_layer; }
    // The Mosaic dock: made hidden, a tab beside the docks already on the right (call once they are
    // there), so that View > Mosaic reaches it; shown with a mosaic. Null before.
    MosaicPanel* createPanel();
    MosaicPanel* panel() const { return m_panel; }

    // Puts a finished mosaic on the map over the mission and zooms to it.
    bool showMosaic(const mosaic::MosaicReport& report, QString* error = nullptr);
    void zoomToMosaic();
    void removeMosaic();

signals:
    void mosaicShown();

private:
    QMainWindow* m_window;
    MapView* m_view;
    PlanController* m_planner;
    const io::Catalog* m_catalog;
    MosaicLayer* m_layer;
    MosaicDialog* m_dialog = nullptr;
    MosaicPanel* m_panel = nullptr;
};

} // namespace pf::ui
