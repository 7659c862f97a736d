// Grid: the approximate cellular decomposition of the admissible area (area minus no-fly zones).
#pragma once

#include "core/geo/no_fly_field.h"
#include "core/geo/polygon_ops.h"
#include "core/geo/types.h"
#include "core/result.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace pf::grid {

enum class CellState : std::uint8_t {
    Outside = 0,   // does not touch the admissible area: not part of the coverage problem
    Free = 1,      // must be photographed; flown at its centre
    Shifted = 2,   // must be photographed; its centre is not flyable, so its flight position is the
                   // nearest flyable point of the cell
    Unflyable = 3, // touches the admissible area but has no flyable point: reported, never visited
};

// 4-neighbourhood directions in grid coordinates (column +1 is East in the grid's own frame).
enum class Dir : std::uint8_t { East = 0, North = 1, West = 2, South = 3 };
constexpr Dir kDirs[4] = {Dir::East, Dir::North, Dir::West, Dir::South};
constexpr int kDirDx[4] = {1, 0, -1, 0};
constexpr int kDirDy[4] = {0, 1, 0, -1};
constexpr Dir opposite(Dir d) { return static_cast<Dir>((static_cast<int>(d) + 2) % 4); }

// Conventions (see grid.cpp for the reasons):
// - The grid frame is the local frame rotated by angleDeg (counter-clockwise from east) about the centre
//   of the area's bounding box; columns run along the rotated x axis, rows along the rotated y axis. The
//   grid covers the admissible area's bounding box in that frame, centred on it.
// - A cell belongs to the coverage problem when it overlaps the admissible area (area minus the
//   un-buffered no-fly zones) by more than 1e-6 of its own area (slivers below are numerical noise).
// - Its flight position is its centre if that is outside every no-fly zone buffered by the safety
//   margin (Free), else the nearest such point of the cell, moved 1 mm further in when it can be
//   (Shifted), else the cell is Unflyable. Points on a buffered zone's boundary count as safe.
// - Zones are buffered by margin / cos(11.25 deg) (about 2 % more) with 8 segments per quarter circle, so
//   that the polygonal buffer contains the true offset curve: the full margin holds at rounded corners.
// - Memory: 2 bytes per cell (state and moves) plus 24 bytes per Shifted cell and the polygons.
struct GridOptions {
    double cellSize = 0.0;        // metres, > 0
    double angleDeg = 0.0;        // grid rotation, counter-clockwise from east
    double safetyMarginM = 0.0;   // no flight position or move closer than this to a no-fly zone
    std::size_t maxCells = 4'000'000; // cell budget over the grid's bounding box
};

// What a grid is built from that depends on neither its cell size nor its angle: the admissible
// area (area minus the no-fly zones) and the zones buffered by the margin, pockets filled (see
// Grid). These GEOS booleans are most of a small grid's build; a planner that searches many angles
// and cell sizes over one region prepares them once. Immutable once prepared.
class GridGround {
public:
    // Errors as Grid::build's for the area (invalid or empty polygon, zones covering it all).
    static Result<GridGround> prepare(const geo::MultiPolygon& area,
                                      const std::vector<geo::Polygon>& noFly, double safetyMarginM);
    double safetyMarginM() const { return m_safetyMarginM; }
    const geo::MultiPolygon& admissible() const { return m_admissible; }

private:
    double m_safetyMarginM = 0.0;
    geo::Box m_areaBox; // the area's own box: the grids turn about its centre
    geo::MultiPolygon m_admissible;
    geo::MultiPolygon m_pockets;
    geo::NoFlyField m_noFly;           // the buffered zones, pockets filled
    std::vector<geo::Box> m_zoneBoxes; // per buffered zone

    friend class GridBuilder;
};

// Cells are indexed row-major: index = row * cols + col, row 0 at the grid's minimum y.
class Grid {
public:
    // Builds the grid of `area` minus `noFly` (local metres). Errors name the problem (bad cell size,
    // too many cells with the count and a cell size that would fit, empty admissible area).
    static Result<Grid> build(const geo::Polygon& area, const std::vector<geo::Polygon>& noFly,
                              const GridOptions& opt);

    // The same for an area made of several polygons (a subarea assigned to one aircraft).
    static Result<Grid> build(const geo::MultiPolygon& area, const std::vector<geo::Polygon>& noFly,
                              const GridOptions& opt);
    // The same on ground prepared once (opt.safetyMarginM must be the one it was prepared with):
    // the same grid as building from the area and zones.
    static Result<Grid> build(const GridGround& ground, const GridOptions& opt);
    // The errors Grid::build gives for its options alone (cell size, angle, margin), if any.
    static std::optional<Error> checkOptions(const GridOptions& opt);

    // Columns and rows a grid of side `cellSize` rotated by `angleDeg` needs to cover `region` (the
    // admissible area), computed without allocating anything: the cell budget is checked with it.
    struct Size {
        long long cols = 0;
        long long rows = 0;
        double cells() const { return static_cast<double>(cols) * static_cast<double>(rows); }
    };
    static Size sizeFor(const geo::MultiPolygon& region, double cellSize, double angleDeg);
    // The smallest cell size (rounded up to the centimetre, >= cellSize) whose grid over `region` fits
    // in `maxCells`.
    static double cellSizeToFit(const geo::MultiPolygon& region, double cellSize, double angleDeg,
                                std::size_t maxCells);

    // A synthetic grid for tests and benchmarks: mask[row * cols + col] != 0 means Free. Moves are
    // allowed between 4-adjacent Free cells; origin (0, 0), no rotation.
    static Grid fromMask(int cols, int rows, const std::vector<std::uint8_t>& mask, double cellSize = 1.0);

    int cols() const { return m_cols; }
    int rows() const { return m_rows; }
    int cellCount() const { return m_cols * m_rows; }
    int index(int col, int row) const { return row * m_cols + col; }
    int col(int i) const { return i % m_cols; }
    int row(int i) const { return i / m_cols; }
    bool inBounds(int col, int row) const { return col >= 0 && row >= 0 && col < m_cols && row < m_rows; }

    CellState state(int i) const { return static_cast<CellState>(m_state[i]); }
    // Cells the planners must visit: Free or Shifted.
    bool needsVisit(int i) const {
        const auto s = state(i);
        return s == CellState::Free || s == CellState::Shifted;
    }
    int visitCount() const { return m_visitCount; }

    // Neighbour index in direction d, or -1 past the grid's edge.
    int neighbour(int i, Dir d) const;
    // True if both cells need a visit and the straight segment between their flight positions keeps
    // out of every no-fly zone and its safety margin.
    bool canMove(int i, Dir d) const { return (m_moves[i] >> static_cast<int>(d)) & 1u; }
    // A visitable cell with at least one 4-neighbour that is not visitable (outside the area, in a
    // no-fly zone, or past the grid's edge): the area's contour as the planners see it.
    bool onContour(int i) const;

    double cellSize() const { return m_cellSize; }
    double angleDeg() const { return m_angleDeg; }
    // Local-frame position of the grid's (col 0, row 0) corner.
    geo::Vec2 origin() const { return m_origin; }
    geo::Vec2 cellCenter(int i) const;
    geo::Vec2 flightPosition(int i) const;
    // The cell's four corners in the local frame, counter-clockwise.
    std::vector<geo::Vec2> cellCorners(int i) const;
    // The cell whose square contains p, if p falls inside the grid's extent.
    std::optional<int> cellAt(const geo::Vec2& p) const;
    // The visitable cell whose flight position is nearest to p, or -1 if there is none.
    int nearestVisitable(const geo::Vec2& p) const;

    // The grid's no-fly model: its buffered zones (pockets filled) as a field of grown zones, so that
    // every safety question asked of the grid agrees with its cells and flight positions.
    const geo::NoFlyField& noFlyField() const { return m_noFly; }
    // True if the straight segment ab keeps out of every buffered no-fly zone (any two points, not only
    // neighbours: planners use it for diagonal moves and transits).
    bool segmentIsSafe(const geo::Vec2& a, const geo::Vec2& b) const { return m_noFly.segmentIsSafe(a, b); }
    // True if p is outside every buffered no-fly zone.
    bool pointIsSafe(const geo::Vec2& p) const { return m_noFly.pointIsSafe(p); }

    // The admissible area and buffered no-fly zones used to build the grid (local metres).
    const geo::MultiPolygon& admissible() const { return m_admissible; }
    // The buffered no-fly zones with every pocket filled (see pockets()).
    const geo::MultiPolygon& bufferedNoFly() const { return m_noFly.zones(); }
    // The admissible ground inside pockets: holes of the buffered zones, enclosed by margins that merge
    // round them, which no safe path reaches. They are treated as margin (never flown into); their
    // ground is photographed from outside as far as the footprints reach.
    const geo::MultiPolygon& pockets() const { return m_pockets; }

    // Approximate heap bytes held by the grid (for the memory budget).
    std::size_t memoryBytes() const;

private:
    int m_cols = 0;
    int m_rows = 0;
    int m_visitCount = 0;
    double m_cellSize = 1.0;
    double m_angleDeg = 0.0;
    geo::Vec2 m_origin{0, 0};
    std::vector<std::uint8_t> m_state; // CellState per cell
    std::vector<std::uint8_t> m_moves; // bit d set: move in direction d allowed
    // Flight positions of Shifted cells only (local frame), sorted by cell index and found by binary
    // search: few cells are shifted, so this keeps the per-cell cost low on large grids.
    std::vector<std::pair<int, geo::Vec2>> m_shifts;
    geo::MultiPolygon m_admissible;
    geo::NoFlyField m_noFly; // the buffered zones, grown by the margin
    geo::MultiPolygon m_pockets;
    double m_cos = 1.0;                 // cos/sin of the grid angle, cached for the cell transforms
    double m_sin = 0.0;

    friend class GridBuilder;
};

} // namespace pf::grid
