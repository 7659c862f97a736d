// The aircraft palette and numbering rule.
#include "core/mission/aircraft_naming.h"

#include <algorithm>

namespace pf::mission {

namespace {

// Distinct, colour-blind-friendly path colours for successive aircraft.
const char* const kPalette[] = {"#e6194b", "#3cb44b", "#4363d8", "#f58231",
                                "#911eb4", "#42d4f4", "#f032e6", "#9a6324"};

} // namespace

std::string aircraftColour(std::size_t index) {
    return kPalette[index % (sizeof kPalette / sizeof *kPalette)];
}

std::string numberedAircraftName(const std::string& model, const std::vector<std::string>& taken) {
    for (int n = 1;; ++n) {
        const std::string candidate = model + " #" + std::to_string(n);
        if (std::find(taken.begin(), taken.end(), candidate) == taken.end())
            return candidate;
    }
}

std::string aircraftLabel(const std::string& name, const std::string& unnamed) {
    return name.empty() ? unnamed : name;
}

} // namespace pf::mission
