// The mission protocol state machine against a scripted vehicle in the same process (time is
// simulated, so timeouts cost nothing). The independent vehicle on loopback is tests/peers/.
#include "core/mavlink/mission_transfer.h"

#include <gtest/gtest.h>

#include <map>

using namespace pf::mavlink;

namespace {

// A minimal autopilot: answers the upload and download transactions per plan type.
struct ScriptedVehicle {
    std::uint8_t sysid = 1;
    bool silent = false;         // no heartbeat, no answers
    bool useOldRequest = false;  // MISSION_REQUEST instead of MISSION_REQUEST_INT
    int dropRequestSeq = -1;     // the first request for this seq is never sent
    int nackAtSeq = -1;          // answer the item with this seq with a NACK
    std::uint8_t nackCode = 4;
    bool corruptReadback = false;
    std::map<MissionType, std::vector<MissionItemInt>> stored;
    std::map<MissionType, std::uint16_t> expecting;
    FrameParser parser;
    Bytes out;
    std::uint8_t seq = 0;
    int requestsSent = 0;

    void send(Frame f) {
        f.systemId = sysid;
        f.componentId = 1;
        f.seq = seq++;
        auto b = encodeFrame(f);
        out.insert(out.end(), b.begin(), b.end());
    }
    void heartbeat() {
        if (silent)
            return;
        Heartbeat hb;
        hb.type = 2;
        hb.autopilot = 3;
        send(encode(hb));
    }
    void request(MissionType t, std::uint16_t s) {
        if (int(s) == dropRequestSeq) {
            dropRequestSeq = -1;
            return;
        }
        ++requestsSent;
        MissionControl c{255, 190, s, t};
        send(encodeControl(useOldRequest ? msg::kMissionRequest : msg::kMissionRequestInt, c));
    }
    void ack(MissionType t, std::uint8_t r) { send(encodeControl(msg::kMissionAck, {255, 190, r, t})); }

    void receive(const Bytes& b) {
        if (silent)
            return;
        for (const auto& f : parser.feed(b)) {
            if (auto c = decodeControl(f, msg::kMissionCount); c && c->targetSystem == sysid) {
                stored[c->type].clear();
                expecting[c->type] = c->value;
                if (c->value == 0)
                    ack(c->type, kMissionAccepted);
                else
                    request(c->type, 0);
            } else if (auto it = decodeItem(f); it && it->targetSystem == sysid) {
                auto& list = stored[it->type];
                if (!list.empty() && it->seq + 1u == list.size() && list.size() < expecting[it->type]) {
                    // The GCS resent the last item: our request for the next one was lost.
                    request(it->type, static_cast<std::uint16_t>(list.size()));
                    continue;
                }
                if (it->seq != list.size())
                    continue;
                if (int(it->seq) == nackAtSeq)
                    return ack(it->type, nackCode);
                list.push_back(*it);
                if (list.size() < expecting[it->type])
                    request(it->type, static_cast<std::uint16_t>(list.size()));
                else
                    ack(it->type, kMissionAccepted);
            } else if (auto l = decodeControl(f, msg::kMissionRequestList); l && l->targetSystem == sysid) {
                send(encodeControl(msg::kMissionCount,
                                   {255, 190, static_cast<std::uint16_t>(stored[l->type].size()), l->type}));
            } else if (auto r = decodeControl(f, msg::kMissionRequestInt); r && r->targetSystem == sysid) {
                MissionItemInt item = stored[r->type].at(r->value);
                if (corruptReadback && r->type == MissionType::Mission && r->value == 2)
                    item.z += 1.0f;
                item.targetSystem = 255;
                item.targetComponent = 190;
                send(encode(item));
            }
        }
    }
};

VehiclePlan samplePlan(std::size_t n) {
    VehiclePlan p;
    for (std::size_t i = 0; i < n; ++i) {
        MissionItemInt it;
        it.command = 16;
        it.frame = 3;
        it.x = 490000000 + static_cast<std::int32_t>(i) * 100;
        it.y = 84000000;
        it.z = 40;
        it.params = {0, 0, 0, 90};
        p.mission.push_back(it);
    }
    MissionItemInt v;
    v.command = 5002;
    v.frame = 0;
    v.params = {3, 0, 0, 0};
    for (int k = 0; k < 3; ++k) {
        v.x = 490001000 + k * 50;
        v.y = 84001000 + (k == 1 ? 80 : 0);
        p.fence.push_back(v);
    }
    MissionItemInt r;
    r.command = 5100;
    r.frame = 3;
    r.x = 490000500;
    r.y = 84000500;
    r.z = 40;
    p.rally.push_back(r);
    return p;
}

// Runs the exchange in 10 ms steps until the transfer ends or `limitMs` passes.
std::int64_t run(MissionTransfer& t, ScriptedVehicle& v, std::int64_t limitMs = 120000) {
    std::int64_t now = 0;
    t.start(now);
    v.heartbeat();
    while (!t.finished() && now < limitMs) {
        v.receive(t.takeOutgoing());
        t.receive(v.out, now);
        v.out.clear();
        now += 10;
        if (now % 1000 == 0)
            v.heartbeat();
        t.tick(now);
    }
    return now;
}

} // namespace

TEST(MissionTransfer, UploadsEveryPlanTypeAndVerifiesTheReadBack) {
    ScriptedVehicle v;
    MissionTransfer t(samplePlan(12), {});
    run(t, v);
    ASSERT_TRUE(t.succeeded()) << t.message();
    EXPECT_EQ(v.stored[MissionType::Mission].size(), 12u);
    EXPECT_EQ(v.stored[MissionType::Fence].size(), 3u);
    EXPECT_EQ(v.stored[MissionType::Rally].size(), 1u);
    EXPECT_EQ(v.stored[MissionType::Mission][7].x, 490000700);
    EXPECT_EQ(v.stored[MissionType::Mission][7].seq, 7);
    EXPECT_EQ(t.progress().done, t.progress().total);
    EXPECT_EQ(t.progress().total, 2u * 16u);
    ASSERT_TRUE(t.vehicle());
    EXPECT_EQ(t.vehicle()->systemId, 1);
    EXPECT_EQ(t.vehicle()->autopilot, 3);
    EXPECT_NE(t.message().find("mission 12 items"), std::string::npos) << t.message();
}

TEST(MissionTransfer, ALostRequestIsRecoveredByResendingTheLastItem) {
    ScriptedVehicle v;
    v.dropRequestSeq = 4;
    MissionTransfer t(samplePlan(8), {});
    const auto took = run(t, v);
    ASSERT_TRUE(t.succeeded()) << t.message();
    EXPECT_EQ(v.stored[MissionType::Mission].size(), 8u);
    EXPECT_GE(took, 1500); // one reply timeout passed before the resend
}

TEST(MissionTransfer, ANackIsReportedWithItsReason) {
    ScriptedVehicle v;
    v.nackAtSeq = 3;
    v.nackCode = 4;
    MissionTransfer t(samplePlan(8), {});
    run(t, v);
    ASSERT_TRUE(t.finished());
    EXPECT_FALSE(t.succeeded());
    EXPECT_NE(t.message().find("refused the mission"), std::string::npos) << t.message();
    EXPECT_NE(t.message().find("no space"), std::string::npos) << t.message();
}

TEST(MissionTransfer, NoVehicleIsAClearTimeout) {
    ScriptedVehicle v;
    v.silent = true;
    TransferOptions o;
    o.heartbeatTimeoutMs = 3000;
    MissionTransfer t(samplePlan(3), o);
    const auto took = run(t, v);
    EXPECT_FALSE(t.succeeded());
    EXPECT_NE(t.message().find("no heartbeat"), std::string::npos) << t.message();
    EXPECT_GE(took, 3000);
    EXPECT_LE(took, 3100);
}

TEST(MissionTransfer, AVehicleThatStopsAnsweringFailsAfterTheRetries) {
    ScriptedVehicle v;
    v.nackAtSeq = -1;
    v.dropRequestSeq = -1;
    MissionTransfer t(samplePlan(4), {});
    std::int64_t now = 0;
    t.start(now);
    v.heartbeat();
    t.receive(v.out, now);
    v.out.clear();
    while (!t.finished() && now < 60000) { // the vehicle hears nothing more
        (void)t.takeOutgoing();
        now += 10;
        t.tick(now);
    }
    EXPECT_FALSE(t.succeeded());
    EXPECT_NE(t.message().find("stopped answering"), std::string::npos) << t.message();
    EXPECT_NEAR(static_cast<double>(now), 6 * 1500.0, 20.0);
}

TEST(MissionTransfer, OlderVehiclesAskingWithMissionRequestGetFloatItems) {
    ScriptedVehicle v;
    v.useOldRequest = true;
    MissionTransfer t(samplePlan(5), {});
    run(t, v);
    ASSERT_TRUE(t.succeeded()) << t.message();
    EXPECT_NEAR(v.stored[MissionType::Mission][4].x, 490000400, 50);
}

TEST(MissionTransfer, ADifferentReadBackIsAFailureNamingTheItem) {
    ScriptedVehicle v;
    v.corruptReadback = true;
    MissionTransfer t(samplePlan(5), {});
    run(t, v);
    EXPECT_FALSE(t.succeeded());
    EXPECT_NE(t.message().find("mission item 2"), std::string::npos) << t.message();
    EXPECT_NE(t.message().find("altitude"), std::string::npos) << t.message();
}

TEST(MissionTransfer, AnArduPilotGetsTheHomeAsItemZeroAndMayReplaceIt) {
    ScriptedVehicle v; // its heartbeat says ArduPilot (3)
    VehiclePlan plan = samplePlan(4);
    MissionItemInt home;
    home.command = 16;
    home.x = 480000000; // far from where the vehicle will say its home is
    home.y = 80000000;
    plan.home = home;
    MissionTransfer t(plan, {});
    std::int64_t now = 0;
    t.start(now);
    v.heartbeat();
    while (!t.finished() && now < 60000) {
        v.receive(t.takeOutgoing());
        if (!v.stored[MissionType::Mission].empty())
            v.stored[MissionType::Mission][0].x = 490107000; // the vehicle's own home
        t.receive(v.out, now);
        v.out.clear();
        now += 10;
        t.tick(now);
    }
    ASSERT_TRUE(t.succeeded()) << t.message();
    EXPECT_EQ(v.stored[MissionType::Mission].size(), 5u);
    EXPECT_EQ(v.stored[MissionType::Mission][1].command, 16);
    EXPECT_EQ(t.progress().done, t.progress().total);
}

TEST(MissionTransfer, OnlyTheBoundSystemIdIsTalkedTo) {
    ScriptedVehicle other;
    other.sysid = 9;
    ScriptedVehicle v;
    v.sysid = 2;
    TransferOptions o;
    o.targetSystem = 2;
    MissionTransfer t(samplePlan(3), o);
    std::int64_t now = 0;
    t.start(now);
    while (!t.finished() && now < 60000) {
        if (now % 1000 == 0) {
            other.heartbeat();
            v.heartbeat();
        }
        const Bytes b = t.takeOutgoing();
        other.receive(b);
        v.receive(b);
        t.receive(other.out, now);
        t.receive(v.out, now);
        other.out.clear();
        v.out.clear();
        now += 10;
        t.tick(now);
    }
    ASSERT_TRUE(t.succeeded()) << t.message();
    EXPECT_EQ(t.vehicle()->systemId, 2);
    EXPECT_EQ(v.stored[MissionType::Mission].size(), 3u);
    EXPECT_TRUE(other.stored[MissionType::Mission].empty());
}
