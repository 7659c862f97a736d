// Shared helpers for planner tests: grids drawn as text, seeded shape generators, path invariants.
#pragma once

#include "core/grid/grid.h"
#include "core/plan/cell_path.h"
#include "core/plan/planner.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace pf::plan::test {

// A grid drawn as text, top line = highest row (north up): '.' or a letter = visitable, '#' = not.
inline grid::Grid drawGrid(const std::vector<std::string>& lines, double cellSize = 1.0) {
    const int rows = static_cast<int>(lines.size());
    const int cols = rows ? static_cast<int>(lines[0].size()) : 0;
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(rows * cols), 0);
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c)
            mask[r * cols + c] = lines[rows - 1 - r][c] != '#';
    return grid::Grid::fromMask(cols, rows, mask, cellSize);
}

// The cell of the first occurrence of `letter` in a drawing.
inline int cellOf(const std::vector<std::string>& lines, char letter) {
    const int rows = static_cast<int>(lines.size());
    for (int r = 0; r < rows; ++r) {
        const auto c = lines[r].find(letter);
        if (c != std::string::npos)
            return (rows - 1 - r) * static_cast<int>(lines[r].size()) + static_cast<int>(c);
    }
    return -1;
}

enum class Shape { Holes, Concave, Teeth, LShape };
inline const char* shapeName(Shape s) {
    switch (s) {
    case Shape::Holes:
        return "holes";
    case Shape::Concave:
        return "concave";
    case Shape::Teeth:
        return "teeth";
    case Shape::LShape:
        return "L";
    }
    return "?";
}

// Seeded random shapes: a rectangle with rectangular holes, with bites taken from its sides, with
// teeth along its top and bottom, or an L with holes.
inline grid::Grid randomShape(Shape shape, unsigned seed, int w = 24, int h = 18) {
    std::mt19937 rng(seed);
    auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    std::vector<std::uint8_t> m(static_cast<std::size_t>(w * h), 1);
    auto clear = [&](int x0, int y0, int x1, int y1) {
        for (int y = std::max(0, y0); y <= std::min(h - 1, y1); ++y)
            for (int x = std::max(0, x0); x <= std::min(w - 1, x1); ++x)
                m[y * w + x] = 0;
    };
    switch (shape) {
    case Shape::Holes:
        for (int k = uni(1, 5); k > 0; --k) {
            const int x = uni(1, w - 4), y = uni(1, h - 4);
            clear(x, y, x + uni(0, 4), y + uni(0, 3));
        }
        break;
    case Shape::Concave:
        for (int k = uni(3, 8); k > 0; --k) {
            const int side = uni(0, 3), depth = uni(1, 6), a = uni(0, std::max(w, h)), len = uni(1, 7);
            if (side == 0)
                clear(a, 0, a + len, depth - 1);
            else if (side == 1)
                clear(a, h - depth, a + len, h - 1);
            else if (side == 2)
                clear(0, a, depth - 1, a + len);
            else
                clear(w - depth, a, w - 1, a + len);
        }
        if (uni(0, 1))
            clear(w / 2 - 1, h / 2 - 1, w / 2 + uni(0, 2), h / 2 + uni(0, 2));
        break;
    case Shape::Teeth:
        for (int x = 0; x < w; ++x) {
            if (uni(0, 2) == 0)
                clear(x, 0, x, uni(0, 3));
            if (uni(0, 2) == 0)
                clear(x, h - 1 - uni(0, 3), x, h - 1);
        }
        break;
    case Shape::LShape:
        clear(w / 2 + uni(-3, 3), h / 2 + uni(-3, 3), w - 1, h - 1);
        for (int k = uni(0, 3); k > 0; --k) {
            const int x = uni(1, w / 2 - 2), y = uni(1, h / 2 - 2);
            clear(x, y, x + uni(0, 2), y + uni(0, 2));
        }
        break;
    }
    return grid::Grid::fromMask(w, h, m, 10.0);
}

// Coverage invariants every planner must meet: each visitable cell photographed exactly once, every
// cell of the path visitable, consecutive cells joined by allowed steps except for `path.jumps`
// declared jumps, and the transit flags consistent.
inline void expectValidCoverage(const grid::Grid& g, const CellPath& path, bool diagonal, int allowedJumps,
                                const std::string& what) {
    ASSERT_EQ(path.cells.size(), path.revisit.size()) << what;
    std::vector<int> photos(static_cast<std::size_t>(g.cellCount()), 0);
    for (std::size_t i = 0; i < path.cells.size(); ++i) {
        const int c = path.cells[i];
        ASSERT_TRUE(c >= 0 && c < g.cellCount()) << what << ": cell " << c << " outside the grid";
        ASSERT_TRUE(g.needsVisit(c)) << what << ": path enters non-visitable cell " << c;
        if (!path.revisit[i])
            ++photos[c];
    }
    for (int i = 0; i < g.cellCount(); ++i) {
        if (g.needsVisit(i)) {
            EXPECT_EQ(photos[i], 1) << what << ": cell (" << g.col(i) << ", " << g.row(i) << ") photographed "
                                    << photos[i] << " times";
        }
    }
    int jumps = 0;
    for (std::size_t i = 1; i < path.cells.size(); ++i)
        if (!isAllowedStep(g, path.cells[i - 1], path.cells[i], diagonal))
            ++jumps;
    EXPECT_EQ(jumps, path.jumps) << what << ": declared jumps differ from the path's";
    EXPECT_LE(jumps, allowedJumps) << what;
}

// Connected components of the unvisited visitable cells over allowed moves: component id per cell
// (-1 for visited or not visitable) and the component sizes.
inline std::vector<int> freeComponents(const grid::Grid& g, const std::vector<std::uint8_t>& visited,
                                       std::vector<int>* sizes) {
    std::vector<int> comp(static_cast<std::size_t>(g.cellCount()), -1);
    sizes->clear();
    for (int i = 0; i < g.cellCount(); ++i) {
        if (!g.needsVisit(i) || visited[i] || comp[i] >= 0)
            continue;
        const int id = static_cast<int>(sizes->size());
        sizes->push_back(0);
        std::vector<int> stack{i};
        comp[i] = id;
        while (!stack.empty()) {
            const int c = stack.back();
            stack.pop_back();
            ++(*sizes)[id];
            for (grid::Dir d : grid::kDirs) {
                if (!g.canMove(c, d))
                    continue;
                const int n = g.neighbour(c, d);
                if (!visited[n] && comp[n] < 0) {
                    comp[n] = id;
                    stack.push_back(n);
                }
            }
        }
    }
    return comp;
}

} // namespace pf::plan::test
