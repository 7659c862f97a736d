// How aircraft of a mission are named and coloured: the one palette and the one numbering rule that
// the CLI (--aircraft), the GUI (Add aircraft) and the exporters' fallback colours share, and the
// one way messages name an aircraft.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace pf::mission {

// The map colour of the aircraft at `index` (0-based) of a mission, "#rrggbb": eight colours that
// stay apart on the map, repeating from the ninth aircraft on.
std::string aircraftColour(std::size_t index);

// "Falcon 8 #2": `model` with the smallest number from 1 that no name in `taken` already uses, so
// that aircraft of one model stay apart in tables, files and messages.
std::string numberedAircraftName(const std::string& model, const std::vector<std::string>& taken);

// An aircraft as messages name it, in front of what they say about it: its name as the user gave it
// ("Falcon 8: the flight needs 5 batteries …", as the route check's "Falcon 8, waypoint 12: …"), or
// `unnamed` ("the aircraft", "aircraft 2") when it has none.
std::string aircraftLabel(const std::string& name, const std::string& unnamed = "the aircraft");

} // namespace pf::mission
