// The MAVLink messages Photoflight speaks (common.xml): ids, CRC extra bytes and payload layouts
// (fields ordered by size as the wire rules say, MAVLink 2 extension fields after them), with the
// enum values the mission protocol needs.
#pragma once

#include "core/mavlink/frame.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace pf::mavlink {

namespace msg {
constexpr std::uint32_t kHeartbeat = 0;
constexpr std::uint32_t kMissionItem = 39;
constexpr std::uint32_t kMissionRequest = 40;
constexpr std::uint32_t kMissionRequestList = 43;
constexpr std::uint32_t kMissionCount = 44;
constexpr std::uint32_t kMissionClearAll = 45;
constexpr std::uint32_t kMissionAck = 47;
constexpr std::uint32_t kMissionRequestInt = 51;
constexpr std::uint32_t kMissionItemInt = 73;
constexpr std::uint32_t kStatusText = 253;
} // namespace msg

// MAV_MISSION_TYPE
enum class MissionType : std::uint8_t { Mission = 0, Fence = 1, Rally = 2, All = 255 };
const char* missionTypeName(MissionType type); // "mission", "geofence", "rally points"

// MAV_MISSION_RESULT
constexpr std::uint8_t kMissionAccepted = 0;
constexpr std::uint8_t kMissionError = 1;
constexpr std::uint8_t kMissionInvalidSequence = 13;
constexpr std::uint8_t kMissionOperationCancelled = 15;
// The result in words ("the vehicle has no space for that many items", ...).
std::string missionResultText(std::uint8_t result);

constexpr std::uint8_t kMavTypeGcs = 6;          // MAV_TYPE_GCS
constexpr std::uint8_t kMavAutopilotInvalid = 8; // MAV_AUTOPILOT_INVALID: not a flight controller
std::string vehicleTypeName(std::uint8_t mavType);
std::string autopilotName(std::uint8_t mavAutopilot);

struct Heartbeat {
    std::uint32_t customMode = 0;
    std::uint8_t type = 0;
    std::uint8_t autopilot = 0;
    std::uint8_t baseMode = 0;
    std::uint8_t systemStatus = 0;
    std::uint8_t mavlinkVersion = 3;
};

struct StatusText {
    std::uint8_t severity = 6; // MAV_SEVERITY_INFO
    std::string text;          // at most 50 characters on the wire
};

// MISSION_COUNT, MISSION_REQUEST_LIST, MISSION_CLEAR_ALL, MISSION_REQUEST(_INT) and MISSION_ACK
// share this shape; `value` is the count, the sequence number or the result.
struct MissionControl {
    std::uint8_t targetSystem = 0;
    std::uint8_t targetComponent = 0;
    std::uint16_t value = 0;
    MissionType type = MissionType::Mission;
};

// MISSION_ITEM_INT as on the wire: latitude and longitude in 1e-7 degrees, altitude in metres
// (MISSION_ITEM, the float form, is converted to this one).
struct MissionItemInt {
    std::uint8_t targetSystem = 0;
    std::uint8_t targetComponent = 0;
    std::uint16_t seq = 0;
    std::uint8_t frame = 0;
    std::uint16_t command = 0;
    std::uint8_t current = 0;
    std::uint8_t autocontinue = 1;
    std::array<float, 4> params{0, 0, 0, 0};
    std::int32_t x = 0;
    std::int32_t y = 0;
    float z = 0;
    MissionType type = MissionType::Mission;
};

// Encoders give a frame without sender ids and sequence (the link fills them in).
Frame encode(const Heartbeat& m);
Frame encode(const StatusText& m);
Frame encodeControl(std::uint32_t messageId, const MissionControl& m);
Frame encode(const MissionItemInt& m);
// The float MISSION_ITEM for vehicles that ask with MISSION_REQUEST (x, y as degrees).
Frame encodeFloatItem(const MissionItemInt& m);

// Decoders return nullopt when the frame holds another message.
std::optional<Heartbeat> decodeHeartbeat(const Frame& f);
std::optional<StatusText> decodeStatusText(const Frame& f);
std::optional<MissionControl> decodeControl(const Frame& f, std::uint32_t messageId);
// MISSION_ITEM_INT or MISSION_ITEM.
std::optional<MissionItemInt> decodeItem(const Frame& f);

} // namespace pf::mavlink
