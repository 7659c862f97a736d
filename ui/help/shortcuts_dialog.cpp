#include "ui/help/shortcuts_dialog.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QMenu>
#include <QMenuBar>
#include <QTableWidget>
#include <QVBoxLayout>

#include <vector>

namespace pf::ui {
namespace {

struct Row {
    QString where;
    QString what;
    QString keys;
};

QString plainText(QString s) {
    s.remove(QLatin1Char('&'));
    s.remove(QStringLiteral("…"));
    return s.trimmed();
}

// Every action with a shortcut under `menu`, submenus included ("File ▸ Terrain").
void collect(const QMenu* menu, const QString& path, std::vector<Row>& rows) {
    for (const QAction* a : menu->actions()) {
        if (a->menu()) {
            collect(a->menu(), path + QStringLiteral(" ▸ ") + plainText(a->text()), rows);
            continue;
        }
        if (a->isSeparator())
            continue;
        QStringList keys;
        for (const QKeySequence& k : a->shortcuts())
            keys << k.toString(QKeySequence::NativeText);
        if (!keys.isEmpty())
            rows.push_back({path, plainText(a->text()), keys.join(QStringLiteral(", "))});
    }
}

// Keys handled by the map and its tools rather than by menu actions (ui/map/map_view.cpp,
// ui/tools/): kept here beside the menu list so the dialog names every key the program knows.
std::vector<Row> mapKeys() {
    const QString map = QObject::tr("Map");
    return {
        {map, QObject::tr("Zoom in / out"), QStringLiteral("+ / -")},
        {map, QObject::tr("Pan the map"), QObject::tr("Arrow keys; or hold Space and drag")},
        {map, QObject::tr("Finish the polygon being drawn"), QObject::tr("Enter, or double-click")},
        {map, QObject::tr("Remove the last vertex drawn"), QObject::tr("Backspace")},
        {map, QObject::tr("Cancel drawing, or clear the selection"), QObject::tr("Esc")},
        {map, QObject::tr("Delete the selected vertex, shape or waypoints"),
         QObject::tr("Delete or Backspace")},
    };
}

} // namespace

ShortcutsDialog::ShortcutsDialog(const QMenuBar* menus, QWidget* parent) : QDialog(parent) {
    setWindowTitle(tr("Keyboard shortcuts"));
    setObjectName(QStringLiteral("ShortcutsDialog"));
    std::vector<Row> rows;
    for (const QAction* top : menus->actions())
        if (top->menu())
            collect(top->menu(), plainText(top->text()), rows);
    for (const Row& r : mapKeys())
        rows.push_back(r);

    m_table = new QTableWidget(int(rows.size()), 3, this);
    m_table->setHorizontalHeaderLabels({tr("Where"), tr("Action"), tr("Keys")});
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    for (int i = 0; i < int(rows.size()); ++i) {
        m_table->setItem(i, 0, new QTableWidgetItem(rows[std::size_t(i)].where));
        m_table->setItem(i, 1, new QTableWidgetItem(rows[std::size_t(i)].what));
        m_table->setItem(i, 2, new QTableWidgetItem(rows[std::size_t(i)].keys));
    }
    m_table->resizeColumnsToContents();
    m_table->horizontalHeader()->setStretchLastSection(true);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_table);
    layout->addWidget(buttons);
    resize(720, 560);
}

} // namespace pf::ui
