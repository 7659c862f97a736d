// WindowShortcutGuard: keeps a window's own shortcuts (Ctrl+E, Plan > Export) working while one of
// its text fields or spin boxes has the focus.
#pragma once

#include <QObject>

class QWidget;

namespace pf::ui {

class WindowShortcutGuard : public QObject {
    Q_OBJECT
public:
    // Watches every event of the application for `window`'s fields; owned by `window`.
    explicit WindowShortcutGuard(QWidget* window);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    QWidget* m_window;
};

} // namespace pf::ui
