// The MAVLink mission protocol with one vehicle, as a state machine without sockets or clocks: bytes
// in, bytes out, the time given by the caller. It waits for the vehicle's heartbeat, uploads the
// mission, the geofence and the rally points (MISSION_COUNT, answering MISSION_REQUEST_INT and the
// older MISSION_REQUEST, MISSION_ACK), with the protocol's timeouts and retries, then downloads each
// again (MISSION_REQUEST_LIST) and compares it item by item before it says "uploaded".
#pragma once

#include "core/mavlink/frame.h"
#include "core/mavlink/messages.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pf::mavlink {

// What goes to one vehicle: the items of each plan type in order (seq, targets and type are filled in
// by the transfer). ArduPilot keeps the home position as mission item 0: `home` is sent first when
// the vehicle's heartbeat says ArduPilot, and its position is not compared on read-back (the vehicle
// replaces it with its own home).
struct VehiclePlan {
    std::optional<MissionItemInt> home;
    std::vector<MissionItemInt> mission;
    std::vector<MissionItemInt> fence;
    std::vector<MissionItemInt> rally;
};

struct TransferOptions {
    std::uint8_t ownSystemId = 255;    // a ground station
    std::uint8_t ownComponentId = 190; // MAV_COMP_ID_MISSIONPLANNER
    std::uint8_t targetSystem = 0;     // 0: the first autopilot heard on the link
    std::uint8_t targetComponent = 0;  // 0: the component of the vehicle's heartbeat
    std::int64_t heartbeatTimeoutMs = 5000;
    std::int64_t replyTimeoutMs = 1500; // per request, as the protocol's reference implementations
    int retries = 5;                    // resends after a timeout before giving up
    std::int64_t heartbeatIntervalMs = 1000; // our own GCS heartbeat
    bool verify = true; // download and compare after the upload
    // For messages: where the vehicle is expected ("UDP 127.0.0.1:14550"), and whether it is a serial
    // link (then the baud rate is worth checking).
    std::string linkDescription;
    bool serialLink = false;
};

enum class TransferPhase { NotStarted, WaitingForVehicle, Uploading, Verifying, Succeeded, Failed };

struct VehicleIdentity {
    std::uint8_t systemId = 0;
    std::uint8_t componentId = 0;
    std::uint8_t type = 0;      // MAV_TYPE
    std::uint8_t autopilot = 0; // MAV_AUTOPILOT
};

struct TransferProgress {
    TransferPhase phase = TransferPhase::NotStarted;
    MissionType type = MissionType::Mission; // plan being sent or checked
    std::size_t done = 0;                    // items sent and read back so far, every plan type
    std::size_t total = 0;                   // items to send and read back
};

class MissionTransfer {
public:
    MissionTransfer(VehiclePlan plan, TransferOptions options);

    void start(std::int64_t nowMs);
    void receive(const std::uint8_t* data, std::size_t n, std::int64_t nowMs);
    void receive(const Bytes& bytes, std::int64_t nowMs) { receive(bytes.data(), bytes.size(), nowMs); }
    void receiveFrame(const Frame& frame, std::int64_t nowMs);
    // Timeouts, retries and heartbeats: call often (every 50-100 ms is plenty).
    void tick(std::int64_t nowMs);
    // Bytes to send to the vehicle since the last call.
    Bytes takeOutgoing();

    bool finished() const;
    bool succeeded() const { return m_progress.phase == TransferPhase::Succeeded; }
    TransferProgress progress() const { return m_progress; }
    // The failure in plain words (empty unless failed), or the summary once it succeeded.
    const std::string& message() const { return m_message; }
    std::optional<VehicleIdentity> vehicle() const { return m_vehicle; }
    // STATUSTEXT messages of the vehicle during the transfer ("Flight plan received", ...).
    const std::vector<std::string>& vehicleMessages() const { return m_vehicleText; }
    // Notes that are not failures (a vehicle without geofence support for an empty fence, a lost
    // acknowledgement that the read-back settled).
    const std::vector<std::string>& notes() const { return m_notes; }

private:
    enum class Step { Count, Items, List, Download };
    void send(Frame f);
    void fail(std::string why);
    void beginType(std::int64_t now);
    void beginDownload(std::int64_t now);
    void nextType(std::int64_t now);
    void requestItem(std::uint16_t seq, std::int64_t now);
    void onUploadRequest(std::uint16_t seq, bool asInt, std::int64_t now);
    void onAck(std::uint8_t result, std::int64_t now);
    void onCount(std::uint16_t count, std::int64_t now);
    void onItem(const MissionItemInt& item, bool asFloat, std::int64_t now);
    void compareDownload(std::int64_t now);
    void onTimeout(std::int64_t now);
    const std::vector<MissionItemInt>& items(MissionType t) const;
    bool fromVehicle(const Frame& f) const;
    std::string itemLabel(std::size_t seq) const;

    VehiclePlan m_plan;
    TransferOptions m_opt;
    FrameParser m_parser;
    Bytes m_out;
    std::uint8_t m_seq = 0;
    TransferProgress m_progress;
    std::string m_message;
    std::optional<VehicleIdentity> m_vehicle;
    std::vector<std::string> m_vehicleText;
    std::vector<std::string> m_notes;
    std::vector<std::string> m_summary;

    std::size_t m_typeIndex = 0;
    Step m_step = Step::Count;
    Frame m_lastSent;
    int m_attempts = 0;
    std::int64_t m_deadline = 0;
    std::int64_t m_startedAt = 0;
    std::int64_t m_nextHeartbeat = 0;
    int m_highestRequested = -1;
    std::size_t m_expectedCount = 0;
    std::vector<MissionItemInt> m_downloaded;
    std::vector<bool> m_downloadedAsFloat;
    bool m_homeIsItemZero = false; // ArduPilot: plan.home went first
    bool m_sentFloat = false; // this plan type went up as float MISSION_ITEMs
};

} // namespace pf::mavlink
