#include "ui/window_shortcut_guard.h"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QKeyEvent>
#include <QLineEdit>

namespace pf::ui {

WindowShortcutGuard::WindowShortcutGuard(QWidget* window) : QObject(window), m_window(window) {
    qApp->installEventFilter(this);
}

bool WindowShortcutGuard::eventFilter(QObject* watched, QEvent* event) {
    // A line edit (and so every spin box) claims Ctrl+E as "end of line" through a shortcut
    // override, which would silence Plan > Export while the focus is in the Aircraft dock. The
    // window's action wins; End still moves to the end of the line.
    if (event->type() == QEvent::ShortcutOverride) {
        auto* w = qobject_cast<QWidget*>(watched);
        auto* key = static_cast<QKeyEvent*>(event);
        if (w && w->window() == m_window &&
            (qobject_cast<QLineEdit*>(w) || qobject_cast<QAbstractSpinBox*>(w)) &&
            QKeySequence(int(key->modifiers()) | key->key()) ==
                QKeySequence(Qt::CTRL | Qt::Key_E)) {
            event->ignore();
            return true;
        }
    }
    return QObject::eventFilter(watched, event);
}

} // namespace pf::ui
