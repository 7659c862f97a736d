#include "core/plan/grid/stride_planner.h"

#include "core/job_scope.h"
#include "core/plan/best_candidate.h"
#include "core/plan/grid/grid_search.h"
#include "core/plan/grid/nearest_cell.h"
#include "core/plan/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

namespace pf::plan {

using grid::Dir;
using grid::Grid;

namespace {

constexpr double kLaneWeight = 2.0;
// Variants cost planning time: lead-ins (up to 12 more plans) only up to kLeadInCellLimit cells to
// photograph, the fixed lane axes (2 more) up to kAxesCellLimit. Beyond, the paper's rules and one lane
// variant.
constexpr int kLeadInCellLimit = 5'000;
constexpr int kAxesCellLimit = 250'000;

using detail::blocked;
using detail::growStride;
using detail::limitsOf;
using detail::popcount2;

// Union-find over small integer ids.
struct UnionFind {
    std::vector<int> parent;
    void reset(int n) {
        parent.resize(static_cast<std::size_t>(n));
        std::iota(parent.begin(), parent.end(), 0);
    }
    int find(int x) {
        while (parent[x] != x) {
            parent[x] = parent[parent[x]];
            x = parent[x];
        }
        return x;
    }
    // Returns the surviving root.
    int unite(int a, int b) {
        a = find(a);
        b = find(b);
        if (a == b)
            return a;
        if (b < a)
            std::swap(a, b);
        parent[b] = a;
        return a;
    }
};

class StridePlanner {
public:
    StridePlanner(const Grid& g, StrideTrace* trace, const StrideVariant& variant)
        : m_g(g), m_n(static_cast<std::size_t>(g.cellCount())), m_visited(m_n, 0), m_search(g),
          m_seedMark(m_n, 0), m_seedSlot(m_n, 0), m_partMark(m_n, 0), m_partGroup(m_n, 0),
          m_targetMark(m_n, 0), m_trace(trace), m_variant(variant), m_laneAxis(variant.laneAxis) {}

    CellPath run(int start) {
        m_remaining = m_g.visitCount();
        visitNew(start);
        newCellsAdded(&start, 1);
        if (m_trace)
            m_trace->segmentEnds.push_back(1);
        std::vector<int> best, cand;
        while (m_remaining > 0 && !stopRequested()) { // a cancelled job drops the partial path
            const int cur = m_path.cells.back();
            // Steps 2-4: the longest stride towards each unvisited neighbour.
            int bestDir = -1;
            StrideKey bestKey;
            for (int d = 0; d < 4; ++d) {
                if (blocked(m_g, m_visited, cur, d) || !inTarget(cur + dirOffset(m_g, d)))
                    continue;
                growStride(m_g, m_visited, cur, d, cand, alongLanes(d));
                StrideKey key = keyFor(cur, d, cand);
                laneChange(d, cand, key);
                if (bestDir < 0 || better(key, bestKey, cand, best, cur, d, bestDir)) {
                    bestDir = d;
                    bestKey = key;
                    best.swap(cand);
                }
            }
            if (bestDir < 0) {
                leaveDeadEnd(cur);
                continue;
            }
            // Steps 5-6.
            for (int c : best)
                visitNew(c);
            newCellsAdded(best.data(), best.size());
            m_heading = bestDir;
            if (best.size() >= 2)
                m_laneAxis = bestDir % 2;
            if (m_trace)
                m_trace->segmentEnds.push_back(m_g.visitCount() - m_remaining);
        }
        if (m_trace)
            // Planner arrays, plus the search's per-cell wave layers.
            m_trace->scratchBytes = m_n * (1 + 4 + 1 + 4 + 4 + 4 + 4 + 4) + m_n * 4;
        return std::move(m_path);
    }

private:
    // The tie-breaking keys, compared in the paper's order after the stride length.
    struct StrideKey {
        int length = 0;
        int limits = 0;    // heuristic (1): limits and visited cells beside the neighbour
        bool contour = false; // heuristic (2): the neighbour lies on the area's contour
    };

    StrideKey keyFor(int cur, int d, const std::vector<int>& cells) const {
        StrideKey k;
        k.length = static_cast<int>(cells.size()) + 1;
        (void)cur;
        k.limits = popcount2(limitsOf(m_g, m_visited, cells.front(), d));
        k.contour = m_g.onContour(cells.front());
        return k;
    }

    // True if candidate (a, dir da) beats the current best (b, dir db). Longest stride first; on equal
    // length: heuristic (1), (2), (3) (the longer next stride), then keeping the current heading, then
    // the fixed order East, North, West, South (the order candidates are examined, so the earlier wins).
    bool better(const StrideKey& ka, const StrideKey& kb, const std::vector<int>& a, const std::vector<int>& b,
                int /*cur*/, int da, int db) {
        if (ka.length != kb.length)
            return ka.length > kb.length;
        if (ka.limits != kb.limits)
            return ka.limits > kb.limits;
        if (ka.contour != kb.contour)
            return ka.contour;
        const int na = nextStrideLength(a), nb = nextStrideLength(b);
        if (na != nb)
            return na > nb;
        if ((da == m_heading) != (db == m_heading))
            return da == m_heading;
        return false;
    }

    // Lane variants (beyond the paper): a stride across the lanes of the last long stride is cut to
    // its first step when the next lane, entered by that step, is at least 1 / laneWeight as long as
    // the whole stride. Its key then carries the next lane's length less one, so it competes as that
    // lane but loses to a lane as long that can be flown without the step.
    void laneChange(int d, std::vector<int>& cand, StrideKey& key) {
        if (m_variant.laneWeight <= 0 || m_laneAxis < 0 || d % 2 == m_laneAxis || cand.size() < 2)
            return;
        const int step = cand.front();
        m_visited[step] = 1;
        int next = 0;
        for (int ld : {m_laneAxis, m_laneAxis + 2}) {
            if (blocked(m_g, m_visited, step, ld))
                continue;
            growStride(m_g, m_visited, step, ld, m_look, true);
            next = std::max(next, static_cast<int>(m_look.size()) + 1);
        }
        m_visited[step] = 0;
        if (next >= 2 && next * m_variant.laneWeight >= key.length) {
            cand.resize(1);
            key.length = next - 1; // a lane along this axis as long as the next one is taken first
        }
    }

    // In a lane variant, strides along the lanes run to the area's limit, as lanes do.
    bool alongLanes(int d) const { return m_variant.laneWeight > 0 && m_laneAxis >= 0 && d % 2 == m_laneAxis; }

    // Heuristic (3): the longest stride available after taking `cells`.
    int nextStrideLength(const std::vector<int>& cells) {
        for (int c : cells)
            m_visited[c] = 1;
        const int end = cells.back();
        int longest = 0;
        for (int d = 0; d < 4; ++d) {
            if (blocked(m_g, m_visited, end, d))
                continue;
            growStride(m_g, m_visited, end, d, m_look);
            longest = std::max(longest, static_cast<int>(m_look.size()) + 1);
        }
        for (int c : cells)
            m_visited[c] = 0;
        return longest;
    }

    void visitNew(int c) {
        m_visited[c] = 1;
        m_path.cells.push_back(c);
        m_path.revisit.push_back(false);
        --m_remaining;
        if (!m_targets.empty() && m_targetMark[c] == m_targets.back().id) {
            --m_targets.back().remaining;
            while (!m_targets.empty() && m_targets.back().remaining <= 0)
                m_targets.pop_back();
        }
    }

    bool inTarget(int c) const { return m_targets.empty() || m_targetMark[c] == m_targets.back().id; }

    // Dead end: the shortest path over allowed moves, through visited cells, to the nearest unvisited
    // cell (of the part being visited first, if any), appended as transits (Zelinsky's distance
    // transform, computed by a breadth-first wave from the current cell).
    void leaveDeadEnd(int cur) {
        if (m_trace)
            ++m_trace->deadEnds;
        std::vector<int> p = m_search.pathToNearestStraightest(
            cur, arrivalDir(), [this](int c) { return !m_visited[c] && inTarget(c); }, [this](int c) { return m_visited[c] != 0; });
        int target;
        if (!p.empty()) {
            for (std::size_t k = 0; k + 1 < p.size(); ++k) {
                m_path.cells.push_back(p[k]);
                m_path.revisit.push_back(true);
            }
            target = p.back();
        } else {
            // No allowed move leads to the remaining cells: they lie in a part of the area the grid's
            // moves do not connect. Jump to the nearest one; the route stage plans that transit.
            target = nearestCell(m_g, cur, [this](int c) { return !m_visited[c]; });
            m_targets.clear();
            ++m_path.jumps;
        }
        visitNew(target);
        newCellsAdded(&target, 1);
        m_heading = -1;
        if (m_trace)
            m_trace->segmentEnds.push_back(m_g.visitCount() - m_remaining);
    }

    // Direction of the path's last move, or -1 (no move yet).
    int arrivalDir() const {
        const std::size_t n = m_path.cells.size();
        if (n < 2)
            return -1;
        const int a = m_path.cells[n - 2], b = m_path.cells[n - 1];
        for (int d = 0; d < 4; ++d)
            if (m_g.canMove(a, static_cast<Dir>(d)) && a + dirOffset(m_g, d) == b)
                return d;
        return -1;
    }

    // The partition rule. Cells just visited can only split the free region if their free neighbours
    // (the seeds) are not already connected around them; that local test settles almost every stride.
    // Otherwise one breadth-first wave per group of seeds grows in turn, one cell at a time; waves that
    // meet merge. A wave that runs out of cells has closed off a part; the smallest closed part is
    // visited first. When a single wave is left it grows on only until it is larger than that part, so
    // the search costs about the size of the parts closed off (times the number of groups), not the
    // size of the whole area.
    void newCellsAdded(const int* cells, std::size_t count) {
        if (m_remaining <= 0)
            return;
        const std::uint32_t s = ++m_seedStamp;
        m_seeds.clear();
        for (std::size_t k = 0; k < count; ++k) {
            const int c = cells[k];
            for (int d = 0; d < 4; ++d) {
                if (blocked(m_g, m_visited, c, d))
                    continue;
                const int n = c + dirOffset(m_g, d);
                if (m_seedMark[n] == s)
                    continue;
                m_seedMark[n] = s;
                m_seedSlot[n] = static_cast<int>(m_seeds.size());
                m_seeds.push_back(n);
            }
        }
        if (m_seeds.size() <= 1)
            return;
        m_uf.reset(static_cast<int>(m_seeds.size()));
        for (std::size_t k = 0; k < m_seeds.size(); ++k) {
            const int a = m_seeds[k];
            for (int d = 0; d < 4; ++d) {
                if (!m_g.canMove(a, static_cast<Dir>(d)))
                    continue;
                const int b = a + dirOffset(m_g, d);
                if (m_seedMark[b] == s)
                    m_uf.unite(static_cast<int>(k), m_seedSlot[b]);
            }
        }
        // Two free neighbours of a new cell are also connected through the free corner between them.
        for (std::size_t k = 0; k < count; ++k) {
            const int c = cells[k];
            for (int d1 = 0; d1 < 4; ++d1) {
                const int d2 = (d1 + 1) % 4;
                if (blocked(m_g, m_visited, c, d1) || blocked(m_g, m_visited, c, d2))
                    continue;
                const int a = c + dirOffset(m_g, d1), b = c + dirOffset(m_g, d2);
                if (blocked(m_g, m_visited, a, d2))
                    continue;
                const int corner = a + dirOffset(m_g, d2);
                if (blocked(m_g, m_visited, corner, (d1 + 2) % 4))
                    continue;
                m_uf.unite(m_seedSlot[a], m_seedSlot[b]);
            }
        }
        // Seed groups.
        m_groupOfRoot.assign(m_seeds.size(), -1);
        int groups = 0;
        for (std::size_t k = 0; k < m_seeds.size(); ++k) {
            const int r = m_uf.find(static_cast<int>(k));
            if (m_groupOfRoot[r] < 0)
                m_groupOfRoot[r] = groups++;
        }
        if (groups <= 1)
            return;
        searchParts(groups);
    }

    // The waves of searchParts: one per seed group, grown in turn; waves that meet merge
    // (m_waveUf).
    struct ClosedPart {
        int root;
        int size;
    };

    void searchParts(int groups) {
        if (m_trace)
            ++m_trace->partitionSearches;
        startWaves(groups);
        std::vector<ClosedPart> closed;
        while (m_live >= 2) {
            for (int gi = 0; gi < groups && m_live >= 2; ++gi) {
                if (m_heads[gi] == m_queues[gi].size())
                    continue;
                const int r = expandWave(gi);
                if (m_pending[r] == 0) {
                    closed.push_back({r, m_size[r]});
                    --m_live;
                }
            }
        }
        if (closed.empty())
            return;
        growLastOpen(groups, closed);
        targetSmallest(groups, closed);
    }

    // One wave per seed group, its seeds queued.
    void startWaves(int groups) {
        m_waveStamp = ++m_partStamp;
        if (m_queues.size() < static_cast<std::size_t>(groups))
            m_queues.resize(static_cast<std::size_t>(groups));
        for (int gi = 0; gi < groups; ++gi)
            m_queues[gi].clear();
        m_heads.assign(groups, 0);
        m_size.assign(groups, 0);
        m_pending.assign(groups, 0);
        m_waveUf.reset(groups);
        for (std::size_t k = 0; k < m_seeds.size(); ++k) {
            const int gi = m_groupOfRoot[m_uf.find(static_cast<int>(k))];
            const int c = m_seeds[k];
            m_partMark[c] = m_waveStamp;
            m_partGroup[c] = gi;
            m_queues[gi].push_back(c);
            ++m_size[gi];
            ++m_pending[gi];
        }
        m_live = groups;
    }

    // Takes the next cell of group gi's queue and grows its wave by that cell's free neighbours,
    // merging waves that meet. Returns the wave's root.
    int expandWave(int gi) {
        const int x = m_queues[gi][m_heads[gi]++];
        int r = m_waveUf.find(gi);
        --m_pending[r];
        for (int d = 0; d < 4; ++d) {
            if (blocked(m_g, m_visited, x, d))
                continue;
            const int n = x + dirOffset(m_g, d);
            if (m_partMark[n] != m_waveStamp) {
                m_partMark[n] = m_waveStamp;
                m_partGroup[n] = gi;
                m_queues[gi].push_back(n);
                ++m_size[r];
                ++m_pending[r];
            } else {
                const int h = m_waveUf.find(m_partGroup[n]);
                if (h != r) {
                    const int sz = m_size[r] + m_size[h], pend = m_pending[r] + m_pending[h];
                    r = m_waveUf.unite(r, h);
                    m_size[r] = sz;
                    m_pending[r] = pend;
                    --m_live;
                }
            }
        }
        return r;
    }

    // A wave made of several seed groups grows several cells per round, so the part it explores can
    // close first and still be larger than the last open part. Grow the last open wave until it has
    // more cells than the smallest closed part (it is then larger) or closes itself.
    void growLastOpen(int groups, std::vector<ClosedPart>& closed) {
        int minClosed = closed.front().size;
        for (const auto& c : closed)
            minClosed = std::min(minClosed, c.size);
        int open = -1;
        for (int gi = 0; gi < groups && open < 0; ++gi) {
            const int r = m_waveUf.find(gi);
            if (m_pending[r] > 0)
                open = r;
        }
        while (open >= 0 && m_pending[open] > 0 && m_size[open] <= minClosed) {
            for (int gi = 0; gi < groups; ++gi)
                if (m_waveUf.find(gi) == open && m_heads[gi] < m_queues[gi].size())
                    expandWave(gi);
        }
        if (open >= 0 && m_pending[open] == 0)
            closed.push_back({open, m_size[open]});
    }

    // The smallest part becomes the target: its cells are marked so that strides and dead-end paths
    // stay in it until it is done.
    void targetSmallest(int groups, const std::vector<ClosedPart>& closed) {
        const ClosedPart* smallest = &closed.front();
        for (const auto& c : closed)
            if (c.size < smallest->size)
                smallest = &c;
        const std::uint32_t id = ++m_targetId;
        for (int gi = 0; gi < groups; ++gi)
            if (m_waveUf.find(gi) == smallest->root)
                for (int c : m_queues[gi])
                    m_targetMark[c] = id;
        if (!m_targets.empty())
            m_targets.back().remaining -= smallest->size;
        m_targets.push_back({id, smallest->size});
        if (m_trace) {
            StrideTrace::Partition p;
            p.photographed = m_g.visitCount() - m_remaining;
            for (const auto& c : closed)
                p.partSizes.push_back(c.size);
            p.chosenSize = smallest->size;
            m_trace->partitions.push_back(std::move(p));
        }
    }

    const Grid& m_g;
    std::size_t m_n;
    std::vector<std::uint8_t> m_visited;
    GridSearch m_search;
    CellPath m_path;
    int m_remaining = 0;
    int m_heading = -1;
    std::vector<int> m_look;

    // Partition detection scratch.
    std::vector<std::uint32_t> m_seedMark;
    std::vector<int> m_seedSlot;
    std::uint32_t m_seedStamp = 0;
    std::vector<int> m_seeds;
    UnionFind m_uf;
    std::vector<int> m_groupOfRoot;
    std::vector<std::uint32_t> m_partMark;
    std::vector<int> m_partGroup;
    std::uint32_t m_partStamp = 0;
    std::vector<std::vector<int>> m_queues;
    std::vector<std::size_t> m_heads;
    std::vector<int> m_size, m_pending;
    UnionFind m_waveUf;
    std::uint32_t m_waveStamp = 0;
    int m_live = 0; // waves not closed nor merged

    // Parts to finish first, innermost last.
    struct Target {
        std::uint32_t id;
        int remaining;
    };
    std::vector<Target> m_targets;
    std::vector<std::uint32_t> m_targetMark;
    std::uint32_t m_targetId = 0;

    StrideTrace* m_trace;
    StrideVariant m_variant;
    int m_laneAxis = -1; // axis (0 east-west, 1 north-south) of the last stride of 3 or more cells
};

} // namespace


std::vector<StrideVariant> strideVariants(const Grid& g, int start) {
    std::vector<StrideVariant> v{{}, {kLaneWeight, -1, -1}};
    if (g.visitCount() > kAxesCellLimit)
        return v;
    for (int axis : {0, 1})
        v.push_back({kLaneWeight, axis, -1});
    if (start < 0 || g.visitCount() > kLeadInCellLimit)
        return v;
    // Lead-ins: to the area's four corners (the cells with the smallest and largest col + row and
    // col - row). Lead-ins to the ends of the start's row and column were tried too; on the sample areas
    // they saved 0.2 % of the turns for twice the plans.
    int corner[4] = {-1, -1, -1, -1};
    auto key = [&](int i, int k) { return (k & 1 ? -1 : 1) * g.col(i) + (k & 2 ? -1 : 1) * g.row(i); };
    for (int i = 0; i < g.cellCount(); ++i) {
        if (!g.needsVisit(i))
            continue;
        for (int k = 0; k < 4; ++k)
            if (corner[k] < 0 || key(i, k) < key(corner[k], k))
                corner[k] = i;
    }
    std::vector<int> targets(corner, corner + 4);
    std::sort(targets.begin(), targets.end());
    targets.erase(std::unique(targets.begin(), targets.end()), targets.end());
    for (int t : targets) {
        if (t == start)
            continue;
        for (int a : {-1, 0, 1})
            v.push_back({kLaneWeight, a, t});
    }
    return v;
}

Result<CellPath> planStrideVariant(const Grid& g, const CoverageRequest& req, const StrideVariant& variant,
                                   StrideTrace* trace) {
    auto start = resolveStart(g, req);
    if (!start)
        return start.error();
    StridePlanner planner(g, trace, variant);
    int first = *start;
    CellPath lead;
    if (variant.leadTo >= 0 && variant.leadTo != first) {
        GridSearch search(g);
        const std::vector<int> p =
            search.pathToNearestStraightest(first, -1, [&](int c) { return c == variant.leadTo; }, [](int) { return true; });
        if (!p.empty()) { // else the corner lies in another part: start where asked
            lead.cells.push_back(first);
            lead.revisit.push_back(true);
            for (std::size_t k = 0; k + 1 < p.size(); ++k) {
                lead.cells.push_back(p[k]);
                lead.revisit.push_back(true);
            }
            first = p.back();
        }
    }
    CellPath body = planner.run(first);
    if (!lead.cells.empty()) {
        lead.cells.insert(lead.cells.end(), body.cells.begin(), body.cells.end());
        lead.revisit.insert(lead.revisit.end(), body.revisit.begin(), body.revisit.end());
        lead.jumps = body.jumps;
        body = std::move(lead);
    }
    CellPath path = withTakeoffAndLanding(g, req, *start, std::move(body));
    cleanUpRevisits(g, path);
    return path;
}

Result<CellPath> planStride(const Grid& g, const CoverageRequest& req, StrideTrace* trace, const StrideChoice& choice) {
    std::optional<CellPath> best;
    MetricsOptions mo;
    mo.turnLowerBound = false;
    mo.time = choice.time;
    auto better = [&](const PathMetrics& m, const PathMetrics& kept) {
        if (choice.byTime) {
            if (!sameTime(m.estimatedTimeS, kept.estimatedTimeS))
                return sooner(m.estimatedTimeS, kept.estimatedTimeS);
            return m.turns < kept.turns;
        }
        return m.turns < kept.turns || (m.turns == kept.turns && m.pathLengthM < kept.pathLengthM);
    };
    // The variants in strideVariants' order: on a tie the paper's rules (the first) win.
    BestCandidate<PathMetrics, decltype(better)> keep(better);
    auto start = resolveStart(g, req);
    if (!start)
        return start.error();
    for (const StrideVariant& v : strideVariants(g, *start)) {
        if (stopRequested())
            return makeError(ErrorCode::Cancelled, "planning cancelled");
        StrideTrace t;
        auto p = planStrideVariant(g, req, v, trace ? &t : nullptr);
        if (!p)
            return p.error();
        const PathMetrics m = computeMetrics(g, *p, mo);
        if (keep.offer(m)) {
            best = std::move(*p);
            if (trace)
                *trace = std::move(t);
        }
    }
    if (trace) // the best path so far is held while the next variant is planned
        trace->scratchBytes += best->cells.capacity() * sizeof(int) + best->revisit.capacity() / 8;
    return std::move(*best);
}

} // namespace pf::plan
