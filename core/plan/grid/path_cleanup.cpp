// Repairs of a finished cell path: transits over allowed moves and the paper's clean-up of revisits.
#include "core/plan/grid/path_cleanup.h"

#include "core/plan/grid/grid_search.h"

#include <algorithm>
#include <unordered_map>

namespace pf::plan {

using grid::Dir;
using grid::Grid;

void appendTransit(const Grid& g, CellPath& path, int to) {
    if (path.cells.empty() || path.cells.back() == to)
        return;
    GridSearch search(g);
    const std::vector<int> p = search.pathTo(path.cells.back(), to);
    if (p.empty()) {
        ++path.jumps;
        path.cells.push_back(to);
        path.revisit.push_back(true);
        return;
    }
    for (int c : p) {
        path.cells.push_back(c);
        path.revisit.push_back(true);
    }
}

void cleanUpRevisits(const Grid& g, CellPath& path) {
    const std::size_t n = path.cells.size();
    if (n < 3)
        return;
    CellPath out;
    out.jumps = path.jumps;
    out.cells.reserve(n);
    out.revisit.reserve(n);
    std::unordered_map<int, std::size_t> lastPos;
    std::size_t windowEnd = 0; // last position of the current window (exclusive bound + 1)
    std::size_t i = 0;
    bool pushCurrent = true;
    while (i < n) {
        if (pushCurrent) {
            out.cells.push_back(path.cells[i]);
            out.revisit.push_back(path.revisit[i]);
        }
        pushCurrent = true;
        if (i + 2 >= n || !path.revisit[i + 1]) {
            ++i;
            continue;
        }
        // The window: the run of transit occurrences after i, plus the occurrence ending it.
        if (windowEnd <= i + 1) {
            std::size_t e = i + 1;
            while (e + 1 < n && path.revisit[e + 1])
                ++e;
            windowEnd = std::min(e + 1, n - 1);
            lastPos.clear();
            for (std::size_t k = i + 1; k <= windowEnd; ++k)
                lastPos[path.cells[k]] = k;
        }
        const int c = path.cells[i];
        std::size_t far = 0;
        bool same = false;
        auto consider = [&](int cell, bool isSame) {
            auto it = lastPos.find(cell);
            if (it != lastPos.end() && it->second >= i + 2 && it->second > far) {
                far = it->second;
                same = isSame;
            }
        };
        consider(c, true);
        for (int d = 0; d < 4; ++d)
            if (g.canMove(c, static_cast<Dir>(d)))
                consider(c + dirOffset(g, d), false);
        if (far == 0) {
            ++i;
            continue;
        }
        // Occurrences i+1 .. far-1 are all transits: drop them. When path[far] is the same cell as
        // path[i], drop it too and keep i's occurrence, photographed if either of the two was (a path
        // that leaves a cell in transit and comes back to photograph it photographs it once).
        i = far;
        pushCurrent = !same;
        if (same && !path.revisit[far])
            out.revisit.back() = false;
    }
    path = std::move(out);
}

} // namespace pf::plan
