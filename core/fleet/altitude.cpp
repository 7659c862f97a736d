#include "core/fleet/altitude.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace pf::fleet {

namespace {
// "3.5 m", "50 m", "3.25 m": with the precision the value has (up to centimetres), so that two
// aircraft at 3.5 m never read "4 m".
std::string metres(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    std::string s = buf;
    s.erase(s.find_last_not_of('0') + 1);
    if (s.back() == '.')
        s.pop_back();
    return s + " m";
}
bool together(const AltitudeSlot& a, const AltitudeSlot& b) { return a.startS < b.endS && b.startS < a.endS; }
} // namespace

AltitudeCheck checkAltitudeSeparation(const std::vector<AltitudeSlot>& slots, double sep) {
    AltitudeCheck out;
    const int n = static_cast<int>(slots.size());
    for (int a = 0; a < n; ++a)
        for (int b = a + 1; b < n; ++b) {
            const auto& sa = slots[static_cast<std::size_t>(a)];
            const auto& sb = slots[static_cast<std::size_t>(b)];
            const double d = std::abs(sa.altitudeM - sb.altitudeM);
            if (!together(sa, sb) || d >= sep - 1e-9)
                continue;
            AltitudeConflict c;
            c.a = a;
            c.b = b;
            c.separationM = d;
            const std::string advice =
                "; keep at least " + metres(sep) + " between them or fly them one after the other.";
            c.message = d < 0.005
                            ? sa.name + " and " + sb.name +
                                  " fly at the same time at the same altitude (" +
                                  metres(sa.altitudeM) + ")" + advice
                            : sa.name + " (" + metres(sa.altitudeM) + ") and " + sb.name + " (" +
                                  metres(sb.altitudeM) + ") fly at the same time only " +
                                  metres(d) + " apart" + advice;
            out.warnings.push_back(c.message);
            out.conflicts.push_back(std::move(c));
        }
    // Proposal: lowest first, each raised just above every aircraft already placed that shares its
    // time in the air (repeat until nothing moves, since raising may create a new conflict).
    std::vector<int> order(static_cast<std::size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int x, int y) {
        return slots[static_cast<std::size_t>(x)].altitudeM < slots[static_cast<std::size_t>(y)].altitudeM;
    });
    out.proposedM.assign(static_cast<std::size_t>(n), 0.0);
    std::vector<int> placed;
    for (int k : order) {
        const auto& sk = slots[static_cast<std::size_t>(k)];
        double alt = sk.altitudeM;
        for (bool moved = true; moved;) {
            moved = false;
            for (int j : placed)
                if (together(sk, slots[static_cast<std::size_t>(j)]) &&
                    std::abs(alt - out.proposedM[static_cast<std::size_t>(j)]) < sep - 1e-9) {
                    alt = out.proposedM[static_cast<std::size_t>(j)] + sep;
                    moved = true;
                }
        }
        out.proposedM[static_cast<std::size_t>(k)] = alt;
        placed.push_back(k);
        if (alt > sk.maxAltitudeM + 1e-9) {
            out.proposalFits = false;
            out.warnings.push_back("No altitude plan keeps " + metres(sep) +
                                   " between the aircraft in the air together: " + sk.name +
                                   " would need " + metres(alt) + ", above its ceiling of " +
                                   metres(sk.maxAltitudeM) +
                                   ". Fly some aircraft one after the other.");
        }
    }
    return out;
}

} // namespace pf::fleet
