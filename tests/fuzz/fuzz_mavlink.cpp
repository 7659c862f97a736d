// libFuzzer harness: MAVLink bytes from a vehicle (or a noisy radio) into the frame parser and into a
// mission transfer that has found its vehicle and is uploading.
#include "core/mavlink/frame.h"
#include "core/mavlink/messages.h"
#include "core/mavlink/mission_transfer.h"

#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    pf::mavlink::FrameParser parser;
    for (const auto& f : parser.feed(data, size)) {
        (void)pf::mavlink::decodeItem(f);
        (void)pf::mavlink::decodeStatusText(f);
        (void)pf::mavlink::decodeControl(f, pf::mavlink::msg::kMissionCount);
    }

    pf::mavlink::VehiclePlan plan;
    for (int i = 0; i < 5; ++i) {
        pf::mavlink::MissionItemInt it;
        it.command = 16;
        it.frame = 3;
        it.x = 490000000 + i;
        it.y = 84000000;
        it.z = 40;
        plan.mission.push_back(it);
    }
    plan.fence = plan.mission;
    plan.home = plan.mission.front();
    pf::mavlink::MissionTransfer t(plan, {});
    t.start(0);
    pf::mavlink::Heartbeat hb;
    hb.type = 2;
    hb.autopilot = 3;
    pf::mavlink::Frame f = pf::mavlink::encode(hb);
    f.systemId = 1;
    f.componentId = 1;
    t.receive(pf::mavlink::encodeFrame(f), 0);
    // The input in pieces, 100 ms apart, so timeouts and retries are exercised too.
    std::int64_t now = 0;
    for (std::size_t pos = 0; pos < size && !t.finished(); pos += 64) {
        now += 100;
        t.receive(data + pos, std::min<std::size_t>(64, size - pos), now);
        t.tick(now);
        (void)t.takeOutgoing();
    }
    return 0;
}
