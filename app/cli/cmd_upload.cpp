// photoflight-cli upload: sends a planned mission (or a waypoint file) to vehicles over MAVLink and
// reads it back; exit 0 only when every vehicle holds exactly what was sent.
#include "app/cli/args.h"
#include "app/cli/commands.h"
#include "app/cli/export_args.h"

#include "core/io/mission_export.h"
#include "core/io/mission_file.h"
#include "core/io/waypoint_formats.h"
#include "core/mavlink/connection_spec.h"
#include "core/mission/plan_mission.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iostream>
#include <optional>

#ifdef PF_CLI_HAS_VEHICLE
#include "ui/vehicle/upload_manager.h"
#include "ui/vehicle/vehicle_upload.h"

#include <QCoreApplication>
#include <QTimer>
#endif

namespace pf::cli {

const char* const kUploadUsage =
    "Usage: photoflight-cli upload PLAN_OR_MISSION --to CONNECTION [--aircraft NAME] [options]\n"
    "\n"
    "Uploads to each vehicle over MAVLink 2 the mission of its aircraft, the same items as the .plan and\n"
    ".waypoints exports (take-off, speed, gimbal, waypoints with camera commands, return or land), the\n"
    "no-fly zones as an exclusion geofence and the rally point, then downloads all three again and\n"
    "compares them item by item. Several vehicles are uploaded in parallel. A mission is one battery's\n"
    "flight: an aircraft whose plan needs several batteries gets the sortie chosen with --sortie N, and a\n"
    "flight of more mission items than an autopilot stores (PX4 500, ArduPilot 650) gets a warning.\n"
    "\n"
    "PLAN_OR_MISSION is a Photoflight mission file (planned now; hand-edited routes in it are flown as\n"
    "edited) or a waypoint file: .plan, .waypoints, .gpx, .geojson or .csv.\n"
    "\n"
    "Connections:\n"
    "  udp:HOST:PORT         send to the vehicle at HOST:PORT (it answers to our port)\n"
    "  udp::PORT, udpin:PORT listen on PORT for a vehicle that sends first (autopilots and SITL: 14550)\n"
    "  tcp:HOST:PORT         TCP (SITL: tcp:127.0.0.1:5760)\n"
    "  serial:DEVICE:BAUD    serial port or telemetry radio, e.g. serial:/dev/ttyUSB0:57600\n"
    "\n"
    "Options:\n"
    "  --to CONNECTION       where the vehicle is (repeatable: one per --aircraft)\n"
    "  --aircraft NAME       the aircraft whose route goes to the vehicle (repeatable; default: every\n"
    "                        route of the input; needed to pick one from several)\n"
    "  --system-id N         the vehicle's MAVLink system id, 1-255 (repeatable, one per --aircraft;\n"
    "                        default 0: the first autopilot heard, only for one aircraft per connection)\n"
    "  --timeout S           how long to wait for the vehicle's heartbeat (default 5 s)\n"
    "  --sortie N            battery N's flight (home to home) of each aircraft: needed when an aircraft\n"
    "                        needs several batteries, as a mission is one battery's flight (without it\n"
    "                        such an upload exits 2 and sends nothing)\n"
    PF_CLI_EXPORT_OPTIONS_HELP
    "\n"
    "Several vehicles: --aircraft \"Falcon 8\" --to udp::14550 --aircraft \"DJI Phantom 4 Pro\" --to udp::14551,\n"
    "or on one link by system id: --to udp::14550 --aircraft A --system-id 1 --aircraft B --system-id 2.\n"
    "\n"
    "Exit codes: 0 every vehicle holds the mission as sent; 2 bad input or a vehicle that could not be\n"
    "reached, refused the mission or read back something else (the reason on stderr); 1 internal error.\n";

#ifndef PF_CLI_HAS_VEHICLE
int runUpload(const std::vector<std::string>&) {
    return reportError("upload: this photoflight-cli was built without Qt, so it cannot talk to vehicles");
}
#else

namespace {

struct Input {
    io::ExportContext ctx;
    std::vector<std::string> notes;
};

// A .json file is a mission when it says so; otherwise it is read as GeoJSON waypoints.
bool isMissionFile(const std::string& path) {
    std::string ext = path.size() >= 5 ? path.substr(path.size() - 5) : std::string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext != ".json")
        return false;
    std::ifstream in(path, std::ios::binary);
    std::string head(4096, '\0');
    in.read(&head[0], static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    return head.find("photoflight-mission") != std::string::npos;
}

std::optional<int> parseSystemId(const std::string& s) {
    if (s.empty() || s.size() > 3 || !std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); }))
        return std::nullopt;
    const int n = std::stoi(s);
    if (n < 1 || n > 255)
        return std::nullopt;
    return n;
}

// The routes of a mission file (planned now; a hand-edited route in it replaces its aircraft's) or
// of a waypoint file, one per aircraft, each with every sortie it flies.
Result<Input> loadInput(const std::string& path) {
    Input in;
    if (!isMissionFile(path)) {
        auto imported = io::importWaypoints(path);
        if (!imported)
            return imported.error();
        in.ctx = io::contextFromImport(*imported);
        return in;
    }
    auto m = io::readMissionFile(path);
    if (!m)
        return m.error();
    auto plan = mission::planMission(*m);
    if (!plan)
        return plan.error();
    std::vector<route::Route> routes;
    for (const auto& a : plan->aircraft) {
        route::Route r = a.route;
        for (const auto& e : m->editedRoutes)
            if (e.aircraft == r.aircraft) {
                r = e;
                in.notes.push_back(r.aircraft +
                                   ": its hand-edited route from the mission file is sent");
            }
        routes.push_back(std::move(r));
    }
    in.ctx = io::makeExportContext(*m, routes);
    return in;
}

// One battery's flight per chosen aircraft: an upload never sends a mission asking one battery for
// several sorties. `sortie` is 1-based, 0 when not given: then an aircraft needing several
// batteries is an error that says how to choose. Each flight is route 0 of its context.
Result<std::vector<io::ExportContext>>
flightsToSend(const io::ExportContext& ctx, const std::vector<std::size_t>& chosen, int sortie) {
    std::vector<io::ExportContext> flights;
    std::string unchosen;
    for (std::size_t i : chosen) {
        const std::size_t n = io::sortieCount(ctx, i);
        if (n > 1 && sortie == 0) {
            unchosen += (unchosen.empty() ? "" : "; ") + ctx.routeLabel(i) + " needs " +
                        std::to_string(n) + " batteries (sorties 1 to " + std::to_string(n) + ")";
            continue;
        }
        if (sortie > 0 && static_cast<std::size_t>(sortie) > n)
            return makeError(ErrorCode::InvalidInput, "--sortie " + std::to_string(sortie) + ": " +
                                                          ctx.routeLabel(i) + " flies " +
                                                          std::to_string(n) + " sortie(s)");
        flights.push_back(
            io::sortieFlight(ctx, i, sortie > 0 ? static_cast<std::size_t>(sortie - 1) : 0));
    }
    if (!unchosen.empty())
        return makeError(
            ErrorCode::InvalidInput,
            "upload: " + unchosen +
                ": a mission is one battery's flight, so nothing was sent. Choose the battery "
                "with --sortie N (--sortie 1 first; upload the next one when it has landed)");
    return flights;
}

} // namespace

int runUpload(const std::vector<std::string>& argv) {
    auto specs = exportOptionSpecs();
    specs.push_back({"to", true, true});
    specs.push_back({"aircraft", true, true});
    specs.push_back({"system-id", true, true});
    specs.push_back({"timeout"});
    specs.push_back({"sortie"});
    auto args = Args::parse(argv, specs);
    if (!args)
        return reportError(args.error());
    if (args->positionals().size() != 1)
        return reportError("upload needs one mission or waypoint file (see photoflight-cli upload --help)");
    const auto tos = args->values("to");
    if (tos.empty())
        return reportError("upload: --to CONNECTION is missing (e.g. --to udp::14550)");
    auto options = exportOptionsFromArgs(*args);
    if (!options)
        return reportError(options.error());
    auto timeout = args->number("timeout");
    if (!timeout)
        return reportError(timeout.error());
    if (*timeout && !(**timeout > 0 && **timeout <= 600))
        return reportError("--timeout: expected seconds between 0 and 600");

    std::vector<mavlink::ConnectionSpec> connections;
    for (const auto& t : tos) {
        auto c = mavlink::parseConnectionSpec(t);
        if (!c)
            return reportError("--to: " + c.error().message);
        connections.push_back(*c);
    }
    std::vector<int> sysids;
    for (const auto& s : args->values("system-id")) {
        auto n = parseSystemId(s);
        if (!n)
            return reportError("--system-id: expected a MAVLink system id from 1 to 255 but got '" + s + "'");
        sysids.push_back(*n);
    }

    auto sortie = args->number("sortie");
    if (!sortie)
        return reportError(sortie.error());
    if (*sortie && !(**sortie >= 1 && **sortie <= 1000 && **sortie == static_cast<int>(**sortie)))
        return reportError("--sortie: expected a sortie number from 1");
    const std::string& path = args->positionals()[0];
    auto input = loadInput(path);
    if (!input)
        return reportError(input.error());
    for (const auto& n : input->notes)
        std::cerr << "photoflight-cli: note: " << n << '\n';
    const io::ExportContext& ctx = input->ctx;

    std::vector<std::size_t> chosen;
    const auto names = args->values("aircraft");
    std::string known;
    for (std::size_t i = 0; i < ctx.routes.size(); ++i)
        known += (known.empty() ? "" : ", ") + ctx.routeLabel(i);
    for (const auto& name : names) {
        std::size_t found = ctx.routes.size();
        for (std::size_t i = 0; i < ctx.routes.size(); ++i)
            if (ctx.routes[i].aircraft == name || ctx.routeLabel(i) == name)
                found = i;
        if (found == ctx.routes.size())
            return reportError(path + ": no route of aircraft '" + name + "' (it has: " + known + ")");
        chosen.push_back(found);
    }
    if (names.empty())
        for (std::size_t i = 0; i < ctx.routes.size(); ++i)
            chosen.push_back(i);
    if (chosen.empty())
        return reportError(path + ": there is no route to upload");
    if (connections.size() != 1 && connections.size() != chosen.size())
        return reportError("upload: " + std::to_string(connections.size()) + " --to for " +
                           std::to_string(chosen.size()) + " aircraft (" + known +
                           "): give one --to, or one per --aircraft");
    if (!sysids.empty() && sysids.size() != chosen.size())
        return reportError("upload: " + std::to_string(sysids.size()) + " --system-id for " +
                           std::to_string(chosen.size()) + " aircraft: give one per aircraft");

    auto flights = flightsToSend(ctx, chosen, *sortie ? static_cast<int>(**sortie) : 0);
    if (!flights)
        return reportError(flights.error());
    // Before the vehicle answers its firmware is unknown: the smaller of the autopilots' limits.
    for (const auto& f : *flights)
        if (auto w = io::flightItemWarning(f, 0, *options, std::nullopt); !w.empty())
            std::cerr << "photoflight-cli: warning: " << w << '\n';

    std::vector<ui::UploadJob> jobs;
    for (std::size_t k = 0; k < flights->size(); ++k) {
        auto job = ui::makeUploadJob((*flights)[k], 0,
                                     connections.size() == 1 ? connections[0] : connections[k],
                                     sysids.empty() ? 0 : sysids[k], *options);
        if (!job)
            return reportError(job.error());
        if (*timeout)
            job->options.heartbeatTimeoutMs = static_cast<std::int64_t>(**timeout * 1000);
        jobs.push_back(std::move(*job));
    }
    if (auto st = ui::checkBindings(jobs); !st)
        return reportError("upload: " + st.error().message);

    int argc = 1;
    char name[] = "photoflight-cli";
    char* qargv[] = {name, nullptr};
    QCoreApplication app(argc, qargv);
    ui::UploadManager manager;
    int failed = 0;
    std::vector<std::string> lastPhase(jobs.size());
    auto label = [&](int i) { return manager.upload(std::size_t(i))->aircraft().toStdString(); };
    QObject::connect(&manager, &ui::UploadManager::jobVehicle, [&](int i, const QString& d) {
        std::cout << label(i) << ": found " << d.toStdString() << std::endl;
    });
    QObject::connect(&manager, &ui::UploadManager::jobProgress, [&](int i) {
        const auto* u = manager.upload(std::size_t(i));
        const std::string phase = u->phaseText().toStdString();
        if (phase != lastPhase[std::size_t(i)] && !u->isFinished()) {
            lastPhase[std::size_t(i)] = phase;
            std::cout << label(i) << ": " << phase << std::endl;
        }
    });
    QObject::connect(&manager, &ui::UploadManager::jobFinished, [&](int i, bool ok) {
        const auto* u = manager.upload(std::size_t(i));
        const std::string text = u->resultText().toStdString();
        if (ok) {
            std::cout << label(i) << ": " << text << std::endl;
        } else {
            ++failed;
            std::cerr << "photoflight-cli: error: " << label(i) << " (" << jobs.size() << " vehicle"
                      << (jobs.size() == 1 ? "" : "s") << "): " << text << std::endl;
        }
    });
    QObject::connect(&manager, &ui::UploadManager::allFinished, &app, &QCoreApplication::quit);
    QString error;
    std::vector<std::string> described;
    for (const auto& j : jobs)
        described.push_back(j.aircraft.toStdString() + " -> " + j.connection.describe());
    for (const auto& d : described)
        std::cout << d << std::endl;
    if (!manager.start(std::move(jobs), &error))
        return reportError("upload: " + error.toStdString());
    app.exec();
    return failed == 0 ? kExitOk : kExitBadInput;
}
#endif

} // namespace pf::cli
