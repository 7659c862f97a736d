// HillshadeLayer: the shaded relief of the mission's terrain model (DEM) on the map, between the
// base map and the mission, semi-transparent; computed off the GUI thread once per DEM chosen.
#pragma once

#include <QFutureWatcher>
#include <QImage>
#include <QObject>
#include <QRectF>
#include <QString>

class QAction;
class QGraphicsPixmapItem;
class QGraphicsScene;

namespace pf::ui {

class MissionDocument;

// The shaded picture and where it lies in the scene (Web Mercator metres, y down).
struct ShadedRelief {
    QImage image; // grey, transparent where the DEM has no data
    QRectF sceneRect;
    QString path;         // the DEM it shows
    bool cropped = false; // the DEM reaches beyond the picture
    QString error;
};

class HillshadeLayer : public QObject {
    Q_OBJECT
public:
    HillshadeLayer(MissionDocument* doc, QGraphicsScene* scene, QObject* parent = nullptr);
    ~HillshadeLayer() override;

    // View ▸ Hillshade: checkable, remembered between sessions.
    QAction* toggleAction() const { return m_action; }
    void setShown(bool on);
    bool isShown() const;
    bool hasRelief() const { return !m_relief.image.isNull(); }
    const ShadedRelief& relief() const { return m_relief; }
    QGraphicsPixmapItem* item() const { return m_item; }
    bool isComputing() const { return m_running; }
    // Runs the event loop until no computation is running (tests, screenshots); false on timeout.
    bool waitUntilReady(int timeoutMs);

    // Over the base map (-100), under a mosaic (-50) and the mission (10 and up).
    static constexpr double kZ = -70.0;
    static constexpr double kOpacity = 0.45;
    static constexpr int kMaxSidePx = 2048;

    // The relief of `demPath` (as the mission names it) around `area` (scene rectangle; empty: the
    // whole DEM, cropped to about 40 km): the DEM's pixel size, or coarser to stay within
    // kMaxSidePx a side. Plain function, safe off the GUI thread.
    static ShadedRelief compute(const QString& demPath, const QRectF& area);

signals:
    // A new relief is shown (or the old one removed).
    void reliefChanged();

private:
    void onMissionChanged();
    void start();
    void onFinished();

    MissionDocument* m_doc;
    QGraphicsPixmapItem* m_item;
    QAction* m_action;
    QFutureWatcher<ShadedRelief> m_watcher;
    ShadedRelief m_relief;
    QString m_wanted;       // the DEM the picture should show ("" for none)
    bool m_pending = false; // a newer request waits for the running one
    bool m_running = false; // until its result is taken (finished() may still be queued)
};

} // namespace pf::ui
