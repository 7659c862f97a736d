// SelectTool: select shapes, drag vertices, insert a vertex on an edge, move shapes and the home point, delete.
#pragma once

#include "ui/map/mission_layer.h"
#include "ui/tools/abstract_tool.h"

#include <memory>

namespace pf::ui {

class SelectTool : public AbstractTool {
    Q_OBJECT
public:
    SelectTool(MissionDocument* doc, MissionLayer* layer, QObject* parent = nullptr);
    ~SelectTool() override;
    QString hint() const override;

    void deactivate(MapView* view) override;
    void mousePressed(QMouseEvent* e, const QPointF& scenePos) override;
    void mouseMoved(QMouseEvent* e, const QPointF& scenePos) override;
    void mouseReleased(QMouseEvent* e, const QPointF& scenePos) override;
    void mouseDoubleClicked(QMouseEvent* e, const QPointF& scenePos) override;
    bool keyPressed(QKeyEvent* e) override;

    // Deletes the selected vertex, or the selected shape when no vertex is selected.
    void deleteSelection();

private:
    enum class Drag { None, Vertex, Shape, Home };
    void endDrag();
    void updatePreview(const QPointF& scenePos);

    Drag m_drag = Drag::None;
    ShapeRef m_dragShape;
    VertexRef m_dragVertex;
    QPointF m_pressPos;
    bool m_moved = false;
    std::unique_ptr<ShapeItem> m_preview;
    std::unique_ptr<ShapeItem> m_groundPreview; // a corridor's ground while its line is dragged
    std::unique_ptr<HomeItem> m_homePreview;
};

} // namespace pf::ui
