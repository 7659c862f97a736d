#include "core/route/photo_waypoints.h"
#include "core/plan/coverage_check.h"

#include "core/plan/grid/stride_planner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace pf::route {
namespace {

sensor::EffectiveFootprint footprint(double across, double along) {
    sensor::EffectiveFootprint fp;
    fp.acrossM = across;
    fp.alongM = along;
    return fp;
}

TEST(PhotoWaypoints, Heading) {
    EXPECT_DOUBLE_EQ(headingDeg({0, 1}), 0.0);
    EXPECT_DOUBLE_EQ(headingDeg({1, 0}), 90.0);
    EXPECT_DOUBLE_EQ(headingDeg({0, -1}), 180.0);
    EXPECT_DOUBLE_EQ(headingDeg({-1, 0}), 270.0);
}

TEST(PhotoWaypoints, PhotosPerCell) {
    // 24 m cells (the long side), 13.5 m along: two photos per cell.
    EXPECT_EQ(photosPerCell(24, footprint(24, 13.5)).along, 2);
    EXPECT_EQ(photosPerCell(24, footprint(24, 13.5)).across, 1);
    EXPECT_EQ(photosPerCell(24, footprint(24, 24)).along, 1);
    EXPECT_EQ(photosPerCell(24, footprint(24, 7.9)).along, 4);
    // Overlaps that make the long side the shorter effective side: photos across as well.
    EXPECT_EQ(photosPerCell(20, footprint(12, 20)).across, 2);
}

// Paper 001's rule: every cell alone.
TEST(PhotoWaypoints, StraightRowSpacingAndHeading) {
    std::vector<std::uint8_t> mask(3, 1);
    const grid::Grid g = grid::Grid::fromMask(3, 1, mask, 24.0);
    plan::CellPath path;
    path.cells = {0, 1, 2};
    path.revisit = {false, false, false};
    const auto wps = photoWaypoints(g, path, footprint(24, 13.5), nullptr, PhotoRule::PerCell);
    ASSERT_EQ(wps.size(), 6u);
    for (std::size_t k = 0; k < wps.size(); ++k) {
        EXPECT_EQ(wps[k].kind, WaypointKind::Photo);
        EXPECT_DOUBLE_EQ(wps[k].headingDeg, 90.0); // flying east
        EXPECT_NEAR(wps[k].pos.y(), 12.0, 1e-9);
        EXPECT_NEAR(wps[k].pos.x(), 6.0 + 12.0 * k, 1e-9); // evenly spaced by 12 m <= 13.5 m
        EXPECT_EQ(wps[k].cell, static_cast<int>(k / 2));
    }
}

TEST(PhotoWaypoints, EveryCellCoveredAlongTheTrack) {
    // For any path, each photographed cell's photos span the whole cell along their heading.
    std::vector<std::uint8_t> mask(6 * 5, 1);
    mask[2 * 6 + 2] = 0;
    const grid::Grid g = grid::Grid::fromMask(6, 5, mask, 30.0);
    auto path = plan::planStride(g, {});
    ASSERT_TRUE(path.ok());
    const auto fp = footprint(30, 11);
    const auto wps = photoWaypoints(g, *path, fp, nullptr, PhotoRule::PerCell);
    std::map<int, std::vector<const LocalWaypoint*>> byCell;
    for (const auto& w : wps)
        if (w.kind == WaypointKind::Photo)
            byCell[w.cell].push_back(&w);
    EXPECT_EQ(static_cast<int>(byCell.size()), g.visitCount());
    for (const auto& [cell, photos] : byCell) {
        ASSERT_EQ(photos.size(), 3u); // ceil(30 / 11)
        const double h = photos.front()->headingDeg * M_PI / 180.0;
        const geo::Vec2 dir(std::sin(h), std::cos(h));
        double lo = 1e9, hi = -1e9;
        for (const auto* w : photos) {
            EXPECT_DOUBLE_EQ(w->headingDeg, photos.front()->headingDeg);
            const double t = (w->pos - g.flightPosition(cell)).dot(dir);
            lo = std::min(lo, t - fp.alongM / 2);
            hi = std::max(hi, t + fp.alongM / 2);
            // Centred on the track through the cell.
            EXPECT_NEAR((w->pos - g.flightPosition(cell) - t * dir).norm(), 0.0, 1e-9);
        }
        EXPECT_LE(lo, -15.0 + 1e-9);
        EXPECT_GE(hi, 15.0 - 1e-9);
    }
}

// The same row as lanes: one lane 72 m long, photos the trigger distance apart (ceil(72 / 13.5) = 6 at
// 13.5 m, centred), all on the row's centre line and heading east: the aircraft flies it straight.
TEST(PhotoWaypoints, StraightRowIsOneLaneAtTheTriggerDistance) {
    std::vector<std::uint8_t> mask(3, 1);
    const grid::Grid g = grid::Grid::fromMask(3, 1, mask, 24.0);
    plan::CellPath path;
    path.cells = {0, 1, 2};
    path.revisit = {false, false, false};
    const auto wps = photoWaypoints(g, path, footprint(24, 13.5));
    ASSERT_EQ(wps.size(), 6u);
    for (std::size_t k = 0; k < wps.size(); ++k) {
        EXPECT_EQ(wps[k].kind, WaypointKind::Photo);
        EXPECT_DOUBLE_EQ(wps[k].headingDeg, 90.0);
        EXPECT_NEAR(wps[k].pos.y(), 12.0, 1e-9);
        EXPECT_NEAR(wps[k].pos.x(), 36.0 + 13.5 * (static_cast<double>(k) - 2.5), 1e-9);
    }
    // The first and last effective footprints reach the row's ends.
    EXPECT_LE(wps.front().pos.x() - 13.5 / 2, 0.0);
    EXPECT_GE(wps.back().pos.x() + 13.5 / 2, 72.0);
}

// Lanes on the planned paths of an area with a hole, at several grid angles: consecutive photos of a
// lane (same heading, on one line) keep the trigger distance, every heading change comes at a lane's
// end, and the real footprints cover the whole area.
TEST(PhotoWaypoints, LanesKeepTheTriggerDistanceAndCoverTheArea) {
    const geo::Polygon area{{{0, 0}, {260, 0}, {260, 170}, {0, 170}}, {{{90, 60}, {150, 60}, {150, 110}, {90, 110}}}};
    for (double angle : {0.0, 17.0, 90.0, 133.0}) {
        grid::GridOptions opt;
        opt.cellSize = 30;
        opt.angleDeg = angle;
        auto g = grid::Grid::build(area, {}, opt);
        ASSERT_TRUE(g.ok()) << g.error().message;
        auto path = plan::planStride(*g, {});
        ASSERT_TRUE(path.ok());
        sensor::EffectiveFootprint fp = footprint(30, 11);
        fp.real.longSideM = 30 / 0.8;
        fp.real.shortSideM = 11 / 0.8;
        const auto wps = photoWaypoints(*g, *path, fp);
        std::vector<plan::PhotoFootprint> photos;
        for (std::size_t k = 0; k < wps.size(); ++k) {
            if (wps[k].kind != WaypointKind::Photo)
                continue;
            photos.push_back({wps[k].pos, wps[k].headingDeg, fp.real.longSideM, fp.real.shortSideM});
            if (k == 0 || wps[k - 1].kind != WaypointKind::Photo || wps[k].headingDeg != wps[k - 1].headingDeg)
                continue;
            const double h = wps[k].headingDeg * M_PI / 180.0;
            const geo::Vec2 dir(std::sin(h), std::cos(h)), step = wps[k].pos - wps[k - 1].pos;
            if (std::fabs(step.x() * dir.y() - step.y() * dir.x()) < 1e-6 && step.dot(dir) > 0) {
                EXPECT_NEAR(step.norm(), 11.0, 1e-6) << "angle " << angle << ", photo " << k;
            }
        }
        auto cov = plan::checkCoverage({area}, photos);
        ASSERT_TRUE(cov.ok());
        EXPECT_GE(cov->coveredFraction, 0.9999) << "angle " << angle;
    }
}

TEST(PhotoWaypoints, RevisitsAndTakeoffLegGetNoPhoto) {
    std::vector<std::uint8_t> mask(3 * 3, 1);
    const grid::Grid g = grid::Grid::fromMask(3, 3, mask, 10.0);
    plan::CellPath path;
    // Take-off leg over (2,2) -> (2,1) -> (2,0), turn west, photos on row 0, back over (1,0) as a transit
    // and up to (1,1).
    path.cells = {g.index(1, 2), g.index(2, 2), g.index(2, 1), g.index(2, 0), g.index(1, 0), g.index(0, 0),
                  g.index(1, 0), g.index(1, 1)};
    path.revisit = {true, true, true, false, false, false, true, false};
    const auto wps = photoWaypoints(g, path, footprint(10, 10));
    int photos = 0, turns = 0, transits = 0;
    for (const auto& w : wps) {
        photos += w.kind == WaypointKind::Photo;
        turns += w.kind == WaypointKind::Turn;
        transits += w.kind == WaypointKind::Transit;
    }
    EXPECT_EQ(photos, 4);
    // (1,2) is the first point, (2,2) turns south: two turn points without photos.
    EXPECT_EQ(turns, 2);
    // (1,0) revisited where the path turns north.
    EXPECT_EQ(transits, 1);
    for (const auto& w : wps) {
        if (w.kind == WaypointKind::Transit) {
            EXPECT_EQ(w.cell, g.index(1, 0));
        }
    }
}

TEST(PhotoWaypoints, RotatedGridHeadings) {
    geo::Polygon area{{{0, 0}, {100, 0}, {100, 100}, {0, 100}}, {}};
    grid::GridOptions opt;
    opt.cellSize = 20;
    opt.angleDeg = 30;
    auto g = grid::Grid::build(area, {}, opt);
    ASSERT_TRUE(g.ok()) << g.error().message;
    auto path = plan::planStride(*g, {});
    ASSERT_TRUE(path.ok());
    const auto wps = photoWaypoints(*g, *path, footprint(20, 20));
    // Grid east is 30 deg counter-clockwise from local east: heading 60; grid north: heading 330.
    for (const auto& w : wps) {
        const double h = w.headingDeg;
        const bool axis = std::fabs(std::remainder(h - 60.0, 90.0)) < 1e-6;
        EXPECT_TRUE(axis) << h;
    }
}

// Legs without a photo between two waypoints fly straight where that is safe and over the area.
TEST(StraightenTransits, OpenGridFliesStraightAndKeepsEveryPhoto) {
    std::vector<std::uint8_t> mask(3 * 3, 1);
    const grid::Grid g = grid::Grid::fromMask(3, 3, mask, 10.0);
    plan::CellPath path;
    path.cells = {g.index(1, 2), g.index(2, 2), g.index(2, 1), g.index(2, 0), g.index(1, 0), g.index(0, 0),
                  g.index(1, 0), g.index(1, 1)};
    path.revisit = {true, true, true, false, false, false, true, false};
    auto wps = photoWaypoints(g, path, footprint(10, 10));
    std::vector<geo::Vec2> photosBefore;
    for (const auto& w : wps)
        if (w.kind == WaypointKind::Photo)
            photosBefore.push_back(w.pos);
    straightenTransits(g, wps);
    // The first point stays; the take-off leg's turn at (2,2) and the transit at (1,0) go.
    ASSERT_FALSE(wps.empty());
    EXPECT_EQ(wps.front().cell, g.index(1, 2));
    std::vector<geo::Vec2> photosAfter;
    int others = 0;
    for (const auto& w : wps) {
        if (w.kind == WaypointKind::Photo)
            photosAfter.push_back(w.pos);
        else
            ++others;
    }
    EXPECT_EQ(others, 1);
    EXPECT_EQ(photosAfter, photosBefore);
}

TEST(StraightenTransits, KeepsTheWayAroundANoFlyZone) {
    const geo::Polygon area{{{0, 0}, {100, 0}, {100, 60}, {0, 60}}, {}};
    const geo::Polygon zone{{{41, 21}, {59, 21}, {59, 39}, {41, 39}}, {}};
    grid::GridOptions opt;
    opt.cellSize = 20;
    opt.safetyMarginM = 3; // the zone and its margin cover the middle cell (2,1) whole
    auto g = grid::Grid::build(area, {zone}, opt);
    ASSERT_TRUE(g.ok()) << g.error().message;
    ASSERT_FALSE(g->needsVisit(g->index(2, 1)));
    plan::CellPath path;
    path.cells = {g->index(1, 1), g->index(1, 2), g->index(2, 2), g->index(3, 2), g->index(3, 1)};
    path.revisit = {false, true, true, true, false};
    auto wps = photoWaypoints(*g, path, footprint(20, 20));
    const auto before = wps.size();
    straightenTransits(*g, wps);
    EXPECT_EQ(wps.size(), before); // the straight leg would cross the zone's margin
}

TEST(StraightenTransits, KeepsTheWayRoundAConcaveArea) {
    // A U: cells (2,1) and (2,2) lie outside; a straight leg across the notch would leave the area.
    const geo::Polygon area{{{0, 0}, {100, 0}, {100, 60}, {60, 60}, {60, 20}, {40, 20}, {40, 60}, {0, 60}}, {}};
    grid::GridOptions opt;
    opt.cellSize = 20;
    auto g = grid::Grid::build(area, {}, opt);
    ASSERT_TRUE(g.ok()) << g.error().message;
    ASSERT_FALSE(g->needsVisit(g->index(2, 2)));
    plan::CellPath path;
    path.cells = {g->index(1, 2), g->index(1, 1), g->index(1, 0), g->index(2, 0),
                  g->index(3, 0), g->index(3, 1), g->index(3, 2)};
    path.revisit = {false, true, true, true, true, true, false};
    auto wps = photoWaypoints(*g, path, footprint(20, 20));
    const auto before = wps.size();
    straightenTransits(*g, wps);
    EXPECT_EQ(wps.size(), before);
    // A way back on the left arm, where the straight leg stays over the area, is cut short.
    plan::CellPath open;
    open.cells = {g->index(0, 2), g->index(0, 1), g->index(0, 0), g->index(1, 0), g->index(1, 1)};
    open.revisit = {false, true, true, true, false};
    auto straight = photoWaypoints(*g, open, footprint(20, 20));
    straightenTransits(*g, straight);
    for (const auto& w : straight)
        EXPECT_EQ(w.kind, WaypointKind::Photo);
}

// The bug of generated area 8 (seed 1): after the no-fly stage a detour's corner T lay 9 cm before a
// photo P; dropping T joined the waypoint before straight to P, a leg cutting 4 cm into the margin
// of a zone's corner, and nothing after that stage repairs a leg. Given the planner's field, the drop
// keeps every leg safe: here T and P merge at T's position (the photo moves by 9 cm).
TEST(DropNearDuplicates, NeverCutsACornerIntoAMargin) {
    // A 10 m square zone, margin 5 m: its top edge is at y = 10, the margin's edge at y = 15.
    const geo::NoFlyField field({geo::Polygon{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {}}}, 5.0);
    const geo::Vec2 x(-20, 14.97), t(20, 14.97), p(20.05, 14.90), q(40, 14.90);
    ASSERT_TRUE(field.segmentIsSafe(x, t)); // 4.97 m from the zone: within the margin's tolerance
    ASSERT_TRUE(field.segmentIsSafe(t, p));
    ASSERT_FALSE(field.segmentIsSafe(x, p)); // 4.93 m over the zone's top edge
    ASSERT_LT((t - p).norm(), kMinWaypointGapM);
    const std::vector<LocalWaypoint> route{{x, 90, WaypointKind::Photo, -1},
                                           {t, 90, WaypointKind::Transit, -1},
                                           {p, 90, WaypointKind::Photo, -1},
                                           {q, 90, WaypointKind::Photo, -1}};
    auto photos = [](const std::vector<LocalWaypoint>& w) {
        return std::count_if(w.begin(), w.end(), [](const auto& v) { return v.kind == WaypointKind::Photo; });
    };

    // Without a field (before the no-fly stage, which repairs what this leaves) T goes: the cut leg.
    auto blind = route;
    dropNearDuplicates(blind);
    ASSERT_EQ(blind.size(), 3u);
    EXPECT_FALSE(field.segmentIsSafe(blind[0].pos, blind[1].pos));

    auto safe = route;
    dropNearDuplicates(safe, &field);
    EXPECT_EQ(photos(safe), 3);
    ASSERT_EQ(safe.size(), 3u);
    EXPECT_EQ(safe[1].kind, WaypointKind::Photo);
    EXPECT_LT((safe[1].pos - p).norm(), kMinWaypointGapM);
    for (std::size_t i = 1; i < safe.size(); ++i) {
        EXPECT_TRUE(field.segmentIsSafe(safe[i - 1].pos, safe[i].pos)) << "leg " << i;
        EXPECT_GE((safe[i].pos - safe[i - 1].pos).norm(), kMinWaypointGapM) << "leg " << i;
    }

    // When neither the drop nor a merge keeps the margin, both waypoints stay.
    auto stuck = route;
    stuck[3].pos = geo::Vec2(-20, 14.90); // the leg on from T would cross the margin too
    ASSERT_FALSE(field.segmentIsSafe(t, stuck[3].pos));
    dropNearDuplicates(stuck, &field);
    ASSERT_EQ(stuck.size(), 4u);
    EXPECT_EQ(stuck[1].pos, t);
    EXPECT_EQ(stuck[2].pos, p);
}

} // namespace
} // namespace pf::route
