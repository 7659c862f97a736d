// The Help menu: the user guide (offline), the keyboard shortcuts, "What's this?" and About.
#pragma once

class QMainWindow;
class QMenu;

namespace pf::ui {

// Adds the Help menu to `window`'s menu bar (call it after the other menus, so the shortcut list
// sees every menu).
QMenu* addHelpMenu(QMainWindow* window);

} // namespace pf::ui
