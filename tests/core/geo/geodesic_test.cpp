#include "core/geo/geodesic.h"

#include <gtest/gtest.h>

using namespace pf::geo;

TEST(Geodesic, OneDegreeOfLatitudeAtTheEquator) {
    // 110 574.389 m: the WGS84 meridian arc from 0 to 1 degree (standard tables).
    EXPECT_NEAR(geodesicDistance({0, 0}, {0, 1}), 110574.389, 0.01);
}

TEST(Geodesic, BearingsOfCardinalDirections) {
    const LonLat o{8.4, 49.0};
    EXPECT_NEAR(initialBearingDeg(o, {8.4, 49.1}), 0.0, 1e-9);
    EXPECT_NEAR(initialBearingDeg(o, {8.4, 48.9}), 180.0, 1e-9);
    EXPECT_NEAR(initialBearingDeg(o, {8.5, 49.0}), 90.0, 0.1);
    EXPECT_NEAR(initialBearingDeg(o, {8.3, 49.0}), 270.0, 0.1);
}

TEST(Geodesic, DirectInvertsInverse) {
    const LonLat o{8.4, 49.0};
    const LonLat p = geodesicDirect(o, 37.0, 1234.5);
    const auto inv = geodesicInverse(o, p);
    EXPECT_NEAR(inv.distanceM, 1234.5, 1e-6);
    EXPECT_NEAR(inv.azimuth1Deg, 37.0, 1e-9);
}
