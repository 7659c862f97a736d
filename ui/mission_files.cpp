#include "ui/mission_files.h"

#include <QCoreApplication>
#include <QFileDialog>

namespace pf::ui {

QString missionExtension() { return QStringLiteral(".json"); }

QString missionFilter() {
    return QCoreApplication::translate("MainWindow", "Photoflight missions (*.json);;All files (*)");
}

QString withMissionExtension(const QString& path) {
    if (path.isEmpty() || path.endsWith(missionExtension(), Qt::CaseInsensitive)) return path;
    return path + missionExtension();
}

QString askMissionSavePath(QWidget* parent, const QString& title, const QString& start) {
    QFileDialog dialog(parent, title, start, missionFilter());
    dialog.setObjectName(QStringLiteral("MissionSaveDialog"));
    dialog.setAcceptMode(QFileDialog::AcceptSave);
    dialog.setDefaultSuffix(missionExtension().mid(1));
    if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty()) return {};
    return withMissionExtension(dialog.selectedFiles().first());
}

QString askMissionOpenPath(QWidget* parent, const QString& title) {
    QFileDialog dialog(parent, title, QString(), missionFilter());
    dialog.setObjectName(QStringLiteral("MissionOpenDialog"));
    dialog.setAcceptMode(QFileDialog::AcceptOpen);
    dialog.setFileMode(QFileDialog::ExistingFile);
    if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty()) return {};
    return dialog.selectedFiles().first();
}

} // namespace pf::ui
