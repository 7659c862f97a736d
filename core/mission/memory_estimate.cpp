#include "core/mission/memory_estimate.h"

#include "core/geo/polygon_ops.h"
#include "core/grid/grid.h"
#include "core/mission/corridor.h"
#include "core/mission/validation.h"
#include "core/sensor/camera.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace pf::mission {

namespace {

constexpr double kBaseBytes = 80e6;
constexpr double kBytesPerCell = 64.0;
constexpr double kBytesPerPhoto = 320.0;
// addressSpaceBytes: mapped per resident byte, and the libraries, stacks and arenas of the process.
constexpr double kMappedPerResident = 1.5;
constexpr double kMappedFixed = 200e6;
// Of an address-space limit, what the plan may map (the rest for the estimate's error).
constexpr double kLimitShare = 0.95;

std::string gigabytes(double bytes) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f GB", bytes / 1e9);
    return buf;
}

} // namespace

MemoryEstimate estimatePlanMemory(const Mission& m) {
    MemoryEstimate e;
    auto geom = localGeometry(m);
    if (!geom)
        return e;
    const geo::MultiPolygon area{geom->area};
    const double areaM2 = std::abs(geo::signedArea(geom->area.outer));
    for (const auto& a : m.aircraft) {
        auto alt = resolvedAltitude(a);
        if (!alt)
            continue;
        auto eff = sensor::effectiveFootprint(a.camera, *alt, a.overlap);
        if (!eff || !(eff->acrossM > 0) || !(eff->alongM > 0))
            continue;
        if (!plansCorridorLanes(m)) // corridor lanes need no grid
            e.cells += grid::Grid::sizeFor(area, sensor::cellSizeFor(*eff),
                                           m.options.gridAngleDeg.value_or(0.0))
                           .cells();
        // Several aircraft share the area: each photographs a part, the sum is the whole (at most).
        e.photos = std::max(e.photos, areaM2 / (eff->acrossM * eff->alongM));
    }
    e.bytes = kBaseBytes + kBytesPerCell * e.cells + kBytesPerPhoto * e.photos;
    return e;
}

double addressSpaceBytes(double residentBytes) { return kMappedFixed + kMappedPerResident * residentBytes; }

namespace {

// The resident budget an address-space limit leaves (the inverse of addressSpaceBytes), if there is one.
std::optional<double> limitBudget() {
    rlimit lim{};
    if (::getrlimit(RLIMIT_AS, &lim) != 0 || lim.rlim_cur == RLIM_INFINITY)
        return std::nullopt;
    const double mappable = kLimitShare * static_cast<double>(lim.rlim_cur) - kMappedFixed;
    return std::max(mappable, 0.0) / kMappedPerResident;
}

} // namespace

std::size_t memoryBudgetBytes() {
    const double pages = static_cast<double>(::sysconf(_SC_PHYS_PAGES));
    const double pageSize = static_cast<double>(::sysconf(_SC_PAGE_SIZE));
    double budget = pages > 0 && pageSize > 0 ? 0.75 * pages * pageSize : static_cast<double>(1u << 30);
    if (const auto lim = limitBudget())
        budget = std::min(budget, *lim);
    return static_cast<std::size_t>(std::max(budget, 1.0));
}

Status checkPlanMemory(const Mission& m, std::size_t budgetBytes, int plans) {
    const MemoryEstimate e = estimatePlanMemory(m);
    const double perPlan = e.bytes - kBaseBytes;
    const double need = kBaseBytes + std::max(1, plans) * perPlan;
    const double budget = static_cast<double>(budgetBytes);
    if (need <= budget)
        return {};
    // Cells and photos both shrink with the square of the altitude (and of the cell size).
    const double room = std::max(budget - kBaseBytes, 1e6) / std::max(1, plans);
    const double scale = std::sqrt(perPlan / room) * 1.05;
    std::string fits;
    if (!m.aircraft.empty()) {
        const auto& a = m.aircraft.front();
        auto alt = resolvedAltitude(a);
        auto eff = alt ? sensor::effectiveFootprint(a.camera, *alt, a.overlap) : Result<sensor::EffectiveFootprint>(alt.error());
        if (alt && eff) {
            char buf[200];
            std::snprintf(buf, sizeof buf, "; an altitude of %.0f m or more (now %.1f m), or a cell of %.1f m or more (now %.1f m), fits",
                          std::ceil(*alt * scale), *alt, std::ceil(sensor::cellSizeFor(*eff) * scale * 10.0) / 10.0,
                          sensor::cellSizeFor(*eff));
            fits = buf;
        }
    }
    char counts[160];
    std::snprintf(counts, sizeof counts, " (%.0f grid cells, about %.0f photos%s)", e.cells, e.photos,
                  plans > 1 ? ", plans compared two at a time" : "");
    // Under an address-space limit the figure that fails is the mapped one: say so.
    std::string limit;
    if (const auto lim = limitBudget(); lim && *lim <= budget + 1.0) {
        rlimit l{};
        ::getrlimit(RLIMIT_AS, &l);
        limit = " (ulimit -v allows " + gigabytes(static_cast<double>(l.rlim_cur)) +
                " of address space; the plan would map about " + gigabytes(addressSpaceBytes(need)) + ")";
    }
    return makeError(ErrorCode::TooLarge, "the plan would need about " + gigabytes(need) + " of memory" + counts +
                                              ", more than the " + gigabytes(budget) + " this machine can give it" +
                                              limit + fits + "; or split the area into parts");
}

} // namespace pf::mission
