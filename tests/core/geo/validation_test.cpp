// Tests of polygon validation: each kind of bad polygon with the message a user sees.
#include "core/geo/validation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace pf::geo;

namespace {

GeoPolygon demoArea() {
    return GeoPolygon{{{8.3272608, 49.0109209},
                       {8.3324653, 49.0108309},
                       {8.3327392, 49.0123597},
                       {8.3308218, 49.0125396},
                       {8.3305478, 49.0133489},
                       {8.3273978, 49.013259}},
                      {}};
}

// The single error message, or a failure listing what was found instead.
std::string onlyError(const std::vector<Problem>& problems) {
    EXPECT_EQ(problems.size(), 1u);
    for (const auto& p : problems)
        if (p.severity == Severity::Error)
            return p.message;
    return "<no error>";
}

} // namespace

TEST(GeoValidation, DemoAreaIsValidWithOrWithoutClosingVertex) {
    EXPECT_TRUE(validatePolygon(demoArea(), "the area").empty());
    GeoPolygon closed = demoArea();
    closed.outer.push_back(closed.outer.front());
    EXPECT_TRUE(validatePolygon(closed, "the area").empty());
    EXPECT_EQ(cleanPolygon(closed), demoArea());
    GeoPolygon withHole = demoArea();
    withHole.holes.push_back({{8.3291782, 49.0118201}, {8.3297261, 49.0118201}, {8.3297261, 49.0121799},
                              {8.3291782, 49.0121799}});
    EXPECT_TRUE(validatePolygon(withHole, "the area").empty());
}

TEST(GeoValidation, TooFewDistinctVertices) {
    GeoPolygon p{{{8.33, 49.01}, {8.34, 49.01}, {8.33, 49.01}, {8.34, 49.01}}, {}};
    EXPECT_EQ(onlyError(validatePolygon(p, "the area")), "the area has 2 distinct vertices; a polygon needs at least 3");
    GeoPolygon one{{{8.33, 49.01}}, {}};
    EXPECT_EQ(onlyError(validatePolygon(one, "no-fly zone \"Mast\"")),
              "no-fly zone \"Mast\" has 1 distinct vertex; a polygon needs at least 3");
    EXPECT_EQ(onlyError(validatePolygon(GeoPolygon{}, "the area")), "the area has no vertices");
}

TEST(GeoValidation, ZeroArea) {
    GeoPolygon p{{{8.33, 49.01}, {8.331, 49.011}, {8.332, 49.012}}, {}};
    EXPECT_EQ(onlyError(validatePolygon(p, "the area")), "the area has zero area: all its vertices lie on one line");
}

TEST(GeoValidation, SelfIntersectionSaysWhichEdgesAndWhere) {
    // A bow tie: edges 1-2 and 3-4 cross in the middle.
    GeoPolygon bow{{{8.330, 49.010}, {8.332, 49.012}, {8.332, 49.010}, {8.330, 49.012}}, {}};
    EXPECT_EQ(onlyError(validatePolygon(bow, "the area")),
              "the area intersects itself: edges 1-2 and 3-4 cross near 49.011000° N, 8.331000° E");
    // A hexagon whose edges 2-3 and 5-6 cross (vertex 3 pulled across the polygon); a repeated closing
    // vertex does not change the numbering.
    GeoPolygon hex{{{8.3300, 49.0100},
                    {8.3320, 49.0100},
                    {8.3310, 49.0140},
                    {8.3320, 49.0130},
                    {8.3300, 49.0130},
                    {8.3330, 49.0115},
                    {8.3300, 49.0100}},
                   {}};
    const std::string msg = onlyError(validatePolygon(hex, "no-fly zone \"Yard\""));
    EXPECT_EQ(msg.rfind("no-fly zone \"Yard\" intersects itself: edges ", 0), 0u) << msg;
    EXPECT_NE(msg.find(" cross near 49.01"), std::string::npos) << msg;
}

TEST(GeoValidation, SpikeIsASelfIntersection) {
    // Vertex 3 goes back along edge 2-3: edges 2-3 and 3-4 overlap.
    GeoPolygon p{{{8.330, 49.010}, {8.332, 49.010}, {8.334, 49.010}, {8.333, 49.010}, {8.331, 49.012}}, {}};
    const std::string msg = onlyError(validatePolygon(p, "the area"));
    EXPECT_EQ(msg.rfind("the area intersects itself: edges 2-3 and 3-4 cross near 49.01", 0), 0u) << msg;
}

TEST(GeoValidation, CoordinatesOutOfRangeOrNotFinite) {
    GeoPolygon p = demoArea();
    p.outer[1] = {49.0108309, 98.3324653};
    EXPECT_EQ(onlyError(validatePolygon(p, "the area")),
              "vertex 2 of the area (49.010831, 98.332465) is out of range: longitude must lie within ±180 and "
              "latitude within ±90 degrees (is the order lon, lat?)");
    GeoPolygon n = demoArea();
    n.outer[0].lon = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(onlyError(validatePolygon(n, "the area")), "vertex 1 of the area is not a finite number");
    GeoPolygon polar{{{10, 86}, {11, 86}, {11, 87}}, {}};
    const auto problems = validatePolygon(polar, "the area");
    ASSERT_EQ(problems.size(), 3u);
    EXPECT_NE(problems[0].message.find("too close to a pole"), std::string::npos);
}

TEST(GeoValidation, HolesOutsideCrossingOrOverlapping) {
    GeoPolygon outside = demoArea();
    outside.holes.push_back({{8.3400, 49.0200}, {8.3410, 49.0200}, {8.3410, 49.0210}});
    EXPECT_EQ(onlyError(validatePolygon(outside, "the area")), "hole 1 of the area lies outside its outer ring");

    GeoPolygon crossing = demoArea();
    crossing.holes.push_back({{8.3270, 49.0115}, {8.3280, 49.0115}, {8.3280, 49.0120}, {8.3270, 49.0120}});
    EXPECT_EQ(onlyError(validatePolygon(crossing, "the area")), "hole 1 of the area crosses the outer ring");

    GeoPolygon overlap = demoArea();
    overlap.holes.push_back({{8.3290, 49.0115}, {8.3300, 49.0115}, {8.3300, 49.0120}, {8.3290, 49.0120}});
    overlap.holes.push_back({{8.3295, 49.0117}, {8.3305, 49.0117}, {8.3305, 49.0122}, {8.3295, 49.0122}});
    EXPECT_EQ(onlyError(validatePolygon(overlap, "the area")), "holes 1 and 2 of the area overlap");

    GeoPolygon badHole = demoArea();
    badHole.holes.push_back({{8.3290, 49.0115}, {8.3300, 49.0115}});
    EXPECT_EQ(onlyError(validatePolygon(badHole, "the area")),
              "hole 1 of the area has 2 distinct vertices; a polygon needs at least 3");
}
