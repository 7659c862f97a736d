#include "ui/mosaic/mosaic_dialog.h"

#include "core/mosaic/mosaic_builder.h"
#include "core/mosaic/mosaic_report.h"
#include "core/progress.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QFileInfo>
#include <QFontDatabase>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QPointer>
#include <QProgressBar>
#include <QPushButton>
#include <QThread>
#include <QVBoxLayout>
#include <QtConcurrent>

namespace pf::ui {

struct MosaicDialog::Outcome {
    std::optional<mosaic::MosaicReport> report;
    Error error;
};

namespace {
enum PlanChoice { NoPlan, CurrentPlan, PlanFile };
} // namespace

MosaicDialog::MosaicDialog(const io::Catalog& catalog,
                           std::function<std::optional<mosaic::PlannedFlight>()> currentPlan,
                           QWidget* parent)
    : QDialog(parent), m_catalog(catalog), m_currentPlan(std::move(currentPlan)) {
    setObjectName(QStringLiteral("MosaicDialog"));
    setWindowTitle(tr("Build mosaic"));
    auto* layout = new QVBoxLayout(this);

    // Photos.
    auto* photoRow = new QHBoxLayout;
    m_photoList = new QListWidget;
    m_photoList->setObjectName(QStringLiteral("photoList"));
    m_photoList->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_photoList->setMinimumHeight(120);
    auto* photoButtons = new QVBoxLayout;
    auto* addFiles = new QPushButton(tr("Add photos…"));
    auto* addFolder = new QPushButton(tr("Add folder…"));
    auto* remove = new QPushButton(tr("Remove"));
    auto* clear = new QPushButton(tr("Clear"));
    for (auto* b : {addFiles, addFolder, remove, clear})
        photoButtons->addWidget(b);
    photoButtons->addStretch();
    photoRow->addWidget(m_photoList, 1);
    photoRow->addLayout(photoButtons);
    m_photoCount = new QLabel;
    layout->addWidget(new QLabel(
        tr("<b>Photos</b> (JPEG, with GPS in EXIF/XMP, or matched to the plan in capture order)")));
    layout->addLayout(photoRow);
    layout->addWidget(m_photoCount);
    connect(addFiles, &QPushButton::clicked, this, &MosaicDialog::browsePhotos);
    connect(addFolder, &QPushButton::clicked, this, &MosaicDialog::browseFolder);
    connect(remove, &QPushButton::clicked, this, [this] {
        qDeleteAll(m_photoList->selectedItems());
        updatePhotoCount();
    });
    connect(clear, &QPushButton::clicked, this, &MosaicDialog::clearPhotos);

    // Options.
    auto* form = new QFormLayout;
    m_plan = new QComboBox;
    m_plan->setObjectName(QStringLiteral("planChoice"));
    m_plan->addItem(tr("None"), NoPlan);
    m_plan->addItem(tr("The current plan"), CurrentPlan);
    m_plan->addItem(tr("A plan file (plan.geojson)…"), PlanFile);
    m_planFile = new QLineEdit;
    m_planFile->setPlaceholderText(
        tr("plan.geojson or the directory photoflight-cli plan --out wrote"));
    m_planBrowse = new QPushButton(tr("Browse…"));
    auto* planRow = new QHBoxLayout;
    planRow->addWidget(m_plan);
    planRow->addWidget(m_planFile, 1);
    planRow->addWidget(m_planBrowse);
    planRow->addStretch();
    form->addRow(tr("Plan:"), planRow);
    connect(m_plan, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
            &MosaicDialog::onPlanChoice);
    connect(m_planBrowse, &QPushButton::clicked, this, &MosaicDialog::browsePlan);
    connect(m_planFile, &QLineEdit::editingFinished, this, &MosaicDialog::refreshAircraft);
    m_aircraft = new QComboBox;
    m_aircraft->setObjectName(QStringLiteral("aircraft"));
    m_aircraft->setToolTip(
        tr("Photos of one aircraft are matched to its photo points only, and the coverage is "
           "measured over its part of the area."));
    form->addRow(tr("Photos of:"), m_aircraft);

    m_camera = new QComboBox;
    m_camera->setObjectName(QStringLiteral("camera"));
    m_camera->addItem(tr("From the photos (EXIF make and model)"), QString());
    for (const auto& c : m_catalog.cameras)
        m_camera->addItem(QString::fromStdString(c.name), QString::fromStdString(c.name));
    form->addRow(tr("Camera:"), m_camera);

    m_gsd = new QDoubleSpinBox;
    m_gsd->setObjectName(QStringLiteral("gsd"));
    m_gsd->setRange(0.0, 1000.0);
    m_gsd->setDecimals(1);
    m_gsd->setSuffix(tr(" cm/px"));
    m_gsd->setSpecialValueText(tr("Automatic (the photos' resolution)"));
    form->addRow(tr("Resolution:"), m_gsd);
    m_feather = new QDoubleSpinBox;
    m_feather->setObjectName(QStringLiteral("feather"));
    m_feather->setRange(0.0, 50.0);
    m_feather->setDecimals(1);
    m_feather->setSuffix(tr(" m"));
    m_feather->setSpecialValueText(tr("Off (sharp seams)"));
    form->addRow(tr("Blend across seams:"), m_feather);

    m_output = new QLineEdit;
    m_output->setObjectName(QStringLiteral("output"));
    m_output->setPlaceholderText(tr("mosaic.tif"));
    auto* outBrowse = new QPushButton(tr("Browse…"));
    auto* outRow = new QHBoxLayout;
    outRow->addWidget(m_output, 1);
    outRow->addWidget(outBrowse);
    form->addRow(tr("Save as (GeoTIFF):"), outRow);
    connect(outBrowse, &QPushButton::clicked, this, &MosaicDialog::browseOutput);
    layout->addLayout(form);

    // Progress and the report.
    m_progress = new QProgressBar;
    m_progress->setRange(0, 1000);
    m_progress->setValue(0);
    m_progress->setTextVisible(false);
    m_status = new QLabel(tr("Choose the photos, then Build."));
    m_status->setWordWrap(true);
    m_reportView = new QPlainTextEdit;
    m_reportView->setObjectName(QStringLiteral("report"));
    m_reportView->setReadOnly(true);
    m_reportView->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_reportView->setMinimumHeight(140);
    m_reportView->setPlaceholderText(
        tr("The report appears here: photos left out and why, photos that do not "
           "match the plan, planned photos missing, gaps in the area."));
    layout->addWidget(m_progress);
    layout->addWidget(m_status);
    layout->addWidget(m_reportView, 1);

    auto* buttons = new QDialogButtonBox;
    m_build = buttons->addButton(tr("Build"), QDialogButtonBox::AcceptRole);
    m_build->setObjectName(QStringLiteral("build"));
    m_cancel = buttons->addButton(tr("Cancel build"), QDialogButtonBox::ActionRole);
    m_cancel->setObjectName(QStringLiteral("cancelBuild"));
    m_cancel->setEnabled(false);
    m_close = buttons->addButton(QDialogButtonBox::Close);
    layout->addWidget(buttons);
    connect(m_build, &QPushButton::clicked, this, [this] { start(); });
    connect(m_cancel, &QPushButton::clicked, this, &MosaicDialog::cancel);
    connect(m_close, &QPushButton::clicked, this, &QDialog::reject);
    connect(&m_watcher, &QFutureWatcher<std::shared_ptr<Outcome>>::finished, this,
            &MosaicDialog::onFinished);

    // The current plan is the natural choice when there is one.
    const bool havePlan = m_currentPlan && m_currentPlan().has_value();
    m_plan->setCurrentIndex(havePlan ? 1 : 0);
    onPlanChoice();
    updatePhotoCount();
    resize(720, 640);
}

MosaicDialog::~MosaicDialog() {
    if (m_running) {
        m_job->cancel();
        m_watcher.waitForFinished();
    }
}

int MosaicDialog::addPhotos(const QStringList& paths) {
    QStringList files;
    for (const QString& p : paths) {
        const QFileInfo info(p);
        if (info.isDir()) {
            const auto entries =
                QDir(p).entryInfoList({QStringLiteral("*.jpg"), QStringLiteral("*.jpeg"),
                                       QStringLiteral("*.JPG"), QStringLiteral("*.JPEG")},
                                      QDir::Files, QDir::Name);
            for (const auto& e : entries)
                files << e.absoluteFilePath();
        } else {
            files << info.absoluteFilePath();
        }
    }
    int added = 0;
    for (const QString& f : files) {
        if (!m_photoList->findItems(f, Qt::MatchExactly).isEmpty())
            continue;
        m_photoList->addItem(f);
        ++added;
    }
    if (m_output->text().isEmpty() && !files.isEmpty())
        m_output->setText(
            QFileInfo(files.front()).absoluteDir().filePath(QStringLiteral("mosaic.tif")));
    updatePhotoCount();
    return added;
}

void MosaicDialog::clearPhotos() {
    m_photoList->clear();
    updatePhotoCount();
}

QStringList MosaicDialog::photos() const {
    QStringList out;
    for (int i = 0; i < m_photoList->count(); ++i)
        out << m_photoList->item(i)->text();
    return out;
}

void MosaicDialog::updatePhotoCount() {
    m_photoCount->setText(tr("%n photo(s)", nullptr, m_photoList->count()));
}

void MosaicDialog::setOutputPath(const QString& path) {
    m_output->setText(path);
}
QString MosaicDialog::outputPath() const {
    return m_output->text().trimmed();
}
void MosaicDialog::useCurrentPlan() {
    m_plan->setCurrentIndex(m_plan->findData(CurrentPlan));
}
void MosaicDialog::useNoPlan() {
    m_plan->setCurrentIndex(m_plan->findData(NoPlan));
}
void MosaicDialog::usePlanFile(const QString& path) {
    m_planFile->setText(path);
    m_plan->setCurrentIndex(m_plan->findData(PlanFile));
    refreshAircraft();
}
void MosaicDialog::setGsdCm(double cm) {
    m_gsd->setValue(cm);
}
void MosaicDialog::setFeatherM(double m) {
    m_feather->setValue(m);
}
void MosaicDialog::setAircraft(const QString& name) {
    const int i = m_aircraft->findData(name);
    m_aircraft->setCurrentIndex(i < 0 ? 0 : i);
}

void MosaicDialog::setCamera(const QString& name) {
    const int i = m_camera->findData(name);
    m_camera->setCurrentIndex(i < 0 ? 0 : i);
}

void MosaicDialog::onPlanChoice() {
    const int choice = m_plan->currentData().toInt();
    m_planFile->setVisible(choice == PlanFile);
    m_planBrowse->setVisible(choice == PlanFile);
    if (choice == CurrentPlan) {
        const auto plan = m_currentPlan ? m_currentPlan() : std::nullopt;
        m_plan->setItemText(
            1, plan ? tr("The current plan (%n photo point(s))", nullptr, int(plan->photos.size()))
                    : tr("The current plan (none yet: plan the mission first)"));
    }
    refreshAircraft();
}

std::optional<mosaic::PlannedFlight> MosaicDialog::chosenPlan(QString* why) const {
    switch (m_plan->currentData().toInt()) {
    case CurrentPlan: {
        auto plan = m_currentPlan ? m_currentPlan() : std::nullopt;
        if (!plan && why)
            *why = tr(
                "There is no current plan: plan the mission first, or choose a plan file or none.");
        return plan;
    }
    case PlanFile: {
        auto plan = mosaic::readPlannedFlight(m_planFile->text().trimmed().toStdString());
        if (!plan) {
            if (why)
                *why = QString::fromStdString(plan.error().message);
            return std::nullopt;
        }
        return std::move(plan).value();
    }
    default:
        return std::nullopt;
    }
}

void MosaicDialog::refreshAircraft() {
    const QString keep = m_aircraft->currentData().toString();
    m_aircraft->clear();
    m_aircraft->addItem(tr("Every aircraft of the plan"), QString());
    if (m_plan->currentData().toInt() != NoPlan &&
        (m_plan->currentData().toInt() != PlanFile || !m_planFile->text().isEmpty())) {
        if (const auto plan = chosenPlan(nullptr))
            for (const auto& a : plan->aircraft())
                m_aircraft->addItem(QString::fromStdString(a), QString::fromStdString(a));
    }
    setAircraft(keep);
    m_aircraft->setEnabled(m_aircraft->count() > 1);
}

void MosaicDialog::browsePhotos() {
    const QStringList files =
        QFileDialog::getOpenFileNames(this, tr("Photos"), QString(),
                                      tr("JPEG photos (*.jpg *.jpeg *.JPG *.JPEG);;All files (*)"));
    addPhotos(files);
}

void MosaicDialog::browseFolder() {
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Folder of photos"));
    if (!dir.isEmpty())
        addPhotos({dir});
}

void MosaicDialog::browseOutput() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Save mosaic as"), outputPath(),
                                                      tr("GeoTIFF (*.tif *.tiff)"));
    if (!path.isEmpty())
        m_output->setText(path.endsWith(QLatin1String(".tif"), Qt::CaseInsensitive) ||
                                  path.endsWith(QLatin1String(".tiff"), Qt::CaseInsensitive)
                              ? path
                              : path + QStringLiteral(".tif"));
}

void MosaicDialog::browsePlan() {
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Plan"), QString(), tr("Plan (plan.geojson *.geojson);;All files (*)"));
    if (!path.isEmpty())
        usePlanFile(path);
}

bool MosaicDialog::start() {
    if (m_running)
        return false;
    auto refuse = [this](const QString& why) {
        m_status->setText(why);
        return false;
    };
    mosaic::MosaicOptions o;
    for (const QString& p : photos())
        o.photos.push_back(p.toStdString());
    if (o.photos.empty())
        return refuse(tr("Add the photos first."));
    QString out = outputPath();
    if (out.isEmpty())
        return refuse(tr("Choose where to save the mosaic."));
    if (!out.endsWith(QLatin1String(".tif"), Qt::CaseInsensitive) &&
        !out.endsWith(QLatin1String(".tiff"), Qt::CaseInsensitive)) {
        out += QStringLiteral(".tif");
        m_output->setText(out);
    }
    o.outputPath = out.toStdString();
    if (m_plan->currentData().toInt() != NoPlan) {
        QString why;
        o.plan = chosenPlan(&why);
        if (!o.plan)
            return refuse(why);
        o.planAircraft = m_aircraft->currentData().toString().toStdString();
    }
    o.catalog = m_catalog.cameras;
    o.cameraName = m_camera->currentData().toString().toStdString();
    o.gsdM = m_gsd->value() / 100.0;
    o.featherM = m_feather->value();
    o.threads = std::max(1, QThread::idealThreadCount());

    m_report.reset();
    m_reportView->clear();
    QPointer<MosaicDialog> self(this);
    m_job = std::make_shared<Progress>([self](double f, const std::string& stage) {
        // Called on the worker thread: hand it to the dialog's thread.
        const QString s = QString::fromStdString(stage);
        QMetaObject::invokeMethod(
            qApp,
            [self, f, s] {
                if (self)
                    self->onProgress(f, s);
            },
            Qt::QueuedConnection);
    });
    auto job = m_job;
    m_watcher.setFuture(QtConcurrent::run([o = std::move(o), job]() {
        auto outcome = std::make_shared<Outcome>();
        auto r = mosaic::buildMosaic(o, *job);
        if (r)
            outcome->report = std::move(r).value();
        else
            outcome->error = r.error();
        return outcome;
    }));
    m_progress->setValue(0);
    m_status->setText(tr("Reading photos…"));
    setRunning(true);
    return true;
}

void MosaicDialog::cancel() {
    if (!m_running)
        return;
    m_job->cancel();
    m_status->setText(tr("Cancelling…"));
    m_cancel->setEnabled(false);
}

bool MosaicDialog::waitForFinished(int timeoutMs) {
    QElapsedTimer t;
    t.start();
    while (m_running && t.elapsed() < timeoutMs)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
    return !m_running;
}

void MosaicDialog::onProgress(double fraction, const QString& stage) {
    if (!m_running)
        return;
    m_progress->setValue(static_cast<int>(fraction * 1000));
    if (!m_job->cancelled()) {
        QString s = stage;
        if (!s.isEmpty())
            s[0] = s[0].toUpper();
        m_status->setText(tr("%1… %2 %").arg(s).arg(static_cast<int>(fraction * 100)));
    }
}

void MosaicDialog::onFinished() {
    const auto outcome = m_watcher.result();
    setRunning(false);
    if (outcome->report) {
        m_report = outcome->report;
        m_progress->setValue(1000);
        m_status->setText(tr("Mosaic saved: %1 (%2 of %3 photos, %4 cm/px).")
                              .arg(QString::fromStdString(m_report->outputPath))
                              .arg(m_report->photosUsed)
                              .arg(m_report->photosGiven)
                              .arg(m_report->gsdM * 100, 0, 'f', 1));
        m_reportView->setPlainText(QString::fromStdString(mosaic::formatReport(*m_report)));
        emit mosaicReady(*m_report);
    } else if (outcome->error.code == ErrorCode::Cancelled) {
        m_progress->setValue(0);
        m_status->setText(tr("Cancelled: nothing was written."));
    } else {
        m_progress->setValue(0);
        m_status->setText(tr("No mosaic: %1").arg(QString::fromStdString(outcome->error.message)));
        m_reportView->setPlainText(QString::fromStdString(outcome->error.message));
    }
}

void MosaicDialog::setRunning(bool on) {
    m_running = on;
    m_build->setEnabled(!on);
    m_cancel->setEnabled(on);
    for (auto* w :
         std::initializer_list<QWidget*>{m_photoList, m_plan, m_planFile, m_planBrowse, m_aircraft,
                                         m_camera, m_gsd, m_feather, m_output})
        w->setEnabled(!on);
    emit runningChanged(on);
}

QString MosaicDialog::statusText() const {
    return m_status->text();
}
QString MosaicDialog::reportText() const {
    return m_reportView->toPlainText();
}

} // namespace pf::ui
