// Mission files: the extension every saved mission gets, the dialogs, and MissionFiles, the window's
// work on files: what opens at start, open, save, recent files, import of areas and waypoint files.
#pragma once

#include <QObject>
#include <QString>

class QMainWindow;
class QMenu;
class QWidget;

namespace pf::ui {

class Autosave;
class MissionDocument;

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

// How a window tells of a failure: a warning dialog, or (not interactive: tests, --screenshot) its
// status bar.
void reportError(QMainWindow* window, bool interactive, const QString& title, const QString& message);

// How imported polygons are used when the mission has an area already.
enum class ImportRole { Ask, Area, NoFlyZones };

class MissionFiles : public QObject {
    Q_OBJECT
public:
    // `interactive` false: no dialog is ever shown; errors and questions' defaults go to the status bar.
    MissionFiles(QMainWindow* window, MissionDocument* doc, Autosave* autosave, bool interactive);

    // What to show at start: a recovered autosave (asks), the given mission, the last one, or on
    // first start the demo.
    void startup(const QString& missionPath);
    bool openMission(const QString& path, QString* error = nullptr);
    bool openDemoMission(QString* error = nullptr);
    bool saveMission(const QString& path, QString* error = nullptr);
    void newMission();
    // Asks whether to save unsaved changes (interactive windows); false when the user cancels.
    bool maybeSave();
    // Imports polygons: with no area yet, the largest becomes the area and the others no-fly zones;
    // otherwise the user is asked (Ask) or `role` decides. One undo step. Returns polygons imported.
    int importAreas(const QString& path, ImportRole role = ImportRole::Ask, QString* error = nullptr);
    // Reads an exported (and maybe edited) waypoint file and puts its routes beside the mission:
    // route k of the file goes to the document's route `assignTo + k` (-1: matched by aircraft name or
    // file name, else asked, else appended). One undo step. Returns the number of routes loaded.
    int openWaypointFile(const QString& path, int assignTo = -1, QString* error = nullptr);
    // The recent missions, newest first, into `menu` (replacing what it held).
    void fillRecentMenu(QMenu* menu);

    // The File menu's commands: each asks what it needs (save the changes first? which file?).
    void askNewMission();
    void askOpenMission();
    void askOpenDemoMission();
    void save();
    void saveAs();
    void askImportAreas();
    void askOpenWaypointFile();

signals:
    // A mission was opened, recovered, or imported into an empty document: show all of it.
    void missionShown();

private:
    void addRecentFile(const QString& path);
    void showError(const QString& title, const QString& message);
    // `why` into *error (when asked for) and shown; false, what the caller then returns.
    bool fail(QString* error, const QString& title, const QString& why);
    void showStatus(const QString& message, int timeoutMs);

    QMainWindow* m_window;
    MissionDocument* m_doc;
    Autosave* m_autosave;
    bool m_interactive;
};

} // namespace pf::ui
