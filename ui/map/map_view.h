// MapView: the map widget. Handles input only (zoom, pan, tools); layers are scene items that paint themselves.
#pragma once

#include "core/geo/types.h"

#include <QGraphicsView>

namespace pf::ui {

class AbstractTool;

class MapView : public QGraphicsView {
    Q_OBJECT
public:
    explicit MapView(QGraphicsScene* scene, QWidget* parent = nullptr);

    // The tool receiving mouse and key input (not owned); null for none.
    void setTool(AbstractTool* tool);
    AbstractTool* tool() const { return m_tool; }

    // Scene metres per screen pixel (Web Mercator metres, not ground metres).
    double metresPerPixel() const;
    // Ground metres per screen pixel at the view centre, along the geodesic.
    double groundMetresPerPixel() const;
    void zoomBy(double factor);
    void zoomBy(double factor, const QPoint& anchorViewPos);
    void centreOn(const geo::LonLat& p);
    // Shows the scene rectangle with a margin of `marginPx` pixels.
    void fitSceneRect(const QRectF& rect, int marginPx = 40);
    geo::LonLat centreLonLat() const;
    QPointF sceneCentre() const;
    // Sets the view: scene point at the viewport's centre and scene metres per pixel.
    void applyView(const QPointF& centre, double metresPerPixel);

    bool graticuleVisible() const { return m_graticule; }
    void setGraticuleVisible(bool on);
    void setAttribution(const QString& text);

signals:
    void cursorMoved(const geo::LonLat& p);
    void cursorLeft();
    void viewChanged();
    // Files dropped on the map (the main window imports them), terrain models left out.
    void filesDropped(const QStringList& paths);
    // A terrain model (DEM) dropped on the map (terrain::Dem::looksLikeDem): it becomes the
    // mission's, as File > Terrain model does.
    void demDropped(const QString& path);

protected:
    void wheelEvent(QWheelEvent* e) override;
    void mousePressEvent(QMouseEvent* e) override;
    void mouseMoveEvent(QMouseEvent* e) override;
    void mouseReleaseEvent(QMouseEvent* e) override;
    void mouseDoubleClickEvent(QMouseEvent* e) override;
    void keyPressEvent(QKeyEvent* e) override;
    void keyReleaseEvent(QKeyEvent* e) override;
    void leaveEvent(QEvent* e) override;
    void scrollContentsBy(int dx, int dy) override;
    void resizeEvent(QResizeEvent* e) override;
    void drawForeground(QPainter* painter, const QRectF& rect) override;
    void dragEnterEvent(QDragEnterEvent* e) override;
    void dragMoveEvent(QDragMoveEvent* e) override;
    void dropEvent(QDropEvent* e) override;

private:
    void drawGraticule(QPainter* painter);
    void drawScaleBar(QPainter* painter);
    void drawAttribution(QPainter* painter);
    bool wantsPan(QMouseEvent* e) const;

    AbstractTool* m_tool = nullptr;
    bool m_panning = false;
    bool m_spaceHeld = false;
    QPoint m_lastPanPos;
    QPointF m_centre;
    bool m_graticule = true;
    QString m_attribution;
};

} // namespace pf::ui
