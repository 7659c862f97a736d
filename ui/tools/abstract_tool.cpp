#include "ui/tools/abstract_tool.h"

#include "ui/map/map_view.h"

namespace pf::ui {

AbstractTool::AbstractTool(const QString& name, const QIcon& icon, const QKeySequence& shortcut,
                           MissionDocument* doc, MissionLayer* layer, QObject* parent)
    : QObject(parent), m_doc(doc), m_layer(layer), m_name(name), m_icon(icon), m_shortcut(shortcut) {}

void AbstractTool::activate(MapView* view) {
    m_view = view;
    view->viewport()->setCursor(cursor());
    emit statusMessage(hint());
}

void AbstractTool::deactivate(MapView* view) {
    view->viewport()->unsetCursor();
    m_view = nullptr;
}

double AbstractTool::pixelsToScene(double px) const { return m_view ? px * m_view->metresPerPixel() : px; }

} // namespace pf::ui
