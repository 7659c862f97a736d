#include "ui/dialogs/export_dialog.h"

#include "core/mission/route_check.h"
#include "ui/dialogs/gimbal_box.h"
#include "ui/dialogs/landing_heading_box.h"
#include "ui/mission_document.h"
#include "ui/planning/plan_controller.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QStyle>
#include <QTextBrowser>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>

namespace pf::ui {

ExportDialog::ExportDialog(MissionDocument* doc, PlanController* planner, const QString& folder,
                           QWidget* parent)
    : QDialog(parent), m_doc(doc), m_planner(planner) {
    setWindowTitle(tr("Export waypoints"));
    m_banner = new QLabel;
    m_banner->setObjectName(QStringLiteral("ExportBanner"));
    m_banner->setWordWrap(true);
    m_banner->setStyleSheet(QStringLiteral("QLabel { color: #6b3a00; background: #ffe8b0; padding: 4px 8px; "
                                           "border-radius: 3px; }"));
    auto* formats = new QGroupBox(tr("Formats"));
    auto* fl = new QVBoxLayout(formats);
    const auto ticked = defaultExportFormats(m_doc->mission());
    for (const auto& info : io::waypointFormats()) {
        auto* box = new QCheckBox(QStringLiteral("%1 (%2)").arg(
            QString::fromLatin1(info.description), QString::fromLatin1(info.extension)));
        box->setObjectName(QStringLiteral("ExportFormat_%1").arg(QString::fromLatin1(info.name)));
        box->setChecked(std::find(ticked.begin(), ticked.end(), info.format) != ticked.end());
        fl->addWidget(box);
        m_formats[info.format] = box;
    }
    auto* aircraft = new QGroupBox(tr("Aircraft"));
    auto* al = new QVBoxLayout(aircraft);
    m_routeLayout = new QVBoxLayout;
    al->addLayout(m_routeLayout);
    rebuildRouteBoxes();
    m_perAircraft = new QCheckBox(tr("One file per aircraft (KML, GPX, GeoJSON)"));
    m_perAircraft->setToolTip(
        tr("Vehicle files (.plan, .waypoints, Litchi .csv, DJI .kmz) are always one per aircraft, "
           "and one per battery for an aircraft that needs several"));
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
    m_firmware->setObjectName(QStringLiteral("ExportFirmware"));
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
    m_gimbal = makeGimbalBox(QStringLiteral("ExportGimbal"), doc->mission().options.cameraTiltDeg);
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
    m_landingHeading = makeLandingHeadingBox(QStringLiteral("ExportLandingHeading"));
    form->addRow(tr("Plane landing heading:"), m_landingHeading);
    form->addRow(QString(), makePlaneOptionsNote());

    m_report = new QPlainTextEdit;
    m_report->setReadOnly(true);
    m_report->setPlaceholderText(tr("The files written are listed here."));
    m_report->setMaximumHeight(110);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    m_exportButton = buttons->addButton(tr("Export"), QDialogButtonBox::ActionRole);
    m_exportButton->setDefault(true);
    connect(m_exportButton, &QPushButton::clicked, this, [this] { runExport(); });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto* top = new QHBoxLayout;
    top->addWidget(formats);
    top->addWidget(aircraft);
    auto* lay = new QVBoxLayout(this);
    lay->addWidget(m_banner);
    lay->addLayout(top);
    lay->addLayout(form);
    lay->addWidget(m_report);
    lay->addWidget(buttons);

    connect(m_planner, &PlanController::planChanged, this, &ExportDialog::onPlanStateChanged);
    connect(m_planner, &PlanController::pendingPlanChanged, this, &ExportDialog::onPlanStateChanged);
    // Queued: a finished plan clears "busy" just before it is applied.
    connect(m_planner, &PlanController::busyChanged, this, &ExportDialog::onPlanStateChanged, Qt::QueuedConnection);
    connect(m_doc, &MissionDocument::changed, this, &ExportDialog::refreshBanner);
    connect(m_doc, &MissionDocument::routesChanged, this, [this] {
        rebuildRouteBoxes();
        refreshBanner();
    });
    refreshBanner();
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
    r.options.landingHeadingDeg = landingHeadingOf(m_landingHeading);
    return r;
}

QStringList ExportDialog::runExport() {
    if (!confirmCurrentPlan())
        return {};
    std::vector<route::Route> routes;
    for (const auto& r : m_doc->routes())
        routes.push_back(r.route);
    ExportRequest req = request();
    QString error;
    QStringList problems, notes, warnings;
    QStringList written =
        exportRoutes(m_doc->mission(), routes, req, &error, &problems, &notes, &warnings);
    if (!problems.isEmpty()) {
        if (!confirmRouteErrors(problems)) {
            report({}, error, {}, {});
            return {};
        }
        req.allowRouteErrors = true;
        written = exportRoutes(m_doc->mission(), routes, req, &error, nullptr, &notes, &warnings);
    }
    report(written, error, notes, warnings);
    return written;
}

void ExportDialog::report(const QStringList& written, const QString& error,
                          const QStringList& notes, const QStringList& warnings) {
    QString text;
    if (!written.isEmpty())
        text = tr("Wrote %n file(s):", nullptr, written.size()) + QLatin1Char('\n') +
               written.join(QLatin1Char('\n'));
    for (const QString& w : warnings)
        text += QStringLiteral("\n") + tr("Warning: %1").arg(w);
    for (const QString& n : notes)
        text += QStringLiteral("\n") + tr("Note: %1").arg(n);
    if (!error.isEmpty())
        text += (text.isEmpty() ? QString() : QStringLiteral("\n")) + tr("Error: %1").arg(error);
    m_report->setPlainText(text);
    if (!written.isEmpty())
        showWritten(written, notes, warnings);
    emit exported(written);
}

// What was written, in a window of its own that scrolls: the warnings first (a flight over its
// autopilot's item limit), the notes (one file per sortie, merged waypoints, Litchi parts), the
// file names. Opened with open(): the export returns at once.
void ExportDialog::showWritten(const QStringList& written, const QStringList& notes,
                               const QStringList& warnings) {
    delete m_result.data(); // the previous export's
    const QString folder = request().folder;
    auto* box = new QDialog(this);
    box->setObjectName(QStringLiteral("ExportResult"));
    box->setWindowTitle(tr("Files written"));
    box->setProperty("warned", !warnings.isEmpty());
    auto* icon = new QLabel;
    icon->setPixmap(style()
                        ->standardIcon(warnings.isEmpty() ? QStyle::SP_MessageBoxInformation
                                                          : QStyle::SP_MessageBoxWarning)
                        .pixmap(32, 32));
    QString head = written.size() == 1
                       ? tr("Wrote 1 file into %1.").arg(folder)
                       : tr("Wrote %1 files into %2.").arg(written.size()).arg(folder);
    if (!warnings.isEmpty())
        head += QLatin1Char(' ') + tr("Read the warnings before flying them.");
    auto* summary = new QLabel(head);
    summary->setObjectName(QStringLiteral("ExportResultSummary"));
    summary->setWordWrap(true);
    auto list = [](const QString& title, const QStringList& items, const QString& colour) {
        if (items.isEmpty())
            return QString();
        QString html =
            QStringLiteral(
                "<p style=\"margin-bottom:2px\"><b>%1</b></p><ul style=\"margin-top:0\">")
                .arg(title.toHtmlEscaped());
        for (const QString& i : items)
            html += QStringLiteral("<li style=\"color:%1\">%2</li>").arg(colour, i.toHtmlEscaped());
        return html + QStringLiteral("</ul>");
    };
    QStringList names;
    for (const QString& f : written)
        names << QFileInfo(f).fileName();
    auto* text = new QTextBrowser;
    text->setObjectName(QStringLiteral("ExportResultText"));
    text->setHtml(list(tr("Warnings"), warnings, QStringLiteral("#8a4b00")) +
                  list(tr("Notes"), notes, QStringLiteral("palette(text)")) +
                  list(tr("Files"), names, QStringLiteral("palette(text)")));
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok);
    connect(buttons, &QDialogButtonBox::accepted, box, &QDialog::accept);
    auto* top = new QHBoxLayout;
    top->addWidget(icon, 0, Qt::AlignTop);
    top->addWidget(summary, 1);
    auto* lay = new QVBoxLayout(box);
    lay->addLayout(top);
    lay->addWidget(text, 1);
    lay->addWidget(buttons);
    box->resize(720, 440);
    box->setAttribute(Qt::WA_DeleteOnClose);
    m_result = box;
    box->open();
}

QString ExportDialog::resultText() const {
    if (!m_result)
        return {};
    const auto* summary = m_result->findChild<QLabel*>(QStringLiteral("ExportResultSummary"));
    const auto* text = m_result->findChild<QTextBrowser*>(QStringLiteral("ExportResultText"));
    return (summary ? summary->text() : QString()) + QLatin1Char('\n') +
           (text ? text->toPlainText() : QString());
}

void ExportDialog::rebuildRouteBoxes() {
    QList<bool> was;
    for (auto* box : m_routes) {
        was << box->isChecked();
        delete box;
    }
    m_routes.clear();
    for (std::size_t i = 0; i < m_doc->routes().size(); ++i) {
        const auto& r = m_doc->routes()[i];
        auto* box = new QCheckBox(QString::fromStdString(r.route.aircraft) + (r.edited ? tr(" (edited)") : QString()));
        box->setChecked(int(i) < was.size() ? was[int(i)] : true);
        m_routeLayout->addWidget(box);
        m_routes.push_back(box);
    }
}

// ---------------------------------------------------------------- confirmed before writing

QString ExportDialog::bannerText() const {
    return m_banner->isHidden() ? QString() : m_banner->text();
}

void ExportDialog::refreshBanner() {
    QStringList lines;
    if (m_planner->isOutdated()) {
        QString line = tr("<b>Outdated plan</b>: the mission changed after these routes were planned.");
        if (m_waiting)
            line += QLatin1Char(' ') + tr("Waiting for the new plan; the export starts when it is ready.");
        else if (m_planner->isBusy())
            line += QLatin1Char(' ') + tr("A new plan is being made.");
        lines << line;
    }
    std::vector<route::Route> routes;
    for (const auto& r : m_doc->routes())
        routes.push_back(r.route);
    const auto problems = mission::routeErrors(m_doc->mission(), routes);
    if (!problems.empty())
        lines << tr("<b>%n route problem(s)</b> (no-fly margins, altitudes): listed before anything is "
                    "written.", nullptr, int(problems.size()));
    m_banner->setText(lines.join(QStringLiteral("<br>")));
    m_banner->setHidden(lines.isEmpty());
    m_exportButton->setEnabled(!m_waiting);
    m_exportButton->setText(m_waiting ? tr("Waiting for the plan…") : tr("Export"));
}

void ExportDialog::onPlanStateChanged() {
    refreshBanner();
    if (!m_waiting || m_planner->isBusy())
        return;
    if (!m_planner->isOutdated()) {
        m_waiting = false;
        refreshBanner();
        runExport();
        return;
    }
    if (m_planner->hasPendingPlan()) {
        m_waiting = false;
        refreshBanner();
        runExport(); // asks how to merge the waiting plan with the edits
        return;
    }
    // Not busy, still outdated, nothing pending: the new plan failed or was cancelled.
    m_waiting = false;
    refreshBanner();
    report({},
           m_planner->lastError().isEmpty()
               ? tr("Not exported: planning was cancelled, and the routes are outdated.")
               : tr("Not exported: the new plan could not be made: %1").arg(m_planner->lastError()),
           {}, {});
}

bool ExportDialog::confirmCurrentPlan() {
    if (!m_planner->isOutdated())
        return true;
    if (m_planner->hasPendingPlan()) {
        QMessageBox box(QMessageBox::Question, tr("Export waypoints"),
                        tr("The mission changed and its new plan is ready, but some routes were edited by "
                           "hand. Export with your edited routes kept (the other aircraft get the new "
                           "plan), or replace them by the new plan?"),
                        QMessageBox::Cancel, this);
        auto* keep = box.addButton(tr("Keep edits"), QMessageBox::AcceptRole);
        auto* replace = box.addButton(tr("Replace edited paths"), QMessageBox::AcceptRole);
        box.setDefaultButton(keep);
        box.exec();
        if (box.clickedButton() == static_cast<QAbstractButton*>(keep))
            m_planner->keepEditsWithPendingPlan();
        else if (box.clickedButton() == static_cast<QAbstractButton*>(replace))
            m_planner->acceptPendingPlan();
        else
            return false;
        return !m_planner->isOutdated();
    }
    QMessageBox box(QMessageBox::Warning, tr("Export waypoints"),
                    tr("These routes are outdated: the mission changed after they were planned, so the "
                       "files would not fly what the mission now says."),
                    QMessageBox::Cancel, this);
    box.setInformativeText(tr("Wait for the new plan (the export starts by itself when it is ready), or "
                              "export the outdated routes?"));
    auto* wait = box.addButton(tr("Wait for the new plan"), QMessageBox::AcceptRole);
    auto* anyway = box.addButton(tr("Export outdated routes"), QMessageBox::DestructiveRole);
    box.setDefaultButton(wait);
    box.exec();
    if (box.clickedButton() == static_cast<QAbstractButton*>(anyway))
        return true;
    if (box.clickedButton() == static_cast<QAbstractButton*>(wait)) {
        m_waiting = true;
        if (!m_planner->isBusy())
            m_planner->planNow();
        refreshBanner();
        onPlanStateChanged(); // a plan may already be there (e.g. the mission has nothing to plan)
    }
    return false;
}

bool ExportDialog::confirmRouteErrors(const QStringList& problems) {
    QMessageBox box(
        QMessageBox::Critical, tr("Export waypoints"),
        tr("The route check found %n problem(s). An aircraft flying these routes would enter a "
           "no-fly zone's safety margin, fly at an altitude out of its limits, or get a file it "
           "cannot fly:",
           nullptr, problems.size()),
        QMessageBox::Cancel, this);
    const int shown = std::min(12, int(problems.size()));
    QString list = problems.mid(0, shown).join(QLatin1Char('\n'));
    if (shown < problems.size())
        list += QLatin1Char('\n') + tr("… and %n more (Show Details)", nullptr, int(problems.size()) - shown);
    box.setInformativeText(list);
    box.setDetailedText(problems.join(QLatin1Char('\n')));
    auto* anyway = box.addButton(tr("Export anyway"), QMessageBox::DestructiveRole);
    box.setDefaultButton(QMessageBox::Cancel);
    box.exec();
    return box.clickedButton() == static_cast<QAbstractButton*>(anyway);
}

} // namespace pf::ui
