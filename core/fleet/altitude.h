// Altitude separation between aircraft flying at the same time (paper 001, section V.B).
#pragma once

#include <limits>
#include <string>
#include <vector>

namespace pf::fleet {

struct AltitudeSlot {
    std::string name;
    double altitudeM = 0.0;
    double maxAltitudeM = 120.0; // ceiling for a proposed altitude (aircraft limit or regulation)
    // When the aircraft is in the air, in seconds from the common start; by default all at once.
    double startS = 0.0;
    double endS = std::numeric_limits<double>::infinity();
};

struct AltitudeConflict {
    int a = 0; // indices into the slots
    int b = 0;
    double separationM = 0.0; // current vertical separation
    std::string message;      // names both aircraft and their altitudes
};

struct AltitudeCheck {
    std::vector<AltitudeConflict> conflicts; // pairs in the air together closer than required
    // A proposal: each aircraft's altitude, raised as little as needed, lowest first, so that every
    // pair in the air together is at least the separation apart. Changing an altitude changes the
    // footprint, so the mission must be re-planned with it.
    std::vector<double> proposedM;
    bool proposalFits = true;           // false if some aircraft would exceed its ceiling
    std::vector<std::string> warnings;  // one per conflict, plus why a proposal does not fit
    bool ok() const { return conflicts.empty(); }
};

// Checks every pair of aircraft whose flight windows overlap against `minSeparationM` and proposes
// altitudes that satisfy it.
AltitudeCheck checkAltitudeSeparation(const std::vector<AltitudeSlot>& slots, double minSeparationM);

} // namespace pf::fleet
