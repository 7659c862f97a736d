#include "core/fleet/aircraft_grids.h"

namespace pf::fleet {

Result<std::vector<grid::Grid>> buildAircraftGrids(const std::vector<geo::MultiPolygon>& subareas,
                                                   const std::vector<geo::Polygon>& noFly,
                                                   const std::vector<grid::GridOptions>& options,
                                                   const std::vector<std::string>& names) {
    if (subareas.size() != options.size() || subareas.size() != names.size())
        return makeError(ErrorCode::Internal, "Per-aircraft grids: subareas, options and names differ in number.");
    std::vector<grid::Grid> grids;
    grids.reserve(subareas.size());
    for (std::size_t k = 0; k < subareas.size(); ++k) {
        // Named as every message names an aircraft (mission/aircraft_naming.h: aircraftLabel).
        const std::string who = names[k].empty() ? "aircraft " + std::to_string(k + 1) : names[k];
        if (subareas[k].empty())
            return makeError(ErrorCode::InvalidInput, who + " received no part of the area.");
        auto g = grid::Grid::build(subareas[k], noFly, options[k]);
        if (!g)
            return makeError(g.error().code, who + ": " + g.error().message);
        grids.push_back(std::move(g).value());
    }
    return grids;
}

} // namespace pf::fleet
