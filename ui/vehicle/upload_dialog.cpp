#include "ui/vehicle/upload_dialog.h"

#include "core/io/export_context.h"
#include "core/io/mission_export.h"
#include "core/mavlink/connection_spec.h"
#include "ui/dialogs/gimbal_box.h"
#include "ui/dialogs/landing_heading_box.h"
#include "ui/mission_document.h"
#include "ui/vehicle/upload_manager.h"
#include "ui/vehicle/vehicle_upload.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSerialPortInfo>
#include <QSettings>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace pf::ui {

namespace {

constexpr int kRowHeight = 62;

// A cell widget at its natural height, centred in the (taller) row.
QWidget* centred(QWidget* w) {
    auto* box = new QWidget;
    auto* l = new QVBoxLayout(box);
    l->setContentsMargins(2, 0, 2, 0);
    l->addStretch();
    l->addWidget(w);
    l->addStretch();
    return box;
}

// The row's battery choice: one item per sortie ("2 of 5"); disabled for a single flight.
QComboBox* sortieBox(const QString& aircraft, int sorties, int row) {
    auto* box = new QComboBox;
    box->setObjectName(QStringLiteral("UploadSortie_%1").arg(row));
    for (int k = 1; k <= sorties; ++k)
        box->addItem(sorties == 1 ? UploadDialog::tr("one flight")
                                  : UploadDialog::tr("%1 of %2").arg(k).arg(sorties));
    box->setEnabled(sorties > 1);
    box->setToolTip(sorties == 1
                        ? UploadDialog::tr("%1 flies the whole plan on one battery").arg(aircraft)
                        : UploadDialog::tr("%1 needs %2 batteries: each upload sends one battery's "
                                           "flight, from home back home")
                              .arg(aircraft)
                              .arg(sorties));
    return box;
}

QString settingsKey(const QString& what, const QString& aircraft) {
    QString a = aircraft;
    a.replace(QLatin1Char('/'), QLatin1Char('_'));
    return QStringLiteral("vehicle/%1/%2").arg(what, a);
}

} // namespace

UploadDialog::UploadDialog(MissionDocument* doc, QWidget* parent, std::map<QString, int>* sent)
    : QDialog(parent), m_doc(doc), m_manager(new UploadManager(this)), m_sent(sent) {
    setWindowTitle(tr("Connect and Upload"));
    setObjectName(QStringLiteral("UploadDialog"));
    auto* intro = new QLabel(
        tr("Each aircraft's mission goes to its vehicle: the waypoints as exported, the no-fly "
           "zones as geofence and the rally point. It is then read back and compared item by item. "
           "A mission is one battery's flight: for an aircraft that needs several, choose the "
           "battery and upload the next one when it has landed. Connections: udp:HOST:PORT "
           "(Photoflight sends first), udp::PORT (listen, e.g. 14550), tcp:HOST:PORT, "
           "serial:DEVICE:BAUD. System id 0 takes the first vehicle heard."));
    intro->setWordWrap(true);

    buildTable();
    QGroupBox* options = buildOptions();
    QDialogButtonBox* buttons = buildButtons();
    connectManager();

    auto* lay = new QVBoxLayout(this);
    lay->addWidget(intro);
    lay->addWidget(m_table, 1);
    lay->addWidget(options);
    lay->addWidget(m_status);
    lay->addWidget(buttons);
    resize(1120, 520);
}

// The table: a row per aircraft (its battery, connection, system id, progress and answer).
void UploadDialog::buildTable() {
    m_table = new QTableWidget(0, 6);
    m_table->setObjectName(QStringLiteral("UploadTable"));
    m_table->setHorizontalHeaderLabels({tr("Aircraft"), tr("Battery"), tr("Connection"),
                                        tr("System id"), tr("Progress"), tr("Vehicle's answer")});
    m_table->horizontalHeaderItem(1)->setToolTip(
        tr("The battery (sortie) whose flight is sent: each flies from home back home"));
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(5, QHeaderView::Stretch);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    QStringList ports;
    for (const auto& p : QSerialPortInfo::availablePorts())
        ports << QStringLiteral("serial:%1:57600").arg(p.systemLocation());
    QSettings settings;
    std::vector<route::Route> routes;
    for (const auto& r : m_doc->routes())
        routes.push_back(r.route);
    const io::ExportContext ctx = io::makeExportContext(m_doc->mission(), routes);
    int row = 0;
    for (const auto& r : m_doc->routes()) {
        m_table->insertRow(row);
        addVehicleRow(row, r.route, ctx, settings, ports);
        ++row;
    }
    // Room for every row (three lines of answer each) up to a screenful; then it scrolls.
    m_table->setMinimumHeight(m_table->horizontalHeader()->sizeHint().height() + 6 +
                              kRowHeight * std::min(row, 6));
    m_table->resizeColumnsToContents();
    m_table->setColumnWidth(0, std::max(m_table->columnWidth(0), 150));
    m_table->setColumnWidth(1, 115);
    m_table->setColumnWidth(2, 230);
    m_table->setColumnWidth(3, 80);
    m_table->setColumnWidth(4, 130);
    m_table->horizontalHeader()->setSectionResizeMode(5, QHeaderView::Stretch);
}

// Row `row` of the table for `route`: checked when it has waypoints, the battery after the last
// verified upload (else the first), the connection and system id last used for the aircraft.
void UploadDialog::addVehicleRow(int row, const route::Route& route, const io::ExportContext& ctx,
                                 const QSettings& settings, const QStringList& ports) {
    const QString name = QString::fromStdString(route.aircraft);
    Row w;
    w.use = new QCheckBox(name);
    w.use->setChecked(!route.waypoints.empty());
    // The battery: by default the one after the last verified upload, else the first.
    const int sorties = route.waypoints.empty() ? 1 : int(io::sortieCount(ctx, std::size_t(row)));
    w.sortie = sortieBox(name, sorties, row);
    if (m_sent && m_sent->count(name) && m_sent->at(name) < sorties)
        w.sortie->setCurrentIndex(m_sent->at(name));
    w.connection = new QComboBox;
    w.connection->setEditable(true);
    w.connection->addItem(settings
                              .value(settingsKey(QStringLiteral("connection"), name),
                                     QStringLiteral("udp::%1").arg(14550 + row))
                              .toString());
    for (const QString& s :
         {QStringLiteral("udp:127.0.0.1:14550"), QStringLiteral("tcp:127.0.0.1:5760")})
        if (w.connection->findText(s) < 0)
            w.connection->addItem(s);
    w.connection->addItems(ports);
    w.connection->setMinimumWidth(200);
    w.systemId = new QSpinBox;
    w.systemId->setRange(0, 255);
    w.systemId->setSpecialValueText(tr("auto"));
    w.systemId->setValue(settings.value(settingsKey(QStringLiteral("sysid"), name), 0).toInt());
    w.progress = new QProgressBar;
    w.progress->setRange(0, 100);
    w.progress->setValue(0);
    w.answer = new QLabel(tr("Not sent"));
    w.answer->setWordWrap(true);
    w.answer->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_table->setCellWidget(row, 0, centred(w.use));
    m_table->setCellWidget(row, 1, centred(w.sortie));
    m_table->setCellWidget(row, 2, centred(w.connection));
    m_table->setCellWidget(row, 3, centred(w.systemId));
    m_table->setCellWidget(row, 4, centred(w.progress));
    m_table->setCellWidget(row, 5, w.answer);
    m_table->setRowHeight(row, kRowHeight);
    m_rows.push_back(w);
}

// The mission options: gimbal command, photo trigger, what follows the last waypoint (as last
// used), a plane's landing heading.
QGroupBox* UploadDialog::buildOptions() {
    QSettings settings;
    m_gimbal = makeGimbalBox(QStringLiteral("UploadGimbal"), m_doc->mission().options.cameraTiltDeg);
    m_trigger = new QComboBox;
    m_trigger->setObjectName(QStringLiteral("UploadTrigger"));
    m_trigger->addItem(tr("A capture command at every photo"), int(io::CameraTrigger::PerPhoto));
    m_trigger->addItem(tr("By distance along lanes (lane ends only)"), int(io::CameraTrigger::Distance));
    m_end = new QComboBox;
    m_end->addItem(tr("Return to launch"), int(io::MissionEnd::ReturnToLaunch));
    m_end->addItem(tr("Land at the landing point"), int(io::MissionEnd::Land));
    m_gimbal->setCurrentIndex(settings.value(QStringLiteral("vehicle/gimbal"), 0).toInt());
    m_trigger->setCurrentIndex(settings.value(QStringLiteral("vehicle/trigger"), 0).toInt());
    m_end->setCurrentIndex(settings.value(QStringLiteral("vehicle/end"), 0).toInt());
    auto* options = new QGroupBox(tr("Mission"));
    auto* form = new QFormLayout(options);
    auto* firmware = new QLabel(tr("From each vehicle's heartbeat (ArduPilot gets the home as item 0)"));
    form->addRow(tr("Firmware:"), firmware);
    form->addRow(tr("Camera:"), m_gimbal);
    form->addRow(tr("Photos:"), m_trigger);
    form->addRow(tr("After the last waypoint:"), m_end);
    // A plane's landing direction: the wind changes from flight to flight, so it is not remembered.
    m_landingHeading = makeLandingHeadingBox(QStringLiteral("UploadLandingHeading"));
    form->addRow(tr("Plane landing heading:"), m_landingHeading);
    form->addRow(QString(), makePlaneOptionsNote());
    return options;
}

// The status line and the buttons: Connect and Upload, Cancel upload, Close.
QDialogButtonBox* UploadDialog::buildButtons() {
    m_status = new QLabel;
    m_status->setObjectName(QStringLiteral("UploadStatus"));
    m_status->setWordWrap(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    m_upload = buttons->addButton(tr("Connect and Upload"), QDialogButtonBox::ActionRole);
    m_upload->setObjectName(QStringLiteral("UploadButton"));
    m_upload->setDefault(true);
    m_cancel = buttons->addButton(tr("Cancel upload"), QDialogButtonBox::ActionRole);
    m_cancel->setEnabled(false);
    connect(m_upload, &QPushButton::clicked, this, [this] { startUpload(); });
    connect(m_cancel, &QPushButton::clicked, m_manager, &UploadManager::cancel);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    return buttons;
}

// The manager's answers: each row's progress, the next battery offered after a verified upload,
// the summary when every job has ended.
void UploadDialog::connectManager() {
    connect(m_manager, &UploadManager::jobProgress, this, &UploadDialog::refreshRow);
    connect(m_manager, &UploadManager::jobVehicle, this, &UploadDialog::refreshRow);
    connect(m_manager, &UploadManager::jobFinished, this, &UploadDialog::refreshRow);
    connect(m_manager, &UploadManager::jobFinished, this, [this](int job, bool ok) {
        // Verified on the vehicle: the next battery is offered for the next upload.
        const std::size_t row = std::size_t(m_jobRow[std::size_t(job)]);
        Row& r = m_rows[row];
        if (!ok)
            return;
        if (m_sent && row < m_doc->routes().size())
            (*m_sent)[QString::fromStdString(m_doc->routes()[row].route.aircraft)] =
                r.sortie->currentIndex() + 1;
        if (r.sortie->currentIndex() + 1 < r.sortie->count())
            r.sortie->setCurrentIndex(r.sortie->currentIndex() + 1);
    });
    connect(m_manager, &UploadManager::allFinished, this, [this](int ok, int failed) {
        m_upload->setEnabled(true);
        m_cancel->setEnabled(false);
        const QString done =
            failed == 0
                ? tr("%n vehicle(s) uploaded and verified.", nullptr, ok)
                : tr("%1 uploaded, %2 failed: see the vehicle's answer.").arg(ok).arg(failed);
        m_status->setText(m_warnings.isEmpty()
                              ? done
                              : done + QLatin1Char('\n') + m_warnings.join(QLatin1Char('\n')));
        emit uploadsFinished(ok, failed);
    });
}

void UploadDialog::setConnection(int row, const QString& connection, int systemId) {
    auto& r = m_rows.at(std::size_t(row));
    r.connection->setCurrentText(connection);
    r.systemId->setValue(systemId);
}

void UploadDialog::setSortie(int row, int sortie) {
    m_rows.at(std::size_t(row)).sortie->setCurrentIndex(sortie);
}

int UploadDialog::sortie(int row) const {
    return m_rows.at(std::size_t(row)).sortie->currentIndex();
}

int UploadDialog::sortieCount(int row) const {
    return m_rows.at(std::size_t(row)).sortie->count();
}

io::ExportOptions UploadDialog::exportOptions() const {
    io::ExportOptions o;
    o.gimbal = io::GimbalCommand(m_gimbal->currentData().toInt());
    o.trigger = io::CameraTrigger(m_trigger->currentData().toInt());
    o.end = io::MissionEnd(m_end->currentData().toInt());
    o.landingHeadingDeg = landingHeadingOf(m_landingHeading);
    return o;
}

bool UploadDialog::isRunning() const { return m_manager->isRunning(); }

QString UploadDialog::rowResult(int row) const { return m_rows.at(std::size_t(row)).answer->text(); }

void UploadDialog::saveSettings() const {
    QSettings settings;
    const auto& routes = m_doc->routes();
    for (std::size_t i = 0; i < m_rows.size() && i < routes.size(); ++i) {
        const QString name = QString::fromStdString(routes[i].route.aircraft);
        settings.setValue(settingsKey(QStringLiteral("connection"), name), m_rows[i].connection->currentText());
        settings.setValue(settingsKey(QStringLiteral("sysid"), name), m_rows[i].systemId->value());
    }
    settings.setValue(QStringLiteral("vehicle/gimbal"), m_gimbal->currentIndex());
    settings.setValue(QStringLiteral("vehicle/trigger"), m_trigger->currentIndex());
    settings.setValue(QStringLiteral("vehicle/end"), m_end->currentIndex());
}

bool UploadDialog::startUpload() {
    std::vector<route::Route> routes;
    for (const auto& r : m_doc->routes())
        routes.push_back(r.route);
    const io::ExportContext ctx = io::makeExportContext(m_doc->mission(), routes);
    const io::ExportOptions options = exportOptions();
    std::vector<UploadJob> jobs;
    m_jobRow.clear();
    m_warnings.clear();
    for (std::size_t i = 0; i < m_rows.size(); ++i) {
        auto& r = m_rows[i];
        if (!r.use->isChecked())
            continue;
        auto spec = mavlink::parseConnectionSpec(r.connection->currentText().trimmed().toStdString());
        if (!spec) {
            m_status->setText(tr("%1: %2").arg(r.use->text(), QString::fromStdString(spec.error().message)));
            return false;
        }
        // One battery's flight; the read-back compares that flight.
        const io::ExportContext flight =
            io::sortieFlight(ctx, i, std::size_t(std::max(0, r.sortie->currentIndex())));
        // The vehicle's firmware is known only once it answers: the smaller of the autopilots'
        // limits.
        if (auto w = io::flightItemWarning(flight, 0, options, std::nullopt); !w.empty())
            m_warnings << QStringLiteral("⚠ ") + QString::fromStdString(w);
        auto job = makeUploadJob(flight, 0, *spec, r.systemId->value(), options);
        if (!job) {
            m_status->setText(QString::fromStdString(job.error().message));
            return false;
        }
        jobs.push_back(std::move(*job));
        m_jobRow.push_back(int(i));
    }
    if (jobs.empty()) {
        m_status->setText(tr("Tick at least one aircraft to upload."));
        return false;
    }
    QString error;
    if (!m_manager->start(std::move(jobs), &error)) {
        m_status->setText(error);
        return false;
    }
    saveSettings();
    for (int row : m_jobRow) {
        m_rows[std::size_t(row)].progress->setValue(0);
        m_rows[std::size_t(row)].answer->setText(tr("Connecting…"));
    }
    m_upload->setEnabled(false);
    m_cancel->setEnabled(true);
    const QString sending = tr("Uploading to %n vehicle(s)…", nullptr, int(m_jobRow.size()));
    m_status->setText(m_warnings.isEmpty()
                          ? sending
                          : sending + QLatin1Char('\n') + m_warnings.join(QLatin1Char('\n')));
    for (std::size_t j = 0; j < m_jobRow.size(); ++j)
        refreshRow(int(j));
    return true;
}

void UploadDialog::refreshRow(int job) {
    const VehicleUpload* u = m_manager->upload(std::size_t(job));
    Row& r = m_rows[std::size_t(m_jobRow[std::size_t(job)])];
    const auto p = u->progress();
    r.progress->setValue(p.total ? int(100 * p.done / p.total) : 0);
    QString text = u->phaseText();
    if (!u->vehicleText().isEmpty())
        text += QStringLiteral(" (") + u->vehicleText() + QLatin1Char(')');
    if (u->isFinished())
        text = (u->succeeded() ? QStringLiteral("✔ ") : QStringLiteral("✘ ")) + u->resultText() +
               (u->vehicleText().isEmpty() ? QString() : QStringLiteral(" (") + u->vehicleText() + QLatin1Char(')'));
    r.answer->setText(text);
    r.answer->setStyleSheet(u->isFinished() ? (u->succeeded() ? QStringLiteral("color: #1b7a1b")
                                                              : QStringLiteral("color: #b00020"))
                                            : QString());
}

} // namespace pf::ui
