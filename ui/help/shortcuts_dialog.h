// Help > Keyboard shortcuts: every menu action that has a shortcut, read from the menus
// themselves (so the list cannot drift from the program), and the keys the map understands.
#pragma once

#include <QDialog>

class QMenuBar;
class QTableWidget;

namespace pf::ui {

class ShortcutsDialog : public QDialog {
    Q_OBJECT
public:
    ShortcutsDialog(const QMenuBar* menus, QWidget* parent = nullptr);
    QTableWidget* table() const { return m_table; }

private:
    QTableWidget* m_table = nullptr;
};

} // namespace pf::ui
