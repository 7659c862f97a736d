// MainWindow: the application's main window: map area, menus, panels.
#pragma once

#include <QMainWindow>

namespace pf::ui {

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
};

} // namespace pf::ui
