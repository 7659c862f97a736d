#include "ui/vehicle/upload_manager.h"

#include "core/mavlink/vehicle_plan.h"
#include "ui/vehicle/vehicle_link.h"
#include "ui/vehicle/vehicle_upload.h"

namespace pf::ui {

Result<UploadJob> makeUploadJob(const io::ExportContext& ctx, std::size_t routeIndex,
                                const mavlink::ConnectionSpec& connection, int systemId,
                                const io::ExportOptions& exportOptions) {
    if (systemId < 0 || systemId > 255)
        return makeError(ErrorCode::InvalidInput,
                         ctx.routeLabel(routeIndex) + ": system id " + std::to_string(systemId) +
                             " is not in 1..255 (0 = the first vehicle heard)");
    auto plan = mavlink::vehiclePlanFor(ctx, routeIndex, exportOptions);
    if (!plan)
        return plan.error();
    UploadJob job;
    job.aircraft = QString::fromStdString(ctx.routeLabel(routeIndex));
    job.connection = connection;
    job.systemId = systemId;
    job.plan = std::move(*plan);
    job.options.targetSystem = static_cast<std::uint8_t>(systemId);
    job.options.linkDescription = connection.describe();
    job.options.serialLink = connection.kind == mavlink::ConnectionSpec::Kind::Serial;
    return job;
}

Status checkBindings(const std::vector<UploadJob>& jobs) {
    for (std::size_t i = 0; i < jobs.size(); ++i)
        for (std::size_t k = i + 1; k < jobs.size(); ++k) {
            if (jobs[i].connection.text() != jobs[k].connection.text())
                continue;
            const std::string a = jobs[i].aircraft.toStdString(), b = jobs[k].aircraft.toStdString();
            if (jobs[i].systemId == 0 || jobs[k].systemId == 0)
                return makeError(ErrorCode::InvalidInput,
                                 a + " and " + b + " share " + jobs[i].connection.describe() +
                                     ": give each its vehicle's system id (1-255)");
            if (jobs[i].systemId == jobs[k].systemId)
                return makeError(ErrorCode::InvalidInput,
                                 a + " and " + b + " are both bound to system id " +
                                     std::to_string(jobs[i].systemId) + " on " +
                                     jobs[i].connection.describe());
        }
    return {};
}

UploadManager::UploadManager(QObject* parent) : QObject(parent) {}

UploadManager::~UploadManager() {
    for (auto* u : m_uploads)
        delete u;
}

bool UploadManager::isRunning() const {
    for (const auto* u : m_uploads)
        if (!u->isFinished())
            return true;
    return false;
}

bool UploadManager::start(std::vector<UploadJob> jobs, QString* error) {
    if (isRunning()) {
        if (error)
            *error = tr("An upload is still running.");
        return false;
    }
    for (auto* u : m_uploads)
        delete u;
    m_uploads.clear();
    m_links.clear();
    m_done = 0;
    if (auto st = checkBindings(jobs); !st) {
        if (error)
            *error = QString::fromStdString(st.error().message);
        return false;
    }
    for (const auto& j : jobs) {
        const std::string key = j.connection.text();
        if (m_links.count(key))
            continue;
        auto link = createLink(j.connection);
        QString why;
        if (!link || !link->open(&why)) {
            if (error)
                *error = tr("%1: cannot open the connection: %2").arg(j.aircraft, why);
            m_links.clear();
            return false;
        }
        m_links[key] = std::move(link);
    }
    for (std::size_t i = 0; i < jobs.size(); ++i) {
        auto& j = jobs[i];
        auto* u = new VehicleUpload(j.aircraft, std::move(j.plan), j.options,
                                    m_links[j.connection.text()].get());
        const int index = int(i);
        connect(u, &VehicleUpload::progressChanged, this, [this, index] { emit jobProgress(index); });
        connect(u, &VehicleUpload::vehicleFound, this,
                [this, index](const QString& d) { emit jobVehicle(index, d); });
        connect(u, &VehicleUpload::finished, this, [this, index] { onJobFinished(index); });
        m_uploads.push_back(u);
    }
    for (auto* u : m_uploads)
        u->start();
    return true;
}

void UploadManager::cancel() {
    for (auto* u : m_uploads)
        u->abort(tr("cancelled"));
}

void UploadManager::onJobFinished(int index) {
    emit jobFinished(index, m_uploads[std::size_t(index)]->succeeded());
    if (++m_done < int(m_uploads.size()))
        return;
    int ok = 0;
    for (const auto* u : m_uploads)
        ok += u->succeeded();
    emit allFinished(ok, int(m_uploads.size()) - ok);
}

} // namespace pf::ui
