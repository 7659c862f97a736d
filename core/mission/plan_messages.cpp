#include "core/mission/plan_messages.h"

#include "core/geo/polygon_ops.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace pf::mission {

namespace {

std::string fixed(double v, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

// Square metres as people write them: "1,012" from 10 m² on, "9.4" below.
std::string squareMetres(double m2) {
    if (m2 < 10.0)
        return fixed(m2, 1);
    const std::string digits = fixed(m2, 0);
    std::string out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0)
            out += ',';
        out += digits[i];
    }
    return out;
}

// "3.5 m", "50 m": an altitude with the precision it has.
std::string altitudeText(double m) {
    std::string s = fixed(m, 2);
    s.erase(s.find_last_not_of('0') + 1);
    if (s.back() == '.')
        s.pop_back();
    return s + " m";
}

double admissibleArea(const geo::MultiPolygon& part, const std::vector<geo::Polygon>& noFly) {
    if (noFly.empty())
        return geo::area(part);
    return geo::area(geo::difference(part, geo::MultiPolygon(noFly.begin(), noFly.end())));
}

double areaWithin(const geo::MultiPolygon& shape, const geo::MultiPolygon& part) {
    double a = 0.0;
    for (const auto& p : part)
        a += geo::area(geo::intersection(shape, p));
    return a;
}

} // namespace

std::string coveragePercentText(double coveredFraction, double uncoveredM2) {
    const double pct = 100.0 * coveredFraction;
    if (!(uncoveredM2 > 0.0))
        return fixed(pct, 1);
    for (int decimals = 1; decimals <= 3; ++decimals) {
        const std::string s = fixed(pct, decimals);
        if (std::stod(s) < 100.0)
            return s;
    }
    return "< 100";
}

std::string uncoveredMessage(const MissionPlan& plan) {
    if (!(plan.uncoveredAreaM2 > 0.0))
        return {};
    // The unseen share with the decimals it takes not to read 0.
    const double unseen = 100.0 * (1.0 - plan.coverageRatio);
    std::string share = "< 0.001";
    for (int decimals = 1; decimals <= 3; ++decimals)
        if (std::stod(fixed(unseen, decimals)) > 0.0) {
            share = fixed(unseen, decimals);
            break;
        }
    return squareMetres(plan.uncoveredAreaM2) + " m² of the area (" + share +
           " %) is seen by no photo, in " + std::to_string(plan.uncoveredPatchCount) + " patch(es)";
}

void attributeUncovered(MissionPlan& plan, const std::vector<geo::Polygon>& noFly) {
    for (auto& a : plan.aircraft) {
        a.admissibleAreaM2 = admissibleArea(a.subarea, noFly);
        a.uncoveredAreaM2 = 0.0;
        for (const auto& u : plan.uncovered)
            a.uncoveredAreaM2 += areaWithin(u.shape, a.subarea);
    }
}

double unattributedUncoveredM2(const MissionPlan& plan) {
    const double listed =
        std::accumulate(plan.uncovered.begin(), plan.uncovered.end(), 0.0,
                        [](double s, const UncoveredArea& u) { return s + u.areaM2; });
    return std::max(0.0, plan.uncoveredAreaM2 - listed);
}

std::optional<double> aircraftCoverage(const MissionPlan& plan, std::size_t k) {
    if (k >= plan.aircraft.size() || !(plan.coverageRatio > 0.0) ||
        !(plan.aircraft[k].admissibleAreaM2 > 0.0))
        return std::nullopt;
    const auto& a = plan.aircraft[k];
    return std::clamp(1.0 - a.uncoveredAreaM2 / a.admissibleAreaM2, 0.0, 1.0);
}

void addAltitudeMessages(MissionPlan& plan, const fleet::AltitudeCheck& check,
                         const std::vector<fleet::AltitudeSlot>& slots, double separationM,
                         const std::vector<std::optional<geo::Vec2>>& homes) {
    constexpr double kSameHomeM = 1.0;
    auto sameHome = [&](int a, int b) {
        const auto& ha = homes.at(std::size_t(a));
        const auto& hb = homes.at(std::size_t(b));
        return ha && hb && (*ha - *hb).norm() <= kSameHomeM;
    };
    for (const auto& c : check.conflicts) {
        if (!sameHome(c.a, c.b)) {
            plan.warnings.push_back(c.message);
            continue;
        }
        // From one home each flies over its own part of the area: they meet where they take off and
        // land, which the operator staggers anyway.
        const auto& sa = slots.at(std::size_t(c.a));
        const auto& sb = slots.at(std::size_t(c.b));
        const std::string how = c.separationM < 0.005
                                    ? " at the same altitude (" + altitudeText(sa.altitudeM) + ")"
                                    : " only " + altitudeText(c.separationM) +
                                          " apart in altitude (" + altitudeText(sa.altitudeM) +
                                          " and " + altitudeText(sb.altitudeM) + ")";
        plan.notes.push_back(
            sa.name + " and " + sb.name + " take off from the same home and fly at the same time" +
            how +
            ", each over its own part of the area: launch them one after the other, or keep " +
            altitudeText(separationM) + " between their altitudes.");
    }
    // The reasons a proposal does not fit follow the conflicts in the check's warnings.
    for (std::size_t i = check.conflicts.size(); i < check.warnings.size(); ++i)
        plan.warnings.push_back(check.warnings[i]);
}

} // namespace pf::mission
