#include "core/mavlink/messages.h"

#include <cmath>
#include <cstring>

namespace pf::mavlink {

namespace {

// Little-endian payload writer and reader. The reader pads a short payload with zeros: MAVLink 2
// cuts trailing zero bytes, and MAVLink 1 senders do not know the extension fields.
class Writer {
public:
    explicit Writer(std::size_t size) : m_b(size, 0) {}
    Writer& u8(std::uint8_t v) { m_b[m_pos++] = v; return *this; }
    Writer& u16(std::uint16_t v) { return u8(v & 0xFF).u8(v >> 8); }
    Writer& u32(std::uint32_t v) { return u16(v & 0xFFFF).u16(v >> 16); }
    Writer& i32(std::int32_t v) { return u32(static_cast<std::uint32_t>(v)); }
    Writer& f32(float v) {
        std::uint32_t u;
        std::memcpy(&u, &v, 4);
        return u32(u);
    }
    Bytes take() { return std::move(m_b); }

private:
    Bytes m_b;
    std::size_t m_pos = 0;
};

class Reader {
public:
    Reader(const Bytes& b, std::size_t size) : m_b(b), m_size(size) {}
    std::uint8_t u8() { return m_pos < m_b.size() && m_pos < m_size ? m_b[m_pos++] : (++m_pos, 0); }
    std::uint16_t u16() { std::uint16_t lo = u8(); return static_cast<std::uint16_t>(lo | (u8() << 8)); }
    std::uint32_t u32() { std::uint32_t lo = u16(); return lo | (static_cast<std::uint32_t>(u16()) << 16); }
    std::int32_t i32() { return static_cast<std::int32_t>(u32()); }
    float f32() {
        const std::uint32_t u = u32();
        float v;
        std::memcpy(&v, &u, 4);
        return v;
    }

private:
    const Bytes& m_b;
    std::size_t m_size;
    std::size_t m_pos = 0;
};

struct Info {
    std::uint32_t id;
    std::uint8_t crcExtra;
    std::uint8_t length; // with the extension fields we use
};

// From common.xml: CRC extra over the base fields, lengths including the extensions we write.
constexpr Info kInfo[] = {
    {msg::kHeartbeat, 50, 9},          {msg::kMissionItem, 254, 38},
    {msg::kMissionRequest, 230, 5},    {msg::kMissionRequestList, 132, 3},
    {msg::kMissionCount, 221, 5},      {msg::kMissionClearAll, 232, 3},
    {msg::kMissionAck, 153, 4},        {msg::kMissionRequestInt, 196, 5},
    {msg::kMissionItemInt, 38, 38},    {msg::kStatusText, 83, 54},
};

const Info* infoFor(std::uint32_t id) {
    for (const auto& i : kInfo)
        if (i.id == id)
            return &i;
    return nullptr;
}

Frame frameOf(std::uint32_t id, Bytes payload) {
    Frame f;
    f.messageId = id;
    f.payload = std::move(payload);
    return f;
}

Bytes itemPayload(const MissionItemInt& m, bool asFloat) {
    Writer w(38);
    for (float p : m.params)
        w.f32(p);
    if (asFloat)
        w.f32(static_cast<float>(m.x * 1e-7)).f32(static_cast<float>(m.y * 1e-7));
    else
        w.i32(m.x).i32(m.y);
    w.f32(m.z).u16(m.seq).u16(m.command).u8(m.targetSystem).u8(m.targetComponent).u8(m.frame);
    w.u8(m.current).u8(m.autocontinue).u8(static_cast<std::uint8_t>(m.type));
    return w.take();
}

} // namespace

std::optional<std::uint8_t> crcExtraFor(std::uint32_t messageId) {
    if (const Info* i = infoFor(messageId))
        return i->crcExtra;
    return std::nullopt;
}

const char* missionTypeName(MissionType type) {
    switch (type) {
    case MissionType::Mission:
        return "mission";
    case MissionType::Fence:
        return "geofence";
    case MissionType::Rally:
        return "rally points";
    case MissionType::All:
        return "all plans";
    }
    return "plan";
}

std::string missionResultText(std::uint8_t r) {
    switch (r) {
    case 0: return "accepted";
    case 1: return "generic error (MAV_MISSION_ERROR)";
    case 2: return "a coordinate frame is not supported (MAV_MISSION_UNSUPPORTED_FRAME)";
    case 3: return "a command is not supported (MAV_MISSION_UNSUPPORTED)";
    case 4: return "the vehicle has no space for that many items (MAV_MISSION_NO_SPACE)";
    case 5: return "a parameter is invalid (MAV_MISSION_INVALID)";
    case 6: case 7: case 8: case 9:
        return "param" + std::to_string(r - 5) + " is invalid (MAV_MISSION_INVALID_PARAM" +
               std::to_string(r - 5) + ")";
    case 10: return "the latitude (x) is invalid (MAV_MISSION_INVALID_PARAM5_X)";
    case 11: return "the longitude (y) is invalid (MAV_MISSION_INVALID_PARAM6_Y)";
    case 12: return "the altitude (param7) is invalid (MAV_MISSION_INVALID_PARAM7)";
    case 13: return "an item arrived out of sequence (MAV_MISSION_INVALID_SEQUENCE)";
    case 14: return "the vehicle refuses new plans now (MAV_MISSION_DENIED)";
    case 15: return "the transfer was cancelled (MAV_MISSION_OPERATION_CANCELLED)";
    default: return "unknown result " + std::to_string(r);
    }
}

std::string vehicleTypeName(std::uint8_t t) {
    switch (t) {
    case 0: return "generic vehicle";
    case 1: return "fixed wing";
    case 2: return "quadrotor";
    case 3: return "coaxial helicopter";
    case 4: return "helicopter";
    case 6: return "ground station";
    case 10: return "ground rover";
    case 13: return "hexarotor";
    case 14: return "octorotor";
    case 15: return "tricopter";
    case 19: case 20: case 21: case 22: return "VTOL";
    default: return "vehicle type " + std::to_string(t);
    }
}

std::string autopilotName(std::uint8_t a) {
    switch (a) {
    case 0: return "generic autopilot";
    case 3: return "ArduPilot";
    case 8: return "no autopilot";
    case 12: return "PX4";
    default: return "autopilot " + std::to_string(a);
    }
}

Frame encode(const Heartbeat& m) {
    Writer w(9);
    w.u32(m.customMode).u8(m.type).u8(m.autopilot).u8(m.baseMode).u8(m.systemStatus);
    w.u8(m.mavlinkVersion);
    return frameOf(msg::kHeartbeat, w.take());
}

Frame encode(const StatusText& m) {
    Writer w(54);
    w.u8(m.severity);
    for (std::size_t i = 0; i < 50; ++i)
        w.u8(i < m.text.size() ? static_cast<std::uint8_t>(m.text[i]) : 0);
    w.u16(0).u8(0);
    return frameOf(msg::kStatusText, w.take());
}

Frame encodeControl(std::uint32_t id, const MissionControl& m) {
    const auto type = static_cast<std::uint8_t>(m.type);
    switch (id) {
    case msg::kMissionRequestList:
    case msg::kMissionClearAll: {
        Writer w(3);
        w.u8(m.targetSystem).u8(m.targetComponent).u8(type);
        return frameOf(id, w.take());
    }
    case msg::kMissionAck: {
        Writer w(4);
        w.u8(m.targetSystem).u8(m.targetComponent).u8(static_cast<std::uint8_t>(m.value)).u8(type);
        return frameOf(id, w.take());
    }
    default: { // MISSION_COUNT, MISSION_REQUEST, MISSION_REQUEST_INT: uint16 first
        Writer w(5);
        w.u16(m.value).u8(m.targetSystem).u8(m.targetComponent).u8(type);
        return frameOf(id, w.take());
    }
    }
}

Frame encode(const MissionItemInt& m) { return frameOf(msg::kMissionItemInt, itemPayload(m, false)); }

Frame encodeFloatItem(const MissionItemInt& m) {
    return frameOf(msg::kMissionItem, itemPayload(m, true));
}

std::optional<Heartbeat> decodeHeartbeat(const Frame& f) {
    if (f.messageId != msg::kHeartbeat)
        return std::nullopt;
    Reader r(f.payload, 9);
    Heartbeat h;
    h.customMode = r.u32();
    h.type = r.u8();
    h.autopilot = r.u8();
    h.baseMode = r.u8();
    h.systemStatus = r.u8();
    h.mavlinkVersion = r.u8();
    return h;
}

std::optional<StatusText> decodeStatusText(const Frame& f) {
    if (f.messageId != msg::kStatusText)
        return std::nullopt;
    Reader r(f.payload, 54);
    StatusText s;
    s.severity = r.u8();
    for (int i = 0; i < 50; ++i) {
        const auto c = static_cast<char>(r.u8());
        if (c == '\0')
            break;
        s.text += c;
    }
    return s;
}

std::optional<MissionControl> decodeControl(const Frame& f, std::uint32_t id) {
    if (f.messageId != id || !infoFor(id))
        return std::nullopt;
    Reader r(f.payload, infoFor(id)->length);
    MissionControl m;
    switch (id) {
    case msg::kMissionRequestList:
    case msg::kMissionClearAll:
        m.targetSystem = r.u8();
        m.targetComponent = r.u8();
        m.type = static_cast<MissionType>(r.u8());
        return m;
    case msg::kMissionAck:
        m.targetSystem = r.u8();
        m.targetComponent = r.u8();
        m.value = r.u8();
        m.type = static_cast<MissionType>(r.u8());
        return m;
    case msg::kMissionCount:
    case msg::kMissionRequest:
    case msg::kMissionRequestInt:
        m.value = r.u16();
        m.targetSystem = r.u8();
        m.targetComponent = r.u8();
        m.type = static_cast<MissionType>(r.u8());
        return m;
    default:
        return std::nullopt;
    }
}

std::optional<MissionItemInt> decodeItem(const Frame& f) {
    const bool isInt = f.messageId == msg::kMissionItemInt;
    if (!isInt && f.messageId != msg::kMissionItem)
        return std::nullopt;
    Reader r(f.payload, 38);
    MissionItemInt m;
    for (float& p : m.params)
        p = r.f32();
    if (isInt) {
        m.x = r.i32();
        m.y = r.i32();
    } else {
        m.x = static_cast<std::int32_t>(std::lround(static_cast<double>(r.f32()) * 1e7));
        m.y = static_cast<std::int32_t>(std::lround(static_cast<double>(r.f32()) * 1e7));
    }
    m.z = r.f32();
    m.seq = r.u16();
    m.command = r.u16();
    m.targetSystem = r.u8();
    m.targetComponent = r.u8();
    m.frame = r.u8();
    m.current = r.u8();
    m.autocontinue = r.u8();
    m.type = static_cast<MissionType>(r.u8());
    return m;
}

} // namespace pf::mavlink
