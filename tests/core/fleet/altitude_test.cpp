#include "core/fleet/altitude.h"

#include <gtest/gtest.h>

using namespace pf::fleet;

TEST(AltitudeSeparation, ConflictNamesThePairAndAltitudes) {
    const auto check = checkAltitudeSeparation({{"Falcon", 50, 120}, {"Phantom", 55, 120}}, 10);
    ASSERT_EQ(check.conflicts.size(), 1u);
    EXPECT_FALSE(check.ok());
    EXPECT_EQ(check.conflicts[0].a, 0);
    EXPECT_EQ(check.conflicts[0].b, 1);
    EXPECT_DOUBLE_EQ(check.conflicts[0].separationM, 5.0);
    EXPECT_EQ(check.conflicts[0].message, "Falcon (50 m) and Phantom (55 m) fly at the same time "
                                          "only 5 m apart; keep at least 10 m between them "
                                          "or fly them one after the other.");
    EXPECT_EQ(check.proposedM, (std::vector<double>{50, 60}));
    EXPECT_TRUE(check.proposalFits);
}

TEST(AltitudeSeparation, ProposalKeepsEveryPairApart) {
    const std::vector<AltitudeSlot> slots{{"A", 60, 120}, {"B", 55, 120}, {"C", 62, 120}, {"D", 100, 120}};
    const auto check = checkAltitudeSeparation(slots, 10);
    EXPECT_EQ(check.conflicts.size(), 3u); // A-B, A-C, B-C
    EXPECT_EQ(check.proposedM, (std::vector<double>{65, 55, 75, 100}));
    auto fixed = slots;
    for (std::size_t k = 0; k < slots.size(); ++k)
        fixed[k].altitudeM = check.proposedM[k];
    EXPECT_TRUE(checkAltitudeSeparation(fixed, 10).ok());
}

TEST(AltitudeSeparation, CeilingMakesTheProposalFail) {
    const auto check = checkAltitudeSeparation({{"Low", 50, 120}, {"Capped", 52, 58}}, 10);
    EXPECT_FALSE(check.proposalFits);
    ASSERT_EQ(check.warnings.size(), 2u);
    EXPECT_EQ(check.warnings[1], "No altitude plan keeps 10 m between the aircraft in the air "
                                 "together: Capped would need 60 m, above "
                                 "its ceiling of 58 m. Fly some aircraft one after the other.");
}

TEST(AltitudeSeparation, AircraftFlyingOneAfterTheOtherDoNotConflict) {
    AltitudeSlot a{"First", 50, 120, 0, 600}, b{"Second", 50, 120, 600, 1200};
    EXPECT_TRUE(checkAltitudeSeparation({a, b}, 10).ok());
    b.startS = 599;
    EXPECT_FALSE(checkAltitudeSeparation({a, b}, 10).ok());
}

// Altitudes keep the precision they have ("3.5 m", never "4 m"), and two aircraft at one altitude
// are said to be at the same altitude, not "only 0 m apart".
TEST(AltitudeSeparation, MessagesShowTheAltitudesAsGivenAndNameTheSameAltitude) {
    const auto same =
        checkAltitudeSeparation({{"Falcon 8", 3.5, 120}, {"Phantom 4 Pro", 3.5, 120}}, 10);
    ASSERT_EQ(same.conflicts.size(), 1u);
    EXPECT_EQ(same.conflicts[0].message, "Falcon 8 and Phantom 4 Pro fly at the same time at the "
                                         "same altitude (3.5 m); keep at least 10 m "
                                         "between them or fly them one after the other.");
    const auto close = checkAltitudeSeparation({{"A", 3.5, 120}, {"B", 4.25, 120}}, 10);
    ASSERT_EQ(close.conflicts.size(), 1u);
    EXPECT_EQ(close.conflicts[0].message,
              "A (3.5 m) and B (4.25 m) fly at the same time only 0.75 m apart; keep at "
              "least 10 m between them or fly them one after the other.");
}
