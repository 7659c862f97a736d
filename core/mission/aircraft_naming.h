// How new aircraft of a mission are named and coloured: the one palette and the one numbering rule
// that the CLI (--aircraft), the GUI (Add aircraft) and the exporters' fallback colours share.
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

} // namespace pf::mission
