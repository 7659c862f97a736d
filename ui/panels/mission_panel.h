// MissionPanel: a summary of the open mission (area or corridor, no-fly zones, home) with selection
// of its shapes, and the corridor's width.
#pragma once

#include <QWidget>

class QDoubleSpinBox;
class QLabel;
class QListWidget;

namespace pf::ui {

class MissionDocument;
class MissionLayer;

class MissionPanel : public QWidget {
    Q_OBJECT
public:
    MissionPanel(MissionDocument* doc, MissionLayer* layer, QWidget* parent = nullptr);

signals:
    // The user picked a shape in the list: the map centres on it.
    void shapeActivated(const QRectF& sceneBounds);

private:
    void refresh();

    MissionDocument* m_doc;
    MissionLayer* m_layer;
    QLabel* m_summary;
    QListWidget* m_shapes;
    QLabel* m_problems;
    QDoubleSpinBox* m_width; // the corridor's width (or the next one drawn), one undo step per edit
};

} // namespace pf::ui
