// photoflight-cli upload against an independent simulated autopilot (sim_vehicle.mjs, node-mavlink)
// on loopback: a full upload and read-back equal to the .waypoints export, a lost request recovered,
// a refusal reported with its reason, no vehicle as a clear timeout, two vehicles in parallel, a
// plane's mission with its landing.
#include "tests/peers/peer_process.h"

#include <cpl_json.h>
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using pf::test::Peer;

const std::string kDemo = std::string(PF_RESOURCES_DIR) + "/demo/demo_mission.json";

std::string scratch(const std::string& name) {
    const fs::path p = fs::temp_directory_path() / ("pf_peer_" + name + "_" + std::to_string(getpid()));
    fs::remove_all(p);
    fs::create_directories(p);
    return p.string();
}

struct CliRun {
    int code = -1;
    std::string output;
    double seconds = 0;
};

CliRun cli(const std::string& args) {
    CliRun r;
    const auto start = std::chrono::steady_clock::now();
    FILE* p = popen((std::string(PF_CLI_PATH) + " " + args + " 2>&1").c_str(), "r");
    if (!p)
        return r;
    std::array<char, 4096> buf;
    std::size_t n;
    while ((n = fread(buf.data(), 1, buf.size(), p)) > 0)
        r.output.append(buf.data(), n);
    const int st = pclose(p);
    r.code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

CPLJSONObject report(const std::string& path) {
    CPLJSONDocument doc;
    EXPECT_TRUE(doc.Load(path)) << path;
    return doc.GetRoot();
}

// A UDP port free right now on loopback (for the ground station to listen on).
int freeUdpPort() {
    const int s = socket(AF_INET, SOCK_DGRAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    bind(s, reinterpret_cast<sockaddr*>(&a), sizeof a);
    socklen_t len = sizeof a;
    getsockname(s, reinterpret_cast<sockaddr*>(&a), &len);
    close(s);
    return ntohs(a.sin_port);
}

std::string quoted(const std::string& s) { return "'" + s + "'"; }

} // namespace

TEST(PeerUpload, FullUploadAndReadBackHoldTheWaypointsFileItems) {
    const std::string dir = scratch("full");
    // ArduPilot replaces item 0 with its own home: the read-back must still match.
    Peer vehicle({"--udp", "0", "--seconds", "60", "--report", dir + "/vehicle.json", "--home",
                  "49.0107,8.3271"});
    ASSERT_GT(vehicle.port(), 0) << "the simulated vehicle did not start";
    const CliRun r = cli("upload " + quoted(kDemo) + " --aircraft 'Falcon 8' --to udp:127.0.0.1:" +
                      std::to_string(vehicle.port()) + " --home-elevation 112");
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_NE(r.output.find("found quadrotor, ArduPilot, system id 1"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("uploaded and read back identical"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("Flight plan received"), std::string::npos) << r.output;

    // The same mission exported as a .waypoints file: line k is uploaded item k.
    const CliRun plan = cli("plan " + quoted(kDemo) + " --format waypoints --home-elevation 112 --out " + dir);
    ASSERT_EQ(plan.code, 0) << plan.output;
    std::ifstream in(dir + "/mission-Falcon_8.waypoints");
    std::string line;
    std::getline(in, line);
    ASSERT_EQ(line, "QGC WPL 110");
    const CPLJSONObject rep = report(dir + "/vehicle.json");
    const CPLJSONArray items = rep.GetArray("mission");
    int k = 0;
    while (std::getline(in, line)) {
        std::istringstream f(line);
        double v[12];
        for (double& x : v)
            f >> x;
        ASSERT_LT(k, items.Size());
        const CPLJSONObject it = items[k];
        EXPECT_EQ(it.GetInteger("command"), int(v[3])) << "item " << k;
        EXPECT_EQ(it.GetInteger("frame"), int(v[2])) << "item " << k;
        if (int(v[3]) == 16 || int(v[3]) == 22) {
            EXPECT_NEAR(it.GetDouble("x") / 1e7, v[8], 1.5e-7) << "item " << k;
            EXPECT_NEAR(it.GetDouble("y") / 1e7, v[9], 1.5e-7) << "item " << k;
            EXPECT_NEAR(it.GetDouble("z"), v[10], 1e-3) << "item " << k;
        }
        ++k;
    }
    EXPECT_EQ(k, items.Size());
    EXPECT_GT(k, 100);
    EXPECT_EQ(rep.GetArray("fence").Size(), 4 + 16); // warehouse and mast vertices
    EXPECT_EQ(rep.GetArray("rally").Size(), 1);
}

TEST(PeerUpload, ALostMissionRequestIsRetried) {
    const std::string dir = scratch("lost");
    // The vehicle's own re-request comes only after 20 s: the ground station's retry must do it.
    Peer vehicle({"--udp", "0", "--seconds", "60", "--report", dir + "/vehicle.json", "--drop-request",
                  "5", "--vehicle-timeout", "20000"});
    ASSERT_GT(vehicle.port(), 0);
    const CliRun r = cli("upload " + quoted(kDemo) + " --aircraft 'Falcon 8' --to udp:127.0.0.1:" +
                      std::to_string(vehicle.port()));
    ASSERT_EQ(r.code, 0) << r.output;
    const CPLJSONObject stats = report(dir + "/vehicle.json").GetObj("stats");
    EXPECT_GE(stats.GetInteger("repeatedItems"), 1);
    EXPECT_EQ(stats.GetInteger("resentRequests"), 0);
    EXPECT_GE(r.seconds, 1.5); // one reply timeout
}

TEST(PeerUpload, ARefusalIsReportedWithItsReason) {
    Peer vehicle({"--udp", "0", "--seconds", "60", "--nack", "7:4"});
    ASSERT_GT(vehicle.port(), 0);
    const CliRun r = cli("upload " + quoted(kDemo) + " --aircraft 'Falcon 8' --to udp:127.0.0.1:" +
                      std::to_string(vehicle.port()));
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_NE(r.output.find("refused the mission at item 7"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("no space"), std::string::npos) << r.output;
}

TEST(PeerUpload, NoVehicleIsAClearTimeout) {
    Peer silent({"--udp", "0", "--seconds", "30", "--silent"});
    ASSERT_GT(silent.port(), 0);
    const CliRun r = cli("upload " + quoted(kDemo) + " --aircraft 'Falcon 8' --timeout 2 --to udp:127.0.0.1:" +
                      std::to_string(silent.port()));
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_NE(r.output.find("no heartbeat from any vehicle on UDP 127.0.0.1:" + std::to_string(silent.port()) +
                            " within 2.0 s"),
              std::string::npos)
        << r.output;
    EXPECT_LT(r.seconds, 15.0);
    // A connection that cannot be opened is named.
    const CliRun tcp = cli("upload " + quoted(kDemo) + " --aircraft 'Falcon 8' --to tcp:127.0.0.1:1");
    EXPECT_EQ(tcp.code, 2) << tcp.output;
    EXPECT_NE(tcp.output.find("TCP 127.0.0.1:1"), std::string::npos) << tcp.output;
}

TEST(PeerUpload, TwoVehiclesOnOneLinkAreUploadedInParallelBySystemId) {
    const std::string dir = scratch("two");
    const int port = freeUdpPort();
    const std::string gcs = "127.0.0.1:" + std::to_string(port);
    // Both vehicles stream to the ground station's port, as autopilots do to 14550; each answers
    // only what is addressed to its system id, slowly (4 ms per message).
    Peer a({"--udp-out", gcs, "--sysid", "1", "--seconds", "90", "--delay", "4", "--report", dir + "/a.json"});
    Peer b({"--udp-out", gcs, "--sysid", "2", "--seconds", "90", "--delay", "4", "--report", dir + "/b.json",
            "--autopilot", "px4"});
    ASSERT_GT(a.port(), 0);
    ASSERT_GT(b.port(), 0);
    const CliRun r = cli("upload " + quoted(kDemo) + " --to udp::" + std::to_string(port) +
                      " --aircraft 'Falcon 8' --system-id 1 --aircraft 'Phantom 4 Pro' --system-id 2");
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_NE(r.output.find("Falcon 8: found quadrotor, ArduPilot, system id 1"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("Phantom 4 Pro: found quadrotor, PX4, system id 2"), std::string::npos) << r.output;
    const CPLJSONObject ra = report(dir + "/a.json"), rb = report(dir + "/b.json");
    const int na = ra.GetArray("mission").Size();
    const int nb = rb.GetArray("mission").Size();
    EXPECT_GT(na, 50);
    EXPECT_GT(nb, 50);
    EXPECT_NE(na, nb); // each vehicle got its own aircraft's route
    // In parallel: each vehicle was served while the other one was (their transfers overlap for
    // most of the shorter one), not one after the other.
    const double a0 = ra.GetObj("stats").GetDouble("firstCountAt"), a1 = ra.GetObj("stats").GetDouble("lastRequestAt");
    const double b0 = rb.GetObj("stats").GetDouble("firstCountAt"), b1 = rb.GetObj("stats").GetDouble("lastRequestAt");
    ASSERT_GT(a1, a0);
    ASSERT_GT(b1, b0);
    const double overlap = std::min(a1, b1) - std::max(a0, b0);
    EXPECT_GT(overlap, 0.5 * std::min(a1 - a0, b1 - b0))
        << "vehicle 1 " << a0 << ".." << a1 << ", vehicle 2 " << b0 << ".." << b1;
}

TEST(PeerUpload, TwoVehiclesOnTwoConnections) {
    const std::string dir = scratch("twoports");
    Peer a({"--udp", "0", "--seconds", "60", "--report", dir + "/a.json"});
    Peer b({"--tcp", "0", "--seconds", "60", "--report", dir + "/b.json", "--old-requests"});
    ASSERT_GT(a.port(), 0);
    ASSERT_GT(b.port(), 0);
    const CliRun r = cli("upload " + quoted(kDemo) + " --aircraft 'Falcon 8' --to udp:127.0.0.1:" +
                      std::to_string(a.port()) + " --aircraft 'Phantom 4 Pro' --to tcp:127.0.0.1:" +
                      std::to_string(b.port()) + " --trigger distance");
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_GT(report(dir + "/a.json").GetArray("mission").Size(), 10);
    EXPECT_GT(report(dir + "/b.json").GetArray("mission").Size(), 10);
}

// A mission is one battery's flight: without --sortie an aircraft needing several batteries is
// refused before anything is sent, with a message naming it, its sortie count and how to choose;
// --sortie N sends exactly battery N's flight, the items of that sortie's .waypoints file.
TEST(PeerUpload, OneBatterysFlightAtATime) {
    const std::string dir = scratch("sortie");
    // The demo with a Falcon 8 that flies 4 minutes: two batteries.
    std::ifstream in(kDemo);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    const auto at = text.find("\"endurance_min\": 20.0");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, 21, "\"endurance_min\": 4.0");
    const std::string mission = dir + "/short.json";
    std::ofstream(mission) << text;
    Peer vehicle({"--udp", "0", "--seconds", "60", "--report", dir + "/vehicle.json"});
    ASSERT_GT(vehicle.port(), 0);
    const std::string to = " --aircraft 'Falcon 8' --to udp:127.0.0.1:" + std::to_string(vehicle.port());
    const CliRun all = cli("upload " + quoted(mission) + to);
    EXPECT_EQ(all.code, 2) << all.output;
    EXPECT_NE(all.output.find("Falcon 8 needs 2 batteries (sorties 1 to 2)"), std::string::npos)
        << all.output;
    EXPECT_NE(all.output.find("nothing was sent"), std::string::npos) << all.output;
    EXPECT_NE(all.output.find("--sortie N"), std::string::npos) << all.output;
    {
        // The vehicle heard nothing of a mission: no upload began, it holds none.
        const CPLJSONObject held = report(dir + "/vehicle.json");
        EXPECT_EQ(held.GetArray("mission").Size(), 0);
        EXPECT_EQ(held.GetObj("stats").GetDouble("firstCountAt"), 0.0);
    }

    const CliRun plan = cli("plan " + quoted(mission) + " --format waypoints --out " + dir);
    ASSERT_EQ(plan.code, 0) << plan.output;
    for (int sortie : {2, 1}) {
        const CliRun one =
            cli("upload " + quoted(mission) + to + " --sortie " + std::to_string(sortie));
        ASSERT_EQ(one.code, 0) << one.output;
        EXPECT_NE(one.output.find("Falcon 8, sortie " + std::to_string(sortie) +
                                  " of 2: uploaded and read back identical"),
                  std::string::npos)
            << one.output;
        // The vehicle holds that sortie's file, item for item after the home (take-off to return).
        std::ifstream file(dir + "/mission-Falcon_8-sortie" + std::to_string(sortie) +
                           ".waypoints");
        std::string line;
        std::getline(file, line);
        ASSERT_EQ(line, "QGC WPL 110");
        std::getline(file, line); // the home: the vehicle keeps its own
        const CPLJSONArray items = report(dir + "/vehicle.json").GetArray("mission");
        int k = 1;
        while (std::getline(file, line)) {
            std::istringstream f(line);
            double v[12];
            for (double& x : v)
                f >> x;
            ASSERT_LT(k, items.Size());
            const CPLJSONObject it = items[k];
            EXPECT_EQ(it.GetInteger("command"), int(v[3])) << "sortie " << sortie << " item " << k;
            if (int(v[3]) == 16) {
                EXPECT_NEAR(it.GetDouble("x") / 1e7, v[8], 1.5e-7)
                    << "sortie " << sortie << " item " << k;
                EXPECT_NEAR(it.GetDouble("y") / 1e7, v[9], 1.5e-7)
                    << "sortie " << sortie << " item " << k;
            }
            ++k;
        }
        EXPECT_EQ(k, items.Size()) << "sortie " << sortie;
        EXPECT_GT(k, 10);
        EXPECT_EQ(items[1].GetInteger("command"), 22);                // one take-off
        EXPECT_EQ(items[items.Size() - 1].GetInteger("command"), 20); // one return
    }
    const CliRun tooMany = cli("upload " + quoted(mission) + to + " --sortie 99");
    EXPECT_EQ(tooMany.code, 2);
    EXPECT_NE(tooMany.output.find("--sortie 99: Falcon 8 flies 2 sortie(s)"), std::string::npos)
        << tooMany.output;
}

// A fixed-wing's mission over MAVLink to a vehicle whose heartbeat says fixed wing: the take-off
// with its pitch, the camera by distance, DO_LAND_START and NAV_LAND towards the heading given, read
// back identical.
TEST(PeerUpload, APlanesMissionWithItsLanding) {
    const std::string dir = scratch("plane");
    CPLJSONDocument doc;
    ASSERT_TRUE(doc.Load(kDemo));
    CPLJSONObject root = doc.GetRoot();
    root.Set("version", 5);
    CPLJSONObject wing = root.GetArray("aircraft")[0];
    wing.Set("name", "Wing");
    wing.Add("kind", "fixed_wing");
    wing.Set("altitude_m", 80.0);
    wing.Set("cruise_speed_mps", 13.0);
    wing.Set("endurance_min", 90.0);
    CPLJSONObject plane;
    plane.Add("bank_deg", 45.0);
    plane.Add("climb_rate_mps", 5.0);
    plane.Add("sink_rate_mps", 5.0);
    plane.Add("run_in_m", 50.0);
    wing.Add("plane", plane);
    CPLJSONArray fleet;
    fleet.Add(wing);
    root.Delete("aircraft");
    root.Add("aircraft", fleet);
    const std::string mission = dir + "/wing.json";
    ASSERT_TRUE(doc.Save(mission));

    Peer vehicle({"--udp", "0", "--seconds", "60", "--report", dir + "/vehicle.json", "--vehicle-type", "1"});
    ASSERT_GT(vehicle.port(), 0) << "the simulated vehicle did not start";
    const CliRun r = cli("upload " + quoted(mission) + " --to udp:127.0.0.1:" + std::to_string(vehicle.port()) +
                         " --landing-heading 270");
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_NE(r.output.find("found fixed wing, ArduPilot"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("uploaded and read back identical"), std::string::npos) << r.output;
    const CPLJSONArray items = report(dir + "/vehicle.json").GetArray("mission");
    ASSERT_GT(items.Size(), 5);
    std::vector<int> commands;
    for (int k = 0; k < items.Size(); ++k)
        commands.push_back(items[k].GetInteger("command"));
    EXPECT_EQ(commands[1], 22); // NAV_TAKEOFF after ArduPilot's home item
    EXPECT_NEAR(items[1].GetArray("params")[0].ToDouble(), 15.0, 1e-6); // its pitch
    EXPECT_GE(std::count(commands.begin(), commands.end(), 206), 2);   // DO_SET_CAM_TRIGG_DIST
    // A photo outside a lane of evenly spaced photos (one moved out of a margin) keeps a capture of
    // its own, right after its waypoint, flown through.
    for (std::size_t k = 1; k < commands.size(); ++k) {
        if (commands[k] == 2000) {
            EXPECT_EQ(commands[k - 1], 16) << "item " << k;
        }
    }
    ASSERT_GE(commands.size(), 3u);
    EXPECT_EQ(commands[commands.size() - 3], 189); // DO_LAND_START
    EXPECT_EQ(commands.back(), 21);                // NAV_LAND
    EXPECT_NEAR(items[items.Size() - 1].GetArray("params")[3].ToDouble(), 270.0, 1e-3);
}
