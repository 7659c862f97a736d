#include "ui/tools/home_tool.h"

#include "ui/commands/set_home_command.h"
#include "ui/geo_adapter.h"
#include "ui/mission_document.h"

#include <QMouseEvent>

namespace pf::ui {

HomeTool::HomeTool(MissionDocument* doc, MissionLayer* layer, QObject* parent)
    : AbstractTool(tr("Set home point"), QIcon(QStringLiteral(":/icons/home.svg")), QKeySequence(Qt::Key_H), doc,
                   layer, parent) {}

QString HomeTool::hint() const { return tr("Click where the aircraft take off and land."); }

void HomeTool::mousePressed(QMouseEvent* e, const QPointF& p) {
    if (e->button() != Qt::LeftButton) return;
    m_doc->undoStack()->push(new SetHomeCommand(m_doc, fromScene(p)));
}

} // namespace pf::ui
