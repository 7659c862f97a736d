#include "ui/main_window.h"

#include <QApplication>
#include <QLabel>
#include <QMenuBar>

namespace pf::ui {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setWindowTitle(tr("Photoflight"));
    auto* map = new QLabel(tr("Map"), this);
    map->setAlignment(Qt::AlignCenter);
    setCentralWidget(map);
    auto* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&Quit"), qApp, &QApplication::quit, QKeySequence::Quit);
    menuBar()->addMenu(tr("&Edit"));
    menuBar()->addMenu(tr("&View"));
    menuBar()->addMenu(tr("&Help"));
    resize(1280, 800);
}

} // namespace pf::ui
