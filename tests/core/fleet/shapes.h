// Seeded synthetic base grids (grid::Grid::fromMask) for the fleet tests: concave outlines with holes.
#pragma once

#include "core/grid/grid.h"

#include <cstdint>
#include <deque>
#include <random>
#include <vector>

namespace pf::fleet::test {

// A rectangle with notches cut from its edges and rectangular holes inside, reduced to its largest
// 4-connected piece. Same seed, same shape.
inline grid::Grid generatedShape(unsigned seed, double cellSize = 10.0) {
    std::mt19937 rng(seed);
    auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    const int cols = uni(16, 40), rows = uni(16, 40);
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(cols * rows), 1);
    auto cut = [&](int x0, int y0, int w, int h) {
        for (int y = std::max(0, y0); y < std::min(rows, y0 + h); ++y)
            for (int x = std::max(0, x0); x < std::min(cols, x0 + w); ++x)
                mask[static_cast<std::size_t>(y * cols + x)] = 0;
    };
    for (int i = uni(1, 3); i > 0; --i) { // notches from the edges: concave outline
        const int w = uni(cols / 5, cols / 2), h = uni(rows / 5, rows / 2);
        switch (uni(0, 3)) {
        case 0: cut(uni(0, cols - w), 0, w, h); break;
        case 1: cut(uni(0, cols - w), rows - h, w, h); break;
        case 2: cut(0, uni(0, rows - h), w, h); break;
        default: cut(cols - w, uni(0, rows - h), w, h); break;
        }
    }
    for (int i = uni(0, 3); i > 0; --i) // holes (no-fly zones)
        cut(uni(3, cols - 6), uni(3, rows - 6), uni(2, 4), uni(2, 4));
    // Keep the largest piece.
    std::vector<int> label(mask.size(), -1);
    int best = -1, bestSize = 0, next = 0;
    for (int s = 0; s < cols * rows; ++s) {
        if (!mask[static_cast<std::size_t>(s)] || label[static_cast<std::size_t>(s)] >= 0)
            continue;
        int size = 0;
        std::deque<int> q{s};
        label[static_cast<std::size_t>(s)] = next;
        while (!q.empty()) {
            const int c = q.front();
            q.pop_front();
            ++size;
            const int x = c % cols, y = c / cols;
            const int nb[4][2] = {{x + 1, y}, {x - 1, y}, {x, y + 1}, {x, y - 1}};
            for (auto& n : nb) {
                if (n[0] < 0 || n[1] < 0 || n[0] >= cols || n[1] >= rows)
                    continue;
                const auto j = static_cast<std::size_t>(n[1] * cols + n[0]);
                if (mask[j] && label[j] < 0) {
                    label[j] = next;
                    q.push_back(static_cast<int>(j));
                }
            }
        }
        if (size > bestSize) {
            bestSize = size;
            best = next;
        }
        ++next;
    }
    for (std::size_t i = 0; i < mask.size(); ++i)
        mask[i] = label[i] == best;
    return grid::Grid::fromMask(cols, rows, mask, cellSize);
}

inline int activeCount(const grid::Grid& g) { return g.visitCount(); }

} // namespace pf::fleet::test
