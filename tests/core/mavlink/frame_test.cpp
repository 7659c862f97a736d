// MAVLink framing: the checksum, MAVLink 2 encoding with payload truncation, and stream parsing.
#include "core/mavlink/crc.h"
#include "core/mavlink/frame.h"
#include "core/mavlink/messages.h"

#include <gtest/gtest.h>

#include <string>

using namespace pf::mavlink;

TEST(MavlinkCrc, MatchesTheCrc16Mcrf4xxCheckValue) {
    // CRC-16/MCRF4XX (the MAVLink "X.25" checksum) of "123456789" is 0x6F91.
    const std::string s = "123456789";
    X25Crc crc;
    crc.add(reinterpret_cast<const std::uint8_t*>(s.data()), s.size());
    EXPECT_EQ(crc.value(), 0x6F91);
}

TEST(MavlinkFrame, HeartbeatHasTheMavlink2HeaderAndRoundTrips) {
    Heartbeat hb;
    hb.type = 2;
    hb.autopilot = 3;
    hb.customMode = 0x01020304;
    Frame f = encode(hb);
    f.systemId = 7;
    f.componentId = 1;
    f.seq = 42;
    const Bytes b = encodeFrame(f);
    ASSERT_EQ(b.size(), 10u + 9u + 2u);
    EXPECT_EQ(b[0], kMagicV2);
    EXPECT_EQ(b[1], 9); // mavlink_version 3 is the last byte: nothing to cut
    EXPECT_EQ(b[4], 42);
    EXPECT_EQ(b[5], 7);
    EXPECT_EQ(b[10], 0x04); // custom_mode little endian first
    FrameParser p;
    auto frames = p.feed(b);
    ASSERT_EQ(frames.size(), 1u);
    auto back = decodeHeartbeat(frames[0]);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->customMode, 0x01020304u);
    EXPECT_EQ(back->type, 2);
    EXPECT_EQ(back->autopilot, 3);
    EXPECT_EQ(frames[0].systemId, 7);
}

TEST(MavlinkFrame, TrailingZerosAreCutButOneByteIsKept) {
    MissionControl c; // all zero: MISSION_REQUEST_LIST to system 0 for the mission
    const Bytes b = encodeFrame(encodeControl(msg::kMissionRequestList, c));
    EXPECT_EQ(b[1], 1); // one payload byte kept
    MissionControl d;
    d.targetSystem = 1;
    d.targetComponent = 1;
    d.value = 300;
    d.type = MissionType::Fence;
    const Bytes e = encodeFrame(encodeControl(msg::kMissionCount, d));
    EXPECT_EQ(e[1], 5);
    FrameParser p;
    auto frames = p.feed(e);
    ASSERT_EQ(frames.size(), 1u);
    auto back = decodeControl(frames[0], msg::kMissionCount);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->value, 300);
    EXPECT_EQ(back->type, MissionType::Fence);
    // A truncated payload decodes with zeros: mission_type 0 = mission.
    MissionControl m = d;
    m.type = MissionType::Mission;
    const Bytes t = encodeFrame(encodeControl(msg::kMissionCount, m));
    EXPECT_EQ(t[1], 4);
    auto tb = decodeControl(p.feed(t).at(0), msg::kMissionCount);
    EXPECT_EQ(tb->type, MissionType::Mission);
}

TEST(MavlinkFrame, ParserSkipsGarbageBadChecksumsAndJoinsSplitFrames) {
    MissionItemInt item;
    item.seq = 5;
    item.command = 16;
    item.frame = 3;
    item.params = {1.5f, 0, 0, 90};
    item.x = 490123456;
    item.y = 84012345;
    item.z = 40.25f;
    item.type = MissionType::Mission;
    const Bytes good = encodeFrame(encode(item));
    Bytes bad = good;
    bad[12] ^= 0x55; // payload damaged: checksum no longer matches
    Bytes stream = {0x00, 0xFD, 0x13};
    stream.insert(stream.end(), bad.begin(), bad.end());
    stream.insert(stream.end(), good.begin(), good.end());
    FrameParser p;
    std::vector<Frame> frames;
    for (std::size_t i = 0; i < stream.size(); i += 7) {
        auto part = p.feed(stream.data() + i, std::min<std::size_t>(7, stream.size() - i));
        frames.insert(frames.end(), part.begin(), part.end());
    }
    ASSERT_EQ(frames.size(), 1u);
    EXPECT_GE(p.badChecksums(), 1u);
    auto back = decodeItem(frames[0]);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->seq, 5);
    EXPECT_EQ(back->command, 16);
    EXPECT_EQ(back->x, 490123456);
    EXPECT_EQ(back->y, 84012345);
    EXPECT_FLOAT_EQ(back->z, 40.25f);
    EXPECT_FLOAT_EQ(back->params[3], 90.0f);
}

TEST(MavlinkFrame, FloatItemCarriesDegrees) {
    MissionItemInt item;
    item.x = 490000000;
    item.y = 84000000;
    auto back = decodeItem(encodeFloatItem(item));
    ASSERT_TRUE(back);
    EXPECT_NEAR(back->x, 490000000, 50);
    EXPECT_NEAR(back->y, 84000000, 50);
}

TEST(MavlinkFrame, StatusTextRoundTrips) {
    StatusText st;
    st.severity = 4;
    st.text = "Flight plan received";
    FrameParser p;
    auto frames = p.feed(encodeFrame(encode(st)));
    ASSERT_EQ(frames.size(), 1u);
    auto back = decodeStatusText(frames[0]);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->text, "Flight plan received");
    EXPECT_EQ(back->severity, 4);
}

TEST(MavlinkFrame, MissionResultsAreWords) {
    EXPECT_NE(missionResultText(4).find("no space"), std::string::npos);
    EXPECT_NE(missionResultText(13).find("sequence"), std::string::npos);
}

#include "core/mavlink/connection_spec.h"

TEST(ConnectionSpec, ParsesEachTransportAndNamesMistakes) {
    auto u = parseConnectionSpec("udp:127.0.0.1:14550");
    ASSERT_TRUE(u.ok());
    EXPECT_EQ(u->kind, ConnectionSpec::Kind::UdpClient);
    EXPECT_EQ(u->port, 14550);
    auto s = parseConnectionSpec("udp::14550");
    ASSERT_TRUE(s.ok());
    EXPECT_EQ(s->kind, ConnectionSpec::Kind::UdpServer);
    EXPECT_EQ(parseConnectionSpec("udpin:14551")->port, 14551);
    EXPECT_EQ(parseConnectionSpec("udp:0.0.0.0:14550")->kind, ConnectionSpec::Kind::UdpServer);
    auto t = parseConnectionSpec("tcp:localhost:5760");
    ASSERT_TRUE(t.ok());
    EXPECT_EQ(t->kind, ConnectionSpec::Kind::Tcp);
    EXPECT_EQ(t->host, "localhost");
    auto ser = parseConnectionSpec("serial:/dev/ttyUSB0:115200");
    ASSERT_TRUE(ser.ok());
    EXPECT_EQ(ser->device, "/dev/ttyUSB0");
    EXPECT_EQ(ser->baud, 115200);
    EXPECT_EQ(parseConnectionSpec("serial:/dev/ttyACM0")->baud, 57600);
    EXPECT_EQ(ser->text(), "serial:/dev/ttyUSB0:115200");
    auto noPort = parseConnectionSpec("udp:10.0.0.1");
    ASSERT_FALSE(noPort.ok());
    EXPECT_NE(noPort.error().message.find("port"), std::string::npos) << noPort.error().message;
    auto badPort = parseConnectionSpec("tcp:host:99999");
    ASSERT_FALSE(badPort.ok());
    EXPECT_NE(badPort.error().message.find("99999"), std::string::npos);
    EXPECT_FALSE(parseConnectionSpec("bluetooth:x").ok());
    EXPECT_FALSE(parseConnectionSpec("serial:/dev/ttyUSB0:fast").ok());
    EXPECT_FALSE(parseConnectionSpec("14550").ok());
}
