// UploadManager: uploads the routes of several aircraft in parallel, each bound to a connection and
// a system id; aircraft on the same connection share its link. Used by the Ground station dialog and
// by `photoflight-cli upload`.
#pragma once

#include "core/io/export_context.h"
#include "core/mavlink/connection_spec.h"
#include "core/mavlink/mission_transfer.h"
#include "core/result.h"

#include <QObject>
#include <QString>

#include <map>
#include <memory>
#include <vector>

namespace pf::ui {

class VehicleLink;
class VehicleUpload;

// One aircraft's upload: where its vehicle is and what it gets.
struct UploadJob {
    QString aircraft;
    mavlink::ConnectionSpec connection;
    int systemId = 0; // 0: the first autopilot heard on the connection (only one aircraft may use it)
    mavlink::VehiclePlan plan;
    mavlink::TransferOptions options;
};

// The job for route `routeIndex` of ctx: the same items as the .plan/.waypoints export with
// `exportOptions`, the fence and the rally point.
Result<UploadJob> makeUploadJob(const io::ExportContext& ctx, std::size_t routeIndex,
                                const mavlink::ConnectionSpec& connection, int systemId,
                                const io::ExportOptions& exportOptions);

// Two aircraft on one connection need distinct, explicit system ids.
Status checkBindings(const std::vector<UploadJob>& jobs);

class UploadManager : public QObject {
    Q_OBJECT
public:
    explicit UploadManager(QObject* parent = nullptr);
    ~UploadManager() override;

    // Opens the links and starts every job; false with `error` when a binding is ambiguous or a
    // link cannot be opened (nothing is started then).
    bool start(std::vector<UploadJob> jobs, QString* error);
    void cancel();
    bool isRunning() const;

    std::size_t jobCount() const { return m_uploads.size(); }
    const VehicleUpload* upload(std::size_t i) const { return m_uploads[i]; }

signals:
    void jobProgress(int index);
    void jobVehicle(int index, const QString& description);
    void jobFinished(int index, bool ok);
    void allFinished(int succeeded, int failed);

private:
    void onJobFinished(int index);
    std::map<std::string, std::unique_ptr<VehicleLink>> m_links;
    std::vector<VehicleUpload*> m_uploads;
    int m_done = 0;
};

} // namespace pf::ui
