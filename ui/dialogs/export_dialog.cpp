#include "ui/dialogs/export_dialog.h"

#include "ui/mission_document.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QToolButton>
#include <QVBoxLayout>

namespace pf::ui {

ExportDialog::ExportDialog(MissionDocument* doc, const QString& folder, QWidget* parent)
    : QDialog(parent), m_doc(doc) {
    setWindowTitle(tr("Export waypoints"));
    auto* formats = new QGroupBox(tr("Formats"));
    auto* fl = new QVBoxLayout(formats);
    for (const auto& info : io::waypointFormats()) {
        auto* box = new QCheckBox(QStringLiteral("%1 (%2)").arg(
            QString::fromLatin1(info.description), QString::fromLatin1(info.extension)));
        box->setChecked(info.format == io::WaypointFormat::QgcPlan ||
                        info.format == io::WaypointFormat::Kml);
        fl->addWidget(box);
        m_formats[info.format] = box;
    }
    auto* aircraft = new QGroupBox(tr("Aircraft"));
    auto* al = new QVBoxLayout(aircraft);
    for (const auto& r : doc->routes()) {
        auto* box = new QCheckBox(QString::fromStdString(r.route.aircraft) +
                                  (r.edited ? tr(" (edited)") : QString()));
        box->setChecked(true);
        al->addWidget(box);
        m_routes.push_back(box);
    }
    m_perAircraft = new QCheckBox(tr("One file per aircraft"));
    m_perAircraft->setChecked(true);
    m_combined =
        new QCheckBox(tr("One combined file where the format allows it (KML, GPX, GeoJSON)"));
    m_combined->setChecked(true);
    al->addWidget(m_perAircraft);
    al->addWidget(m_combined);

    m_folder = new QLineEdit(folder);
    auto* browse = new QToolButton;
    browse->setText(tr("…"));
    connect(browse, &QToolButton::clicked, this, [this] {
        const QString d =
            QFileDialog::getExistingDirectory(this, tr("Export folder"), m_folder->text());
        if (!d.isEmpty())
            m_folder->setText(d);
    });
    auto* folderRow = new QHBoxLayout;
    folderRow->addWidget(m_folder, 1);
    folderRow->addWidget(browse);
    m_stem = new QLineEdit(QStringLiteral("mission"));
    m_firmware = new QComboBox;
    m_firmware->addItem(tr("ArduPilot"), int(io::QgcFirmware::ArduPilot));
    m_firmware->addItem(tr("PX4"), int(io::QgcFirmware::PX4));
    m_end = new QComboBox;
    m_end->addItem(tr("Return to launch"), int(io::MissionEnd::ReturnToLaunch));
    m_end->addItem(tr("Land at the last waypoint"), int(io::MissionEnd::Land));
    auto* form = new QFormLayout;
    form->addRow(tr("Folder:"), folderRow);
    form->addRow(tr("File name start:"), m_stem);
    form->addRow(tr("Firmware (.plan):"), m_firmware);
    form->addRow(tr("After the last waypoint:"), m_end);
    // MAVLink mission options (.plan and .waypoints; the upload offers the same).
    m_gimbal = new QComboBox;
    m_gimbal->setObjectName(QStringLiteral("ExportGimbal"));
    m_gimbal->addItem(tr("Camera straight down: DO_MOUNT_CONTROL"), int(io::GimbalCommand::MountControl));
    m_gimbal->addItem(tr("Camera straight down: DO_GIMBAL_MANAGER_PITCHYAW"),
                      int(io::GimbalCommand::GimbalManagerPitchYaw));
    m_gimbal->addItem(tr("No gimbal command"), int(io::GimbalCommand::None));
    m_trigger = new QComboBox;
    m_trigger->setObjectName(QStringLiteral("ExportTrigger"));
    m_trigger->addItem(tr("A capture command at every photo"), int(io::CameraTrigger::PerPhoto));
    m_trigger->addItem(tr("By distance along lanes (DO_SET_CAM_TRIGG_DIST, lane ends only)"),
                       int(io::CameraTrigger::Distance));
    m_homeElevation = new QDoubleSpinBox;
    m_homeElevation->setRange(-501, 9000);
    m_homeElevation->setDecimals(1);
    m_homeElevation->setSuffix(tr(" m"));
    m_homeElevation->setSpecialValueText(tr("unknown (0)"));
    m_homeElevation->setValue(-501);
    form->addRow(tr("Gimbal (.plan, .waypoints):"), m_gimbal);
    form->addRow(tr("Photos (.plan, .waypoints):"), m_trigger);
    form->addRow(tr("Home elevation above sea level:"), m_homeElevation);

    m_report = new QPlainTextEdit;
    m_report->setReadOnly(true);
    m_report->setPlaceholderText(tr("The files written are listed here."));
    m_report->setMaximumHeight(110);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    auto* exportButton = buttons->addButton(tr("Export"), QDialogButtonBox::ActionRole);
    exportButton->setDefault(true);
    connect(exportButton, &QPushButton::clicked, this, [this] { runExport(); });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto* top = new QHBoxLayout;
    top->addWidget(formats);
    top->addWidget(aircraft);
    auto* lay = new QVBoxLayout(this);
    lay->addLayout(top);
    lay->addLayout(form);
    lay->addWidget(m_report);
    lay->addWidget(buttons);
}

ExportRequest ExportDialog::request() const {
    ExportRequest r;
    r.folder = m_folder->text();
    r.stem =
        m_stem->text().trimmed().isEmpty() ? QStringLiteral("mission") : m_stem->text().trimmed();
    for (const auto& [fmt, box] : m_formats)
        if (box->isChecked())
            r.formats.push_back(fmt);
    for (std::size_t i = 0; i < m_routes.size(); ++i)
        if (m_routes[i]->isChecked())
            r.routes.push_back(int(i));
    if (r.routes.empty())
        r.routes.push_back(-1); // none chosen: export nothing rather than all
    r.perAircraft = m_perAircraft->isChecked();
    r.combined = m_combined->isChecked();
    r.options.firmware = io::QgcFirmware(m_firmware->currentData().toInt());
    r.options.end = io::MissionEnd(m_end->currentData().toInt());
    r.options.gimbal = io::GimbalCommand(m_gimbal->currentData().toInt());
    r.options.trigger = io::CameraTrigger(m_trigger->currentData().toInt());
    if (m_homeElevation->value() > m_homeElevation->minimum())
        r.options.homeElevationM = m_homeElevation->value();
    return r;
}

QStringList ExportDialog::runExport() {
    std::vector<route::Route> routes;
    for (const auto& r : m_doc->routes())
        routes.push_back(r.route);
    QString error;
    QStringList notes;
    const QStringList written = exportRoutes(m_doc->mission(), routes, request(), &error, &notes);
    QString text;
    if (!written.isEmpty())
        text = tr("Wrote %n file(s):", nullptr, written.size()) + QLatin1Char('\n') +
               written.join(QLatin1Char('\n'));
    for (const QString& n : notes)
        text += QStringLiteral("\n") + tr("Note: %1").arg(n);
    if (!error.isEmpty())
        text += (text.isEmpty() ? QString() : QStringLiteral("\n")) + tr("Error: %1").arg(error);
    m_report->setPlainText(text);
    return written;
}

} // namespace pf::ui
