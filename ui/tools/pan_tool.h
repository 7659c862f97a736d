// PanTool: the left button drags the map (the middle button and Space+drag pan with every tool).
#pragma once

#include "ui/tools/abstract_tool.h"

namespace pf::ui {

class PanTool : public AbstractTool {
    Q_OBJECT
public:
    PanTool(MissionDocument* doc, MissionLayer* layer, QObject* parent = nullptr);
    QString hint() const override;
    QCursor cursor() const override { return Qt::OpenHandCursor; }
    bool pansWithLeftButton() const override { return true; }
};

} // namespace pf::ui
