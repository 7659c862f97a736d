#include "core/geo/geodesic.h"
#include "core/geo/local_frame.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <thread>
#include <vector>

using namespace pf::geo;

namespace {
constexpr LonLat kKarlsruhe{8.4244, 49.0146};
}

TEST(LocalFrame, OriginMapsToZero) {
    auto f = LocalFrame::create(kKarlsruhe);
    ASSERT_TRUE(f.ok());
    const Vec2 p = f->toLocal(kKarlsruhe);
    EXPECT_NEAR(p.x(), 0.0, 1e-6);
    EXPECT_NEAR(p.y(), 0.0, 1e-6);
}

TEST(LocalFrame, AxesPointEastAndNorth) {
    auto f = LocalFrame::create(kKarlsruhe);
    ASSERT_TRUE(f.ok());
    const Vec2 east = f->toLocal({kKarlsruhe.lon + 0.01, kKarlsruhe.lat});
    const Vec2 north = f->toLocal({kKarlsruhe.lon, kKarlsruhe.lat + 0.01});
    EXPECT_GT(east.x(), 700.0);
    EXPECT_NEAR(east.y(), 0.0, 1.0);
    EXPECT_GT(north.y(), 1100.0);
    EXPECT_NEAR(north.x(), 0.0, 1e-6);
}

TEST(LocalFrame, PointTenKilometresAwayRoundTripsBelowOneMillimetre) {
    auto f = LocalFrame::create(kKarlsruhe);
    ASSERT_TRUE(f.ok());
    for (double az = 0; az < 360; az += 30) {
        const LonLat far = geodesicDirect(kKarlsruhe, az, 10000.0);
        const Vec2 local = f->toLocal(far);
        const LonLat back = f->toGeo(local);
        // Compare on the ground: geodesic distance between the original and the round-tripped point.
        EXPECT_LT(geodesicDistance(far, back), 1e-3) << "azimuth " << az;
    }
}

TEST(LocalFrame, LocalDistancesAgreeWithGeodesicWithinOneCentimetreOverTenKilometres) {
    auto f = LocalFrame::create(kKarlsruhe);
    ASSERT_TRUE(f.ok());
    for (double az = 0; az < 360; az += 15) {
        const LonLat far = geodesicDirect(kKarlsruhe, az, 10000.0);
        const double local = f->toLocal(far).norm();
        EXPECT_NEAR(local, geodesicDistance(kKarlsruhe, far), 0.01) << "azimuth " << az;
    }
    // Also between two points off the origin, across the frame.
    const LonLat a = geodesicDirect(kKarlsruhe, 300.0, 5000.0);
    const LonLat b = geodesicDirect(kKarlsruhe, 100.0, 5000.0);
    EXPECT_NEAR((f->toLocal(a) - f->toLocal(b)).norm(), geodesicDistance(a, b), 0.01);
}

TEST(LocalFrame, RoundTripsPolygonsWithHoles) {
    auto f = LocalFrame::create(kKarlsruhe);
    ASSERT_TRUE(f.ok());
    GeoPolygon g;
    g.outer = {{8.42, 49.01}, {8.43, 49.01}, {8.43, 49.02}, {8.42, 49.02}};
    g.holes = {{{8.424, 49.014}, {8.426, 49.014}, {8.426, 49.016}}};
    const GeoPolygon back = f->toGeo(f->toLocal(g));
    ASSERT_EQ(back.outer.size(), 4u);
    ASSERT_EQ(back.holes.size(), 1u);
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_NEAR(back.outer[i].lon, g.outer[i].lon, 1e-10);
        EXPECT_NEAR(back.outer[i].lat, g.outer[i].lat, 1e-10);
    }
}

TEST(LocalFrame, ForAreaCentresOnTheBoundingBox) {
    GeoPolygon g;
    g.outer = {{8.0, 49.0}, {8.2, 49.0}, {8.2, 49.1}, {8.0, 49.1}};
    auto f = LocalFrame::forArea(g);
    ASSERT_TRUE(f.ok());
    EXPECT_DOUBLE_EQ(f->origin().lon, 8.1);
    EXPECT_DOUBLE_EQ(f->origin().lat, 49.05);
}

TEST(LocalFrame, RejectsOutOfRangeOrigin) {
    auto f = LocalFrame::create({200.0, 49.0});
    ASSERT_FALSE(f.ok());
    EXPECT_NE(f.error().message.find("out of range"), std::string::npos);
    EXPECT_FALSE(LocalFrame::create({8.0, NAN}).ok());
    EXPECT_FALSE(LocalFrame::forArea(GeoPolygon{}).ok());
}

TEST(LocalFrame, CopiesAreIndependentAndEquivalent) {
    auto f = LocalFrame::create(kKarlsruhe);
    ASSERT_TRUE(f.ok());
    LocalFrame copy = *f;
    const LonLat p{8.43, 49.02};
    EXPECT_EQ(copy.toLocal(p), f->toLocal(p));
    EXPECT_NE(copy.projString().find("+proj=tmerc"), std::string::npos);
}

// A copy (its transformations cloned, not built anew) transforms bit for bit as its source, both
// ways, and keeps working after the source is gone; copies used on two threads at once agree too.
TEST(LocalFrame, CopiesTransformBitForBitAndOutliveTheirSource) {
    std::optional<LocalFrame> source;
    {
        auto f = LocalFrame::create(kKarlsruhe);
        ASSERT_TRUE(f.ok());
        source.emplace(std::move(*f));
    }
    std::vector<LonLat> geo;
    std::vector<Vec2> local;
    for (int k = 0; k < 200; ++k) {
        geo.push_back({kKarlsruhe.lon + 0.0003 * (k - 100),
                       kKarlsruhe.lat + 0.0002 * ((k * 37) % 200 - 100)});
        local.push_back(Vec2(13.7 * (k - 100), 9.1 * ((k * 53) % 200 - 100)));
    }
    std::vector<Vec2> wantLocal;
    std::vector<LonLat> wantGeo;
    for (std::size_t k = 0; k < geo.size(); ++k) {
        wantLocal.push_back(source->toLocal(geo[k]));
        wantGeo.push_back(source->toGeo(local[k]));
    }
    LocalFrame copy = *source;
    LocalFrame copyOfCopy = copy;
    source.reset();
    auto check = [&](const LocalFrame& f) {
        int same = 0;
        for (std::size_t k = 0; k < geo.size(); ++k) {
            const Vec2 l = f.toLocal(geo[k]);
            const LonLat g = f.toGeo(local[k]);
            same += l == wantLocal[k] && g.lon == wantGeo[k].lon && g.lat == wantGeo[k].lat;
        }
        return same;
    };
    EXPECT_EQ(check(copyOfCopy), 200);
    LocalFrame other = copy;
    int onThread = 0;
    std::thread t([&] { onThread = check(other); });
    const int here = check(copy);
    t.join();
    EXPECT_EQ(here, 200);
    EXPECT_EQ(onThread, 200);
}
