// Autosave: periodic and after-edit copies of the open mission, and their recovery after a crash.
#pragma once

#include <QDateTime>
#include <QObject>
#include <QTimer>

namespace pf::ui {

class MissionDocument;

class Autosave : public QObject {
    Q_OBJECT
public:
    // `dir` defaults to <AppDataLocation>/autosave. Copies are written `debounceMs` after an edit and
    // every `periodMs` while the document has unsaved changes.
    Autosave(MissionDocument* doc, QString dir = {}, int periodMs = 60000, int debounceMs = 3000,
             QObject* parent = nullptr);
    ~Autosave() override;

    QString directory() const { return m_dir; }
    // The file this session writes to.
    QString filePath() const;

    struct Recovery {
        QString autosavePath; // the autosaved mission
        QString originalPath; // the file it was opened from, empty for an unsaved mission
        QDateTime savedAt;
    };
    // Copies left by a session that did not exit cleanly (newest first), excluding this session's own.
    QList<Recovery> leftovers() const;
    // Opens a leftover in the document (marked as modified) and deletes it.
    bool recover(const Recovery& r, QString* error);
    void discard(const Recovery& r);

    // Writes a copy now if the document has unsaved changes; removes it when there are none.
    void writeNow();
    // Called on a clean exit: nothing to recover next time.
    void removeOwn();

private:
    MissionDocument* m_doc;
    QString m_dir;
    QTimer m_debounce;
    QTimer m_period;
};

} // namespace pf::ui
