// How many mission items an autopilot stores, and the check of one flight against it (the waypoint
// files written for MAVLink autopilots and the uploads to them).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace pf::io {

enum class Autopilot { ArduPilot, PX4 };

struct MissionItemLimit {
    std::size_t items =
        0;             // the most items one mission may hold, counted as the autopilot counts them
    std::string where; // "ArduPilot 650 (...)": the figure and what holds more, for messages
};

// The documented figures (see mission_limits.cpp for the sources).
const MissionItemLimit& missionItemLimit(Autopilot autopilot);

// The items the autopilot stores for a mission of `missionItems` items (take-off to the return, as
// missionItems() makes them): ArduPilot keeps its home as item 0 in the same storage.
std::size_t storedItems(std::size_t missionItems, Autopilot autopilot);

// Whether a mission of `missionItems` items fits the autopilot; with none given (an upload before
// the vehicle answers) it must fit both.
bool fitsAutopilot(std::size_t missionItems, std::optional<Autopilot> autopilot);

// What to say when the flight `flight` ("Falcon 8, sortie 2") of `missionItems` items does not
// fit: names the flight, the count and the limit, and with `itemsByDistance` (the same flight with
// the camera triggered by distance along lanes) how many that would take. Empty when it fits. With
// no autopilot given (an upload before the vehicle answers) the smallest figure counts.
std::string itemLimitWarning(const std::string& flight, std::size_t missionItems,
                             std::optional<Autopilot> autopilot,
                             std::optional<std::size_t> itemsByDistance = std::nullopt);
// The same for several flights of one aircraft that do not fit, said once: `flights` names them
// ("Falcon 8, sorties 1 to 5 (...)"), `missionItems` gives their counts in order and
// `itemsByDistance` (empty or as many) their counts with the camera triggered by distance.
std::string itemLimitWarning(const std::string& flights,
                             const std::vector<std::size_t>& missionItems,
                             std::optional<Autopilot> autopilot,
                             const std::vector<std::size_t>& itemsByDistance);

} // namespace pf::io
