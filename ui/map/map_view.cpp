#include "ui/map/map_view.h"

#include "core/geo/geodesic.h"
#include "core/terrain/dem.h"
#include "ui/geo_adapter.h"
#include "ui/map/web_mercator.h"
#include "ui/tools/abstract_tool.h"

#include <QKeyEvent>
#include <QMimeData>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QResizeEvent>
#include <QScrollBar>
#include <QWheelEvent>

#include <cmath>

namespace pf::ui {

namespace {
constexpr double kMinMetresPerPixel = 0.01;   // closest zoom
constexpr double kMaxMetresPerPixel = 80000.0; // whole world

// A "nice" number (1, 2 or 5 times a power of ten) not larger than x.
double niceFloor(double x) {
    const double p = std::pow(10.0, std::floor(std::log10(x)));
    const double m = x / p;
    return (m >= 5 ? 5 : m >= 2 ? 2 : 1) * p;
}

QString formatDistance(double m) {
    if (m >= 1000) return QStringLiteral("%1 km").arg(m / 1000.0, 0, 'g', 3);
    if (m >= 1) return QStringLiteral("%1 m").arg(m, 0, 'g', 3);
    return QStringLiteral("%1 cm").arg(m * 100.0, 0, 'g', 3);
}

void drawHaloText(QPainter* p, const QPointF& at, const QString& text, const QColor& colour) {
    QPainterPath path;
    path.addText(at, p->font(), text);
    p->setPen(QPen(QColor(255, 255, 255, 210), 3.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    p->setBrush(Qt::NoBrush);
    p->drawPath(path);
    p->setPen(Qt::NoPen);
    p->setBrush(colour);
    p->drawPath(path);
}
} // namespace

MapView::MapView(QGraphicsScene* scene, QWidget* parent) : QGraphicsView(scene, parent) {
    const double h = mercator::kHalfWorld;
    scene->setSceneRect(-h, -h, 2 * h, 2 * h);
    m_centre = QPointF(0, 0);
    setTransformationAnchor(QGraphicsView::NoAnchor);
    setAlignment(Qt::AlignLeft | Qt::AlignTop); // with the exact scene rectangle: no rounding
    setResizeAnchor(QGraphicsView::AnchorViewCenter);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    setRenderHints(QPainter::Antialiasing | QPainter::SmoothPixmapTransform | QPainter::TextAntialiasing);
    setViewportUpdateMode(QGraphicsView::FullViewportUpdate); // foreground overlays move with every scroll
    setMouseTracking(true);
    setDragMode(QGraphicsView::NoDrag);
    setBackgroundBrush(QColor(226, 228, 222));
    setFrameShape(QFrame::NoFrame);
    setAcceptDrops(true);
    setFocusPolicy(Qt::StrongFocus);
    applyView(m_centre, 1000.0);
}

void MapView::setTool(AbstractTool* tool) {
    if (m_tool) m_tool->deactivate(this);
    m_tool = tool;
    if (m_tool) m_tool->activate(this);
}

double MapView::metresPerPixel() const { return 1.0 / transform().m11(); }

double MapView::groundMetresPerPixel() const {
    const QPointF c = m_centre;
    const double half = 50.0 * metresPerPixel();
    return geo::geodesicDistance(fromScene(c - QPointF(half, 0)), fromScene(c + QPointF(half, 0))) / 100.0;
}

void MapView::zoomBy(double factor) { zoomBy(factor, viewport()->rect().center()); }

void MapView::zoomBy(double factor, const QPoint& anchor) {
    const double target = std::clamp(metresPerPixel() / factor, kMinMetresPerPixel, kMaxMetresPerPixel);
    // Keep the scene point under the anchor fixed.
    const QPointF under = mapToScene(anchor);
    const QPointF offset = QPointF(anchor) - QPointF(viewport()->width() / 2.0, viewport()->height() / 2.0);
    applyView(under - offset * target, target);
}

void MapView::applyView(const QPointF& centre, double mpp) {
    mpp = std::clamp(mpp, kMinMetresPerPixel, kMaxMetresPerPixel);
    setTransform(QTransform::fromScale(1.0 / mpp, 1.0 / mpp));
    // QGraphicsView scrolls with int scroll bars: a world-wide scene rectangle would overflow them at
    // close zoom. So the view's own scene rectangle is just the visible area (a hair smaller, so it
    // never needs scrolling); the view still places it on whole pixels, so the centre is exact to
    // within a pixel.
    const double w = std::max(1, viewport()->width()) * mpp;
    const double h = std::max(1, viewport()->height()) * mpp;
    const double eps = 0.01 * mpp;
    QGraphicsView::setSceneRect(QRectF(centre.x() - w / 2, centre.y() - h / 2, w - eps, h - eps));
    m_centre = centre;
    emit viewChanged();
}

void MapView::resizeEvent(QResizeEvent* e) {
    QGraphicsView::resizeEvent(e);
    applyView(m_centre, metresPerPixel());
}

QPointF MapView::sceneCentre() const { return m_centre; }

void MapView::centreOn(const geo::LonLat& p) { applyView(toScene(p), metresPerPixel()); }

geo::LonLat MapView::centreLonLat() const { return fromScene(m_centre); }

void MapView::fitSceneRect(const QRectF& rect, int marginPx) {
    if (rect.isEmpty()) return;
    const QSize vp = viewport()->size();
    const double sx = (vp.width() - 2 * marginPx) / rect.width();
    const double sy = (vp.height() - 2 * marginPx) / rect.height();
    const double s = std::max(1e-9, std::min(sx, sy));
    applyView(rect.center(), 1.0 / s);
}

void MapView::setGraticuleVisible(bool on) {
    m_graticule = on;
    viewport()->update();
}

void MapView::setAttribution(const QString& text) {
    m_attribution = text;
    viewport()->update();
}

void MapView::wheelEvent(QWheelEvent* e) {
    const double steps = e->angleDelta().y() / 120.0;
    zoomBy(std::pow(1.25, steps), e->position().toPoint());
    e->accept();
}

bool MapView::wantsPan(QMouseEvent* e) const {
    return e->button() == Qt::MiddleButton ||
           (e->button() == Qt::LeftButton && (m_spaceHeld || !m_tool || m_tool->pansWithLeftButton()));
}

void MapView::mousePressEvent(QMouseEvent* e) {
    setFocus();
    if (wantsPan(e)) {
        m_panning = true;
        m_lastPanPos = e->pos();
        viewport()->setCursor(Qt::ClosedHandCursor);
        e->accept();
        return;
    }
    if (m_tool) m_tool->mousePressed(e, mapToScene(e->pos()));
}

void MapView::mouseMoveEvent(QMouseEvent* e) {
    const QPointF scenePos = mapToScene(e->pos());
    emit cursorMoved(fromScene(scenePos));
    if (m_panning) {
        const QPoint d = e->pos() - m_lastPanPos;
        m_lastPanPos = e->pos();
        applyView(m_centre - QPointF(d) * metresPerPixel(), metresPerPixel());
        return;
    }
    if (m_tool) m_tool->mouseMoved(e, scenePos);
}

void MapView::mouseReleaseEvent(QMouseEvent* e) {
    if (m_panning && (e->button() == Qt::MiddleButton || e->button() == Qt::LeftButton)) {
        m_panning = false;
        viewport()->setCursor(m_tool ? m_tool->cursor() : QCursor(Qt::OpenHandCursor));
        return;
    }
    if (m_tool) m_tool->mouseReleased(e, mapToScene(e->pos()));
}

void MapView::mouseDoubleClickEvent(QMouseEvent* e) {
    if (m_tool && e->button() == Qt::LeftButton) m_tool->mouseDoubleClicked(e, mapToScene(e->pos()));
}

void MapView::keyPressEvent(QKeyEvent* e) {
    if (m_tool && m_tool->keyPressed(e)) return;
    const double pan = 100.0 * metresPerPixel();
    const QPointF c = m_centre;
    const double mpp = metresPerPixel();
    switch (e->key()) {
    case Qt::Key_Plus:
    case Qt::Key_Equal:
        zoomBy(1.5);
        return;
    case Qt::Key_Minus:
        zoomBy(1.0 / 1.5);
        return;
    case Qt::Key_Left:
        applyView(c - QPointF(pan, 0), mpp);
        return;
    case Qt::Key_Right:
        applyView(c + QPointF(pan, 0), mpp);
        return;
    case Qt::Key_Up:
        applyView(c - QPointF(0, pan), mpp);
        return;
    case Qt::Key_Down:
        applyView(c + QPointF(0, pan), mpp);
        return;
    case Qt::Key_Space:
        if (!e->isAutoRepeat()) {
            m_spaceHeld = true;
            viewport()->setCursor(Qt::OpenHandCursor);
        }
        return;
    default:
        QGraphicsView::keyPressEvent(e);
    }
}

void MapView::keyReleaseEvent(QKeyEvent* e) {
    if (e->key() == Qt::Key_Space && !e->isAutoRepeat()) {
        m_spaceHeld = false;
        viewport()->setCursor(m_tool ? m_tool->cursor() : QCursor(Qt::ArrowCursor));
        return;
    }
    QGraphicsView::keyReleaseEvent(e);
}

void MapView::leaveEvent(QEvent* e) {
    emit cursorLeft();
    QGraphicsView::leaveEvent(e);
}

void MapView::scrollContentsBy(int dx, int dy) {
    QGraphicsView::scrollContentsBy(dx, dy);
    viewport()->update();
}

void MapView::dragEnterEvent(QDragEnterEvent* e) {
    if (e->mimeData()->hasUrls()) e->acceptProposedAction();
}

void MapView::dragMoveEvent(QDragMoveEvent* e) {
    if (e->mimeData()->hasUrls()) e->acceptProposedAction();
}

void MapView::dropEvent(QDropEvent* e) {
    QStringList paths;
    for (const QUrl& url : e->mimeData()->urls())
        if (url.isLocalFile()) paths << url.toLocalFile();
    if (paths.isEmpty()) return;
    e->acceptProposedAction();
    QStringList others;
    for (const QString& p : paths)
        if (terrain::Dem::looksLikeDem(p.toStdString())) emit demDropped(p);
        else others << p;
    if (!others.isEmpty()) emit filesDropped(others);
}

void MapView::drawForeground(QPainter* painter, const QRectF&) {
    painter->save();
    painter->resetTransform();
    painter->setRenderHint(QPainter::Antialiasing);
    if (m_graticule) drawGraticule(painter);
    drawScaleBar(painter);
    drawAttribution(painter);
    painter->restore();
}

void MapView::drawGraticule(QPainter* p) {
    const QRect vp = viewport()->rect();
    const QPointF tl = mercator::toLonLat(mapToScene(vp.topLeft()));
    const QPointF br = mercator::toLonLat(mapToScene(vp.bottomRight()));
    // About one line per 180 px: step in degrees of longitude from the view's width.
    const double degPerPx = (br.x() - tl.x()) / std::max(1, vp.width());
    const double step = niceFloor(std::max(1e-6, degPerPx * 180.0));
    const int decimals = std::max(0, int(std::ceil(-std::log10(step))));
    QFont f = font();
    f.setPointSizeF(7.5);
    p->setFont(f);
    const QPen line(QColor(255, 255, 255, 90), 1.0, Qt::DashLine);
    for (double lon = std::ceil(tl.x() / step) * step; lon <= br.x(); lon += step) {
        const double x = mapFromScene(mercator::toScene(lon, 0)).x();
        p->setPen(line);
        p->drawLine(QPointF(x, 0), QPointF(x, vp.height()));
        drawHaloText(p, QPointF(x + 3, 11), QStringLiteral("%1°").arg(lon, 0, 'f', decimals), QColor(40, 40, 40));
    }
    for (double lat = std::ceil(br.y() / step) * step; lat <= tl.y(); lat += step) {
        const double y = mapFromScene(mercator::toScene(0, lat)).y();
        p->setPen(line);
        p->drawLine(QPointF(0, y), QPointF(vp.width(), y));
        drawHaloText(p, QPointF(3, y - 3), QStringLiteral("%1°").arg(lat, 0, 'f', decimals), QColor(40, 40, 40));
    }
}

void MapView::drawScaleBar(QPainter* p) {
    const double mpp = groundMetresPerPixel();
    if (!(mpp > 0) || !std::isfinite(mpp)) return;
    const double length = niceFloor(150.0 * mpp);
    const double px = length / mpp;
    const QRect vp = viewport()->rect();
    const QPointF origin(16, vp.height() - 18);
    p->setPen(Qt::NoPen);
    p->setBrush(QColor(255, 255, 255, 200));
    p->drawRoundedRect(QRectF(origin.x() - 8, origin.y() - 22, px + 16, 30), 4, 4);
    // Two-tone bar, halves alternating, the classic cartographic scale bar.
    const double h = 5;
    p->setPen(QPen(QColor(30, 30, 30), 1));
    p->setBrush(QColor(30, 30, 30));
    p->drawRect(QRectF(origin.x(), origin.y(), px / 2, h));
    p->setBrush(Qt::white);
    p->drawRect(QRectF(origin.x() + px / 2, origin.y(), px / 2, h));
    QFont f = font();
    f.setPointSizeF(8);
    p->setFont(f);
    p->setPen(QColor(30, 30, 30));
    p->drawText(QPointF(origin.x(), origin.y() - 5), QStringLiteral("0"));
    const QString label = formatDistance(length);
    p->drawText(QPointF(origin.x() + px - p->fontMetrics().horizontalAdvance(label) / 2.0, origin.y() - 5), label);
}

void MapView::drawAttribution(QPainter* p) {
    if (m_attribution.isEmpty()) return;
    QFont f = font();
    f.setPointSizeF(7.5);
    p->setFont(f);
    const QRect vp = viewport()->rect();
    const int w = p->fontMetrics().horizontalAdvance(m_attribution) + 12;
    const QRectF r(vp.width() - w, vp.height() - 18, w, 18);
    p->setPen(Qt::NoPen);
    p->setBrush(QColor(255, 255, 255, 200));
    p->drawRect(r);
    p->setPen(QColor(40, 40, 40));
    p->drawText(r, Qt::AlignCenter, m_attribution);
}

} // namespace pf::ui
