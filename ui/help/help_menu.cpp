#include "ui/help/help_menu.h"

#include "ui/help/help_browser.h"
#include "ui/help/shortcuts_dialog.h"

#include <QAction>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPointer>
#include <QWhatsThis>

#include <memory>

namespace pf::ui {

QMenu* addHelpMenu(QMainWindow* window) {
    QMenu* help = window->menuBar()->addMenu(QObject::tr("&Help"));
    help->setObjectName(QStringLiteral("HelpMenu"));

    // One guide window, raised again when it is already open.
    auto guide = std::make_shared<QPointer<HelpBrowser>>();
    QAction* userGuide = help->addAction(QObject::tr("&User guide"), window, [window, guide] {
        if (!*guide) {
            *guide = new HelpBrowser(window);
            (*guide)->setAttribute(Qt::WA_DeleteOnClose);
        }
        (*guide)->show();
        (*guide)->raise();
        (*guide)->activateWindow();
    });
    userGuide->setShortcut(QKeySequence::HelpContents);
    userGuide->setObjectName(QStringLiteral("UserGuideAction"));

    QAction* keys = help->addAction(QObject::tr("&Keyboard shortcuts"), window, [window] {
        ShortcutsDialog dialog(window->menuBar(), window);
        dialog.exec();
    });
    keys->setObjectName(QStringLiteral("KeyboardShortcutsAction"));

    QAction* whatsThis = QWhatsThis::createAction(help);
    whatsThis->setText(QObject::tr("What's &this?"));
    help->addAction(whatsThis);

    help->addSeparator();
    help->addAction(QObject::tr("&About Photoflight"), window, [window] {
        QMessageBox::about(
            window, QObject::tr("About Photoflight"),
            QObject::tr(
                "<b>Photoflight %1</b><br>Photo-survey flight planning for one or several "
                "UAVs.<br><br>"
                "Released under the Apache License 2.0.<br>"
                "The demo map is synthetic: it is drawn by the program and shows no real place.")
                .arg(QStringLiteral(PF_VERSION)));
    });
    return help;
}

} // namespace pf::ui
