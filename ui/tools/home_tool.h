// HomeTool: set the take-off/landing point with a click.
#pragma once

#include "ui/tools/abstract_tool.h"

namespace pf::ui {

class HomeTool : public AbstractTool {
    Q_OBJECT
public:
    HomeTool(MissionDocument* doc, MissionLayer* layer, QObject* parent = nullptr);
    QString hint() const override;
    QCursor cursor() const override { return Qt::CrossCursor; }
    void mousePressed(QMouseEvent* e, const QPointF& scenePos) override;
};

} // namespace pf::ui
