#include "core/mavlink/mission_transfer.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace pf::mavlink {

namespace {

constexpr MissionType kTypes[] = {MissionType::Mission, MissionType::Fence, MissionType::Rally};

std::string fmt(double v, int decimals) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

bool sameParam(float a, float b) {
    if (std::isnan(a) || std::isnan(b))
        return std::isnan(a) && std::isnan(b);
    return std::abs(a - b) <= 1e-4f * std::max(1.0f, std::abs(a));
}

} // namespace

MissionTransfer::MissionTransfer(VehiclePlan plan, TransferOptions options)
    : m_plan(std::move(plan)), m_opt(options) {
    std::size_t n = 0;
    for (auto t : kTypes)
        n += items(t).size();
    m_progress.total = m_opt.verify ? 2 * n : n;
}

const std::vector<MissionItemInt>& MissionTransfer::items(MissionType t) const {
    return t == MissionType::Fence ? m_plan.fence : t == MissionType::Rally ? m_plan.rally : m_plan.mission;
}

bool MissionTransfer::finished() const {
    return m_progress.phase == TransferPhase::Succeeded || m_progress.phase == TransferPhase::Failed;
}

void MissionTransfer::send(Frame f) {
    f.seq = m_seq++;
    f.systemId = m_opt.ownSystemId;
    f.componentId = m_opt.ownComponentId;
    const Bytes b = encodeFrame(f);
    m_out.insert(m_out.end(), b.begin(), b.end());
}

Bytes MissionTransfer::takeOutgoing() {
    Bytes out;
    out.swap(m_out);
    return out;
}

void MissionTransfer::fail(std::string why) {
    m_progress.phase = TransferPhase::Failed;
    m_message = std::move(why);
}

std::string MissionTransfer::itemLabel(std::size_t seq) const {
    return std::string(missionTypeName(m_progress.type)) + " item " + std::to_string(seq);
}

void MissionTransfer::start(std::int64_t now) {
    m_startedAt = now;
    m_progress.phase = TransferPhase::WaitingForVehicle;
    m_nextHeartbeat = now;
    tick(now);
}

void MissionTransfer::tick(std::int64_t now) {
    if (finished() || m_progress.phase == TransferPhase::NotStarted)
        return;
    if (now >= m_nextHeartbeat) {
        Heartbeat hb;
        hb.type = kMavTypeGcs;
        hb.autopilot = kMavAutopilotInvalid;
        hb.systemStatus = 4; // MAV_STATE_ACTIVE
        send(encode(hb));
        m_nextHeartbeat = now + m_opt.heartbeatIntervalMs;
    }
    if (m_progress.phase == TransferPhase::WaitingForVehicle) {
        if (now - m_startedAt >= m_opt.heartbeatTimeoutMs)
            fail("no heartbeat from " +
                 (m_opt.targetSystem ? "the vehicle with system id " + std::to_string(m_opt.targetSystem)
                                     : std::string("any vehicle")) +
                 (m_opt.linkDescription.empty() ? std::string() : " on " + m_opt.linkDescription) +
                 " within " + fmt(m_opt.heartbeatTimeoutMs / 1000.0, 1) + " s: " +
                 (m_opt.serialLink ? "check that it is powered, the cable or radio, the port and the baud rate"
                                   : "check that it is powered, connected and talking to this address and port"));
        return;
    }
    if (now >= m_deadline)
        onTimeout(now);
}

bool MissionTransfer::fromVehicle(const Frame& f) const {
    if (!m_vehicle || f.systemId != m_vehicle->systemId)
        return false;
    return m_opt.targetComponent == 0 ? f.componentId == m_vehicle->componentId
                                      : f.componentId == m_opt.targetComponent;
}

void MissionTransfer::receive(const std::uint8_t* data, std::size_t n, std::int64_t now) {
    for (const auto& f : m_parser.feed(data, n))
        receiveFrame(f, now);
}

void MissionTransfer::receiveFrame(const Frame& f, std::int64_t now) {
    if (finished() || m_progress.phase == TransferPhase::NotStarted)
        return;
    if (m_progress.phase == TransferPhase::WaitingForVehicle) {
        const auto hb = decodeHeartbeat(f);
        if (!hb || hb->type == kMavTypeGcs || hb->autopilot == kMavAutopilotInvalid)
            return;
        if (m_opt.targetSystem && f.systemId != m_opt.targetSystem)
            return;
        if (m_opt.targetComponent && f.componentId != m_opt.targetComponent)
            return;
        m_vehicle = VehicleIdentity{f.systemId, f.componentId, hb->type, hb->autopilot};
        constexpr std::uint8_t kArduPilot = 3; // MAV_AUTOPILOT_ARDUPILOTMEGA
        if (m_plan.home && hb->autopilot == kArduPilot) {
            m_plan.mission.insert(m_plan.mission.begin(), *m_plan.home);
            m_homeIsItemZero = true;
            m_progress.total += m_opt.verify ? 2 : 1;
        }
        m_progress.phase = TransferPhase::Uploading;
        m_typeIndex = 0;
        beginType(now);
        return;
    }
    if (!fromVehicle(f))
        return;
    if (auto st = decodeStatusText(f)) {
        if (m_vehicleText.size() < 50)
            m_vehicleText.push_back(st->text);
        return;
    }
    const auto targeted = [&](const MissionControl& c) {
        return (c.targetSystem == 0 || c.targetSystem == m_opt.ownSystemId) &&
               c.type == m_progress.type;
    };
    if (m_progress.phase == TransferPhase::Uploading) {
        for (auto id : {msg::kMissionRequestInt, msg::kMissionRequest})
            if (auto r = decodeControl(f, id); r && targeted(*r))
                return onUploadRequest(r->value, id == msg::kMissionRequestInt, now);
        if (auto a = decodeControl(f, msg::kMissionAck); a && targeted(*a))
            return onAck(static_cast<std::uint8_t>(a->value), now);
    } else if (m_progress.phase == TransferPhase::Verifying) {
        if (auto c = decodeControl(f, msg::kMissionCount); c && targeted(*c) && m_step == Step::List)
            return onCount(c->value, now);
        if (auto it = decodeItem(f); it && m_step == Step::Download &&
                                     (it->targetSystem == 0 || it->targetSystem == m_opt.ownSystemId) &&
                                     it->type == m_progress.type)
            return onItem(*it, f.messageId == msg::kMissionItem, now);
        if (auto a = decodeControl(f, msg::kMissionAck); a && targeted(*a) &&
                                                      a->value != kMissionAccepted)
            return fail("the vehicle stopped the read-back of the " +
                        std::string(missionTypeName(m_progress.type)) + ": " +
                        missionResultText(static_cast<std::uint8_t>(a->value)));
    }
}

void MissionTransfer::beginType(std::int64_t now) {
    m_progress.type = kTypes[m_typeIndex];
    m_progress.phase = TransferPhase::Uploading;
    m_step = Step::Count;
    m_highestRequested = -1;
    m_sentFloat = false;
    MissionControl c;
    c.targetSystem = m_vehicle->systemId;
    c.targetComponent = m_vehicle->componentId;
    c.value = static_cast<std::uint16_t>(items(m_progress.type).size());
    c.type = m_progress.type;
    m_lastSent = encodeControl(msg::kMissionCount, c);
    m_attempts = 0;
    send(m_lastSent);
    m_deadline = now + m_opt.replyTimeoutMs;
}

void MissionTransfer::onUploadRequest(std::uint16_t seq, bool asInt, std::int64_t now) {
    const auto& list = items(m_progress.type);
    if (seq >= list.size())
        return; // not ours to answer: the vehicle will time out or ask again
    MissionItemInt item = list[seq];
    item.seq = seq;
    item.targetSystem = m_vehicle->systemId;
    item.targetComponent = m_vehicle->componentId;
    item.type = m_progress.type;
    item.current = 0;
    if (static_cast<int>(seq) > m_highestRequested) {
        m_progress.done += static_cast<std::size_t>(static_cast<int>(seq) - m_highestRequested);
        m_highestRequested = seq;
    }
    m_step = Step::Items;
    m_sentFloat = m_sentFloat || !asInt;
    m_lastSent = asInt ? encode(item) : encodeFloatItem(item);
    m_attempts = 0;
    send(m_lastSent);
    m_deadline = now + m_opt.replyTimeoutMs;
}

void MissionTransfer::onAck(std::uint8_t result, std::int64_t now) {
    const auto& list = items(m_progress.type);
    const std::string what = missionTypeName(m_progress.type);
    if (result != kMissionAccepted) {
        if (list.empty() && m_progress.type != MissionType::Mission) {
            m_notes.push_back("the vehicle did not clear its " + what + " (" +
                              missionResultText(result) + "); this plan has none");
            return nextType(now);
        }
        return fail("the vehicle refused the " + what +
                    (m_highestRequested >= 0 ? " at item " + std::to_string(m_highestRequested) : "") +
                    ": " + missionResultText(result));
    }
    if (static_cast<std::size_t>(m_highestRequested + 1) < list.size())
        return fail("the vehicle accepted the " + what + " after only " +
                    std::to_string(m_highestRequested + 1) + " of " + std::to_string(list.size()) +
                    " items");
    if (m_opt.verify)
        return beginDownload(now);
    m_summary.push_back(what + " " + std::to_string(list.size()) + (list.size() == 1 ? " item" : " items"));
    nextType(now);
}

void MissionTransfer::nextType(std::int64_t now) {
    if (++m_typeIndex < std::size(kTypes))
        return beginType(now);
    m_progress.phase = TransferPhase::Succeeded;
    std::string s;
    for (const auto& part : m_summary)
        s += (s.empty() ? "" : ", ") + part;
    m_message = (m_opt.verify ? "uploaded and read back identical: " : "uploaded (not read back): ") + s;
}

void MissionTransfer::beginDownload(std::int64_t now) {
    m_progress.phase = TransferPhase::Verifying;
    m_step = Step::List;
    m_downloaded.clear();
    m_downloadedAsFloat.clear();
    MissionControl c;
    c.targetSystem = m_vehicle->systemId;
    c.targetComponent = m_vehicle->componentId;
    c.type = m_progress.type;
    m_lastSent = encodeControl(msg::kMissionRequestList, c);
    m_attempts = 0;
    send(m_lastSent);
    m_deadline = now + m_opt.replyTimeoutMs;
}

void MissionTransfer::onCount(std::uint16_t count, std::int64_t now) {
    m_expectedCount = count;
    if (count == 0)
        return compareDownload(now);
    m_step = Step::Download;
    requestItem(0, now);
}

void MissionTransfer::requestItem(std::uint16_t seq, std::int64_t now) {
    MissionControl c;
    c.targetSystem = m_vehicle->systemId;
    c.targetComponent = m_vehicle->componentId;
    c.value = seq;
    c.type = m_progress.type;
    m_lastSent = encodeControl(msg::kMissionRequestInt, c);
    m_attempts = 0;
    send(m_lastSent);
    m_deadline = now + m_opt.replyTimeoutMs;
}

void MissionTransfer::onItem(const MissionItemInt& item, bool asFloat, std::int64_t now) {
    if (item.seq != m_downloaded.size())
        return; // a late duplicate; the request for the one we need is pending
    m_downloaded.push_back(item);
    m_downloadedAsFloat.push_back(asFloat);
    if (m_downloaded.size() <= items(m_progress.type).size())
        ++m_progress.done;
    if (m_downloaded.size() < m_expectedCount)
        return requestItem(static_cast<std::uint16_t>(m_downloaded.size()), now);
    compareDownload(now);
}

void MissionTransfer::compareDownload(std::int64_t now) {
    MissionControl ack;
    ack.targetSystem = m_vehicle->systemId;
    ack.targetComponent = m_vehicle->componentId;
    ack.value = kMissionAccepted;
    ack.type = m_progress.type;
    if (m_expectedCount > 0)
        send(encodeControl(msg::kMissionAck, ack));
    const auto& sent = items(m_progress.type);
    const std::string what = missionTypeName(m_progress.type);
    if (m_expectedCount != sent.size())
        return fail("read-back of the " + what + " differs: the vehicle holds " +
                    std::to_string(m_expectedCount) + " items, " + std::to_string(sent.size()) +
                    " were sent");
    for (std::size_t i = 0; i < sent.size(); ++i) {
        const auto& a = sent[i];
        const auto& b = m_downloaded[i];
        const std::string where = "read-back of " + itemLabel(i) + " (command " +
                                  std::to_string(a.command) + ") differs: ";
        if (a.command != b.command)
            return fail(where + "the vehicle holds command " + std::to_string(b.command));
        if (a.frame != b.frame)
            return fail(where + "frame " + std::to_string(a.frame) + " sent, " +
                        std::to_string(b.frame) + " read back");
        const bool home = m_homeIsItemZero && i == 0 && m_progress.type == MissionType::Mission;
        if (home)
            continue;
        for (std::size_t p = 0; p < 4; ++p)
            if (!sameParam(a.params[p], b.params[p]))
                return fail(where + "param" + std::to_string(p + 1) + " " + fmt(a.params[p], 4) +
                            " sent, " + fmt(b.params[p], 4) + " read back");
        // MISSION_ITEM (float) carries only about 7 digits of a latitude.
        const std::int64_t tol = m_downloadedAsFloat[i] || m_sentFloat ? 100 : 1;
        if (std::llabs(std::int64_t{a.x} - b.x) > tol || std::llabs(std::int64_t{a.y} - b.y) > tol)
            return fail(where + "position " + fmt(a.x * 1e-7, 7) + ", " + fmt(a.y * 1e-7, 7) +
                        " sent, " + fmt(b.x * 1e-7, 7) + ", " + fmt(b.y * 1e-7, 7) + " read back");
        if (!(std::abs(a.z - b.z) <= 0.01f) && !(std::isnan(a.z) && std::isnan(b.z)))
            return fail(where + "altitude " + fmt(a.z, 2) + " m sent, " + fmt(b.z, 2) +
                        " m read back");
    }
    m_summary.push_back(what + " " + std::to_string(sent.size()) + (sent.size() == 1 ? " item" : " items"));
    nextType(now);
}

void MissionTransfer::onTimeout(std::int64_t now) {
    const std::string what = missionTypeName(m_progress.type);
    if (m_attempts >= m_opt.retries) {
        const auto& list = items(m_progress.type);
        if (m_progress.phase == TransferPhase::Uploading && m_step == Step::Items &&
            static_cast<std::size_t>(m_highestRequested + 1) == list.size() && m_opt.verify) {
            // Every item was asked for and sent; only the acknowledgement is missing. The
            // read-back decides.
            m_notes.push_back("no acknowledgement for the " + what + "; checked by reading it back");
            return beginDownload(now);
        }
        std::string stage;
        if (m_progress.phase == TransferPhase::Uploading)
            stage = m_step == Step::Count ? "to the " + what + " item count"
                                          : "after " + itemLabel(static_cast<std::size_t>(m_highestRequested));
        else
            stage = m_step == Step::List ? "to the request for its " + what
                                         : "to the request for " + itemLabel(m_downloaded.size());
        return fail("the vehicle stopped answering " + stage + " (no reply in " +
                    std::to_string(m_opt.retries + 1) + " tries of " +
                    fmt(m_opt.replyTimeoutMs / 1000.0, 1) + " s)");
    }
    ++m_attempts;
    send(m_lastSent);
    m_deadline = now + m_opt.replyTimeoutMs;
}

} // namespace pf::mavlink
