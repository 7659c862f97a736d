#include "ui/autosave.h"

#include "ui/mission_document.h"

#include "core/io/mission_file.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSaveFile>
#include <QStandardPaths>

#include <algorithm>

namespace pf::ui {

namespace {
QString originOf(const QString& autosavePath) {
    QFile f(autosavePath + QStringLiteral(".origin"));
    if (!f.open(QIODevice::ReadOnly)) return {};
    return QString::fromUtf8(f.readAll()).trimmed();
}
} // namespace

Autosave::Autosave(MissionDocument* doc, QString dir, int periodMs, int debounceMs, QObject* parent)
    : QObject(parent), m_doc(doc), m_dir(std::move(dir)) {
    if (m_dir.isEmpty())
        m_dir = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/autosave");
    QDir().mkpath(m_dir);
    m_debounce.setSingleShot(true);
    m_debounce.setInterval(debounceMs);
    m_period.setInterval(periodMs);
    connect(&m_debounce, &QTimer::timeout, this, &Autosave::writeNow);
    connect(&m_period, &QTimer::timeout, this, &Autosave::writeNow);
    connect(doc, &MissionDocument::changed, this, [this] { m_debounce.start(); });
    // A hand edit of a route is not a `changed` (it must not trigger a new plan) but must be saved.
    connect(doc, &MissionDocument::routesChanged, this, [this] { m_debounce.start(); });
    connect(doc, &MissionDocument::dirtyChanged, this, [this](bool dirty) {
        if (!dirty) removeOwn(); // saved: the file on disk is the latest state
    });
    m_period.start();
}

Autosave::~Autosave() = default;

QString Autosave::filePath() const {
    // One file per running process, so two open windows never overwrite each other's copy.
    return QDir(m_dir).filePath(QStringLiteral("mission-%1.json").arg(QCoreApplication::applicationPid()));
}

void Autosave::writeNow() {
    if (!m_doc->isDirty()) {
        removeOwn();
        return;
    }
    // The origin (which file this is a copy of) goes first: a kill between the two writes then leaves
    // a copy that still knows where it belongs, never one recovered as an unnamed mission.
    QSaveFile origin(filePath() + QStringLiteral(".origin"));
    if (origin.open(QIODevice::WriteOnly)) {
        origin.write(m_doc->filePath().toUtf8());
        origin.commit();
    }
    QString error;
    m_doc->writeCopy(filePath(), &error); // on failure the next edit or tick tries again
}

void Autosave::removeOwn() {
    QFile::remove(filePath());
    QFile::remove(filePath() + QStringLiteral(".origin"));
}

QList<Autosave::Recovery> Autosave::leftovers() const {
    QList<Recovery> out;
    const QDir dir(m_dir);
    for (const QFileInfo& fi : dir.entryInfoList({QStringLiteral("mission-*.json")}, QDir::Files)) {
        if (fi.absoluteFilePath() == QFileInfo(filePath()).absoluteFilePath()) continue;
        out.push_back({fi.absoluteFilePath(), originOf(fi.absoluteFilePath()), fi.lastModified()});
    }
    std::sort(out.begin(), out.end(), [](const Recovery& a, const Recovery& b) { return a.savedAt > b.savedAt; });
    return out;
}

bool Autosave::recover(const Recovery& r, QString* error) {
    auto m = io::readMissionFile(r.autosavePath.toStdString());
    if (!m) {
        if (error) *error = QString::fromStdString(m.error().message);
        return false;
    }
    m_doc->reset(std::move(m).value(), r.originalPath, /*markDirty=*/true);
    discard(r);
    writeNow(); // the recovered state is now this session's autosave
    return true;
}

void Autosave::discard(const Recovery& r) {
    QFile::remove(r.autosavePath);
    QFile::remove(r.autosavePath + QStringLiteral(".origin"));
}

} // namespace pf::ui
