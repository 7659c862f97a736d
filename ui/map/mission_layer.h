// MissionLayer: the scene items showing the mission (area, no-fly zones, home), rebuilt from the document.
#pragma once

#include "ui/commands/shape_edit_command.h"
#include "ui/mission_document.h"

#include <QGraphicsItem>
#include <QObject>

#include <optional>
#include <vector>

class QGraphicsScene;

namespace pf::ui {

class ShapeItem;
class HomeItem;

enum class ShapeStyle { Area, NoFly, Preview };

// Paints a polygon (with holes) in one of the map styles; used by the layer and by tools' previews.
class ShapeItem : public QGraphicsItem {
public:
    ShapeItem(ShapeStyle style, QGraphicsItem* parent = nullptr);
    ~ShapeItem() override;
    void setRings(const QVector<QPolygonF>& rings); // scene coords; ring 0 outer
    const QVector<QPolygonF>& rings() const { return m_rings; }
    void setProblem(const QString& problem); // non-empty: drawn in the warning style
    QString problem() const { return m_problem; }
    void setLabel(const QString& label);
    // Where the label goes (scene); the middle of the bounding box when unset.
    void setLabelAnchor(std::optional<QPointF> anchor);
    void setHighlighted(bool on, std::optional<VertexRef> vertex = std::nullopt);
    void setClosed(bool closed); // previews of a polygon being drawn are open polylines
    void setHandleMargin(double sceneMetres);

    QRectF boundingRect() const override;
    QPainterPath shape() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;
    // The label is an item of its own above the flight paths, so that no path hides it.
    QGraphicsItem* labelItem() const { return m_labelItem; }

protected:
    QVariant itemChange(GraphicsItemChange change, const QVariant& value) override;

private:
    QPainterPath path() const;
    void placeLabel();
    ShapeStyle m_style;
    QGraphicsItem* m_labelItem = nullptr;
    QVector<QPolygonF> m_rings;
    QString m_problem;
    QString m_label;
    std::optional<QPointF> m_labelAnchor;
    bool m_highlighted = false;
    bool m_closed = true;
    std::optional<VertexRef> m_vertex;
    double m_margin = 0;
};

// The take-off/landing marker, drawn at a constant screen size.
class HomeItem : public QGraphicsItem {
public:
    explicit HomeItem(QGraphicsItem* parent = nullptr);
    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;
};

class MissionLayer : public QObject {
    Q_OBJECT
public:
    MissionLayer(MissionDocument* doc, QGraphicsScene* scene, QObject* parent = nullptr);
    ~MissionLayer() override;

    struct VertexHit {
        ShapeRef shape;
        VertexRef vertex;
    };
    struct EdgeHit {
        ShapeRef shape;
        VertexRef insertAt; // index the new vertex gets
        QPointF point;      // nearest point on the edge (scene)
    };
    // Hit tests in scene coordinates with a tolerance in scene metres. Selected shape first, then
    // no-fly zones (drawn on top), then the corridor's line, then the area (not with a corridor:
    // the area is then the corridor's ground, edited through its line and width).
    std::optional<VertexHit> hitVertex(const QPointF& p, double tolerance) const;
    std::optional<EdgeHit> hitEdge(const QPointF& p, double tolerance) const;
    std::optional<ShapeRef> hitShape(const QPointF& p) const;
    bool hitHome(const QPointF& p, double tolerance) const;

    std::optional<ShapeRef> selectedShape() const { return m_selected; }
    std::optional<VertexRef> selectedVertex() const { return m_selectedVertex; }
    void select(std::optional<ShapeRef> shape, std::optional<VertexRef> vertex = std::nullopt);

    // Scene rings of a shape of the document (ring 0 outer).
    QVector<QPolygonF> sceneRings(const ShapeRef& ref) const;
    // Bounding rectangle of everything in the mission, in scene coordinates (empty if nothing).
    QRectF missionBounds() const;
    // Hides a shape while a tool shows its own preview of it being dragged.
    void setShapeHidden(const ShapeRef& ref, bool hidden);
    void setHomeHidden(bool hidden);
    // Problems of the current shapes in words ("Area: edges cross ..."); empty when all are valid.
    QStringList problems() const { return m_problems; }
    // Handles and labels are sized in screen pixels: the layer must know the zoom.
    void setMetresPerPixel(double mpp);

    ShapeItem* itemFor(const ShapeRef& ref) const;

signals:
    void selectionChanged();
    void problemsChanged(const QStringList& problems);

private:
    void rebuild();
    void applySelection();

    MissionDocument* m_doc;
    QGraphicsScene* m_scene;
    ShapeItem* m_area = nullptr;
    ShapeItem* m_corridorLine = nullptr; // the corridor's centre line over its ground (m_area)
    std::vector<ShapeItem*> m_noFly;
    HomeItem* m_home = nullptr;
    std::optional<ShapeRef> m_selected;
    std::optional<VertexRef> m_selectedVertex;
    QStringList m_problems;
    double m_mpp = 1.0;
};

} // namespace pf::ui
