// Mission file names and dialogs: the extension every saved mission gets and the filters that show
// every mission file.
#pragma once

#include <QString>

class QWidget;

namespace pf::ui {

// ".json": what Photoflight writes and the bundled missions use.
QString missionExtension();
// "Photoflight missions (*.json);;All files (*)": the first filter is the dialogs' default.
QString missionFilter();
// `path` with the mission extension appended when it has another one or none ("incident_site" ->
// "incident_site.json"); empty stays empty.
QString withMissionExtension(const QString& path);
// The save dialog (object name "MissionSaveDialog"): the name typed gets the mission extension.
// Empty when cancelled.
QString askMissionSavePath(QWidget* parent, const QString& title, const QString& start);
// The open dialog (object name "MissionOpenDialog"), on the mission filter. Empty when cancelled.
QString askMissionOpenPath(QWidget* parent, const QString& title);

} // namespace pf::ui
