// Hillshade: the standard formula's values on planes facing the light, away from it and across it,
// flat ground, no-data and the ground-metre scale of a Web Mercator grid.
#include "core/terrain/hillshade.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace pf;
using terrain::HeightGrid;

namespace {

// A 9 x 9 grid of `spacing` whose heights rise by `east` and `north` metres per metre (of the
// grid).
HeightGrid plane(double east, double north, double spacing = 2.0) {
    std::vector<float> h;
    for (int r = 0; r < 9; ++r)
        for (int c = 0; c < 9; ++c)
            h.push_back(static_cast<float>(100.0 + east * c * spacing - north * r * spacing));
    return HeightGrid(0.0, 0.0, spacing, 9, 9, std::move(h));
}

int centre(const std::vector<std::uint8_t>& v) {
    return v[4 * 9 + 4];
}

double expected(double slopeRad, double aspectMathRad, double azimuthDeg = 315,
                double altitudeDeg = 45) {
    const double z = (90 - altitudeDeg) * M_PI / 180, az = (90 - azimuthDeg) * M_PI / 180;
    return std::max(1.0, 255 * (std::cos(z) * std::cos(slopeRad) +
                                std::sin(z) * std::sin(slopeRad) * std::cos(az - aspectMathRad)));
}

} // namespace

TEST(Hillshade, FlatGroundIsLitBySinOfTheAltitude) {
    const auto v = terrain::hillshade(plane(0, 0));
    for (auto b : v)
        EXPECT_EQ(b, 180);                                                    // 255 sin 45°
    EXPECT_EQ(centre(terrain::hillshade(plane(0, 0), {315, 30, 1, 1})), 128); // 255 sin 30° = 127.5
}

TEST(Hillshade, SlopesFacingTheLightAreBrightAndAwayFromItDark) {
    // Rising to the south-east at 45°: it faces the north-west light squarely.
    const double k = std::tan(M_PI / 4) / std::sqrt(2.0);
    EXPECT_EQ(centre(terrain::hillshade(plane(k, -k))), 255);
    // Rising to the north-west: facing away, the light grazes at 90° to the normal.
    EXPECT_EQ(centre(terrain::hillshade(plane(-k, k))), 1);
    // Facing north-east (rising to the south-west) at 30°: across the light, cos(slope)
    // cos(zenith).
    const double t = std::tan(M_PI / 6) / std::sqrt(2.0);
    EXPECT_NEAR(centre(terrain::hillshade(plane(-t, -t))), expected(M_PI / 6, M_PI / 4),
                0.5 + 1e-9);
    // A gentle slope facing south (rising to the north), 10 %.
    EXPECT_NEAR(centre(terrain::hillshade(plane(0, 0.1))), expected(std::atan(0.1), -M_PI / 2),
                0.5 + 1e-9);
    // The light from the south instead: that slope is now brighter than flat ground.
    EXPECT_GT(centre(terrain::hillshade(plane(0, 0.1), {180, 45, 1, 1})), 180);
    // A plane is shaded the same at every node inside the border.
    const auto v = terrain::hillshade(plane(0.3, 0.2));
    for (int r = 1; r < 8; ++r)
        for (int c = 1; c < 8; ++c)
            EXPECT_EQ(v[r * 9 + c], centre(v));
}

TEST(Hillshade, GroundMetresPerUnitAndTheZFactorScaleTheSlope) {
    // A grid in Web Mercator metres at 60° N: 2 grid units are 1 ground metre, so the 22.5 % the
    // grid shows is a 45 % slope on the ground.
    const auto merc = terrain::hillshade(plane(0.225, 0), {315, 45, 0.5, 1});
    EXPECT_NEAR(centre(merc), expected(std::atan(0.45), M_PI), 0.5 + 1e-9);
    EXPECT_EQ(centre(merc), centre(terrain::hillshade(plane(0.45, 0))));
    EXPECT_EQ(centre(terrain::hillshade(plane(0.225, 0), {315, 45, 1, 2})), centre(merc));
}

TEST(Hillshade, NoDataAndItsNeighboursAreTransparent) {
    HeightGrid g = plane(0, 0);
    std::vector<float> h;
    for (int r = 0; r < 9; ++r)
        for (int c = 0; c < 9; ++c)
            h.push_back(r == 4 && c == 4 ? std::numeric_limits<float>::quiet_NaN() : 100.0f);
    const auto v = terrain::hillshade(HeightGrid(0, 0, 2, 9, 9, std::move(h)));
    for (int r = 0; r < 9; ++r)
        for (int c = 0; c < 9; ++c) {
            const bool near = std::abs(r - 4) <= 1 && std::abs(c - 4) <= 1;
            EXPECT_EQ(v[r * 9 + c], near ? 0 : 180) << r << "," << c;
        }
    EXPECT_TRUE(terrain::hillshade(HeightGrid()).empty());
}
