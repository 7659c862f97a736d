#include "ui/tools/pan_tool.h"

namespace pf::ui {

PanTool::PanTool(MissionDocument* doc, MissionLayer* layer, QObject* parent)
    : AbstractTool(tr("Pan"), QIcon(QStringLiteral(":/icons/pan.svg")), QKeySequence(Qt::Key_P), doc, layer, parent) {}

QString PanTool::hint() const { return tr("Drag to move the map; the wheel or +/- zooms."); }

} // namespace pf::ui
