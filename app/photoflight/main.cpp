// photoflight: the desktop application.
#include "ui/main_window.h"

#include <QApplication>

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("Photoflight"));
    QApplication::setOrganizationName(QStringLiteral("Photoflight"));
    QApplication::setApplicationVersion(QStringLiteral(PF_VERSION));
    pf::ui::MainWindow w;
    w.show();
    return QApplication::exec();
}
