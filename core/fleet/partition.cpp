#include "core/fleet/partition.h"

#include "core/geo/polygon_ops.h"
#include "core/grid/grid.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <numeric>
#include <queue>
#include <set>
#include <tuple>

namespace pf::fleet {

namespace {

constexpr int kDx[4] = {1, 0, -1, 0};
constexpr int kDy[4] = {0, 1, 0, -1};

// Integer targets summing to `total`, proportional to weights (largest remainder).
std::vector<int> largestRemainder(const std::vector<double>& w, int total) {
    const double sum = std::accumulate(w.begin(), w.end(), 0.0);
    std::vector<int> t(w.size());
    std::vector<std::pair<double, std::size_t>> rem;
    int used = 0;
    for (std::size_t k = 0; k < w.size(); ++k) {
        const double exact = total * w[k] / sum;
        t[k] = static_cast<int>(std::floor(exact));
        used += t[k];
        rem.emplace_back(exact - t[k], k);
    }
    std::stable_sort(rem.begin(), rem.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    for (std::size_t i = 0; used < total; ++i, ++used)
        ++t[rem[i % rem.size()].second];
    return t;
}

// BFS distances from `src` through cells accepted by `inSet`; -1 where unreached.
template <class Pred> std::vector<int> bfs(const BaseGrid& g, const std::vector<int>& src, Pred inSet) {
    std::vector<int> dist(static_cast<std::size_t>(g.cellCount()), -1);
    std::deque<int> q;
    for (int s : src) {
        dist[static_cast<std::size_t>(s)] = 0;
        q.push_back(s);
    }
    while (!q.empty()) {
        const int c = q.front();
        q.pop_front();
        for (int d = 0; d < 4; ++d) {
            if (!g.canMove(c, d))
                continue;
            const int n = g.neighbour(c, d);
            if (n < 0 || dist[static_cast<std::size_t>(n)] >= 0 || !inSet(n))
                continue;
            dist[static_cast<std::size_t>(n)] = dist[static_cast<std::size_t>(c)] + 1;
            q.push_back(n);
        }
    }
    return dist;
}

// The working state shared by growth, redistribution and balancing.
class Assignment {
public:
    Assignment(const BaseGrid& g, int aircraft) : m_g(g), m_owner(static_cast<std::size_t>(g.cellCount()), -1),
                                                   m_size(static_cast<std::size_t>(aircraft), 0) {}
    Assignment(const BaseGrid& g, const Partition& p) : m_g(g), m_owner(p.owner), m_size(p.cells.size(), 0) {
        for (std::size_t k = 0; k < p.cells.size(); ++k)
            m_size[k] = static_cast<int>(p.cells[k].size());
    }

    int owner(int c) const { return m_owner[static_cast<std::size_t>(c)]; }
    int size(int k) const { return m_size[static_cast<std::size_t>(k)]; }
    int aircraft() const { return static_cast<int>(m_size.size()); }
    void assign(int c, int k) {
        const int old = owner(c);
        if (old >= 0)
            --m_size[static_cast<std::size_t>(old)];
        m_owner[static_cast<std::size_t>(c)] = k;
        if (k >= 0)
            ++m_size[static_cast<std::size_t>(k)];
    }

    // Neighbours of c reachable by a move that belong to subarea k.
    int neighboursIn(int c, int k) const {
        int n = 0;
        for (int d = 0; d < 4; ++d)
            if (m_g.canMove(c, d) && owner(m_g.neighbour(c, d)) == k)
                ++n;
        return n;
    }

    // True if removing c from its subarea leaves the rest in one piece.
    bool removable(int c) const {
        const int k = owner(c);
        if (k < 0 || size(k) <= 1)
            return false;
        // Fast local test: if the subarea's move-neighbours of c are linked to each other around
        // the 3x3 ring (consecutive ring cells, allowed moves), any path through c can detour.
        static constexpr int ringDx[8] = {1, 1, 0, -1, -1, -1, 0, 1};
        static constexpr int ringDy[8] = {0, 1, 1, 1, 0, -1, -1, -1};
        const int cx = c % m_g.cols, cy = c / m_g.cols;
        int ring[8];
        for (int r = 0; r < 8; ++r) {
            const int x = cx + ringDx[r], y = cy + ringDy[r];
            ring[r] = (x >= 0 && y >= 0 && x < m_g.cols && y < m_g.rows) ? y * m_g.cols + x : -1;
            if (ring[r] >= 0 && owner(ring[r]) != k)
                ring[r] = -1;
        }
        // Label ring runs: consecutive owned ring cells joined by an allowed move.
        int label[8];
        int next = 0;
        for (int r = 0; r < 8; ++r)
            label[r] = ring[r] >= 0 ? next++ : -1;
        auto linked = [&](int a, int b) {
            if (ring[a] < 0 || ring[b] < 0)
                return false;
            for (int d = 0; d < 4; ++d)
                if (m_g.neighbour(ring[a], d) == ring[b])
                    return m_g.canMove(ring[a], d);
            return false;
        };
        for (int pass = 0; pass < 2; ++pass)
            for (int r = 0; r < 8; ++r) {
                const int s = (r + 1) % 8;
                if (linked(r, s)) {
                    const int lo = std::min(label[r], label[s]);
                    label[r] = label[s] = lo;
                }
            }
        int common = -2;
        bool local = true;
        for (int d = 0; d < 4; ++d) {
            if (!m_g.canMove(c, d))
                continue;
            const int n = m_g.neighbour(c, d);
            if (owner(n) != k)
                continue;
            const int r = 2 * d; // E, N, W, S sit at ring positions 0, 2, 4, 6
            if (common == -2)
                common = label[r];
            else if (label[r] != common)
                local = false;
        }
        if (common == -2)
            return true; // c has no move-neighbour in its subarea: it is already apart
        if (local)
            return true;
        // Exact test: BFS through the subarea without c.
        int start = -1;
        for (int d = 0; d < 4 && start < 0; ++d)
            if (m_g.canMove(c, d) && owner(m_g.neighbour(c, d)) == k)
                start = m_g.neighbour(c, d);
        const auto dist = bfs(m_g, {start}, [&](int n) { return n != c && owner(n) == k; });
        int reached = 0;
        for (std::size_t i = 0; i < dist.size(); ++i)
            if (dist[i] >= 0)
                ++reached;
        return reached == size(k) - 1;
    }

    // Hands up to `count` cells of `from` to `to`, one at a time, each time the best boundary cell:
    // adjacent to `to` by a move, removable from `from` without splitting it, maximising neighbours
    // in `to` minus neighbours in `from` (keeps both compact). Only the shared boundary is scanned
    // per pick, so large grids stay fast. Returns the cells moved, in order.
    // Sweep mode orders the cells by how far they lie towards `to` (along the line between the two
    // subareas' centroids) instead: the boundary then moves as a straight front, which suits
    // planners that fly long straight strides.
    std::vector<int> transfer(int from, int to, int count, bool sweep = false) {
        std::vector<int> moved;
        if (count <= 0)
            return moved;
        geo::Vec2 dir(0, 0);
        if (sweep) {
            geo::Vec2 cf(0, 0), ct(0, 0);
            int nf = 0, nt = 0;
            for (int c = 0; c < m_g.cellCount(); ++c) {
                const geo::Vec2 xy(c % m_g.cols, c / m_g.cols);
                if (owner(c) == from) {
                    cf += xy;
                    ++nf;
                } else if (owner(c) == to) {
                    ct += xy;
                    ++nt;
                }
            }
            if (nf > 0 && nt > 0)
                dir = ct / nt - cf / nf;
        }
        std::vector<int> cand;
        std::vector<std::uint8_t> inCand(static_cast<std::size_t>(m_g.cellCount()), 0);
        auto consider = [&](int c) {
            if (c >= 0 && owner(c) == from && !inCand[static_cast<std::size_t>(c)] && neighboursIn(c, to) > 0) {
                inCand[static_cast<std::size_t>(c)] = 1;
                cand.push_back(c);
            }
        };
        for (int c = 0; c < m_g.cellCount(); ++c)
            consider(c);
        while (static_cast<int>(moved.size()) < count) {
            // Drop stale candidates, score the rest, try them best first.
            std::vector<std::pair<double, int>> scored;
            std::vector<int> keep;
            for (int c : cand) {
                if (owner(c) != from || neighboursIn(c, to) == 0) {
                    inCand[static_cast<std::size_t>(c)] = 0;
                    continue;
                }
                keep.push_back(c);
                const double compact = 2 * neighboursIn(c, to) - neighboursIn(c, from);
                const double along = dir.x() * (c % m_g.cols) + dir.y() * (c / m_g.cols);
                scored.emplace_back(sweep ? -(along + 1e-3 * compact) : -compact, c);
            }
            cand.swap(keep);
            std::sort(scored.begin(), scored.end());
            int pick = -1;
            for (const auto& [negScore, c] : scored)
                if (removable(c)) {
                    pick = c;
                    break;
                }
            if (pick < 0)
                break;
            assign(pick, to);
            moved.push_back(pick);
            for (int d = 0; d < 4; ++d)
                if (m_g.canMove(pick, d))
                    consider(m_g.neighbour(pick, d));
        }
        return moved;
    }

    // Shared move-edges between subareas: adj[a][b].
    std::vector<std::vector<int>> adjacency() const {
        std::vector<std::vector<int>> adj(m_size.size(), std::vector<int>(m_size.size(), 0));
        for (int c = 0; c < m_g.cellCount(); ++c) {
            const int a = owner(c);
            if (a < 0)
                continue;
            for (int d = 0; d < 4; ++d) {
                if (!m_g.canMove(c, d))
                    continue;
                const int b = owner(m_g.neighbour(c, d));
                if (b >= 0 && b != a)
                    ++adj[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)];
            }
        }
        return adj;
    }

    Partition toPartition(const std::vector<int>& targets) const {
        Partition p;
        p.owner = m_owner;
        p.targets = targets;
        p.cells.assign(m_size.size(), {});
        for (int c = 0; c < m_g.cellCount(); ++c)
            if (owner(c) >= 0)
                p.cells[static_cast<std::size_t>(owner(c))].push_back(c);
        for (const auto& cells : p.cells)
            if (!cells.empty() && !isConnected(m_g, cells))
                ++p.disconnectedSubareas;
        return p;
    }

private:
    const BaseGrid& m_g;
    std::vector<int> m_owner;
    std::vector<int> m_size;
};

// Grows one subarea per aircraft in `fleet` over the connected piece `piece`, then places the
// leftovers and redistributes to `targets` (indexed by aircraft).
void partitionPiece(const BaseGrid& g, const std::vector<int>& piece, const std::vector<int>& fleet,
                    const std::vector<int>& targets, Assignment& as) {
    std::vector<std::uint8_t> inPiece(static_cast<std::size_t>(g.cellCount()), 0);
    for (int c : piece)
        inPiece[static_cast<std::size_t>(c)] = 1;
    auto isFree = [&](int c) { return inPiece[static_cast<std::size_t>(c)] && as.owner(c) < 0; };

    // Sweep start: the far end of a double BFS sweep over the piece.
    auto farthest = [&](const std::vector<int>& dist) {
        int best = -1;
        for (int c : piece)
            if (dist[static_cast<std::size_t>(c)] >= 0 &&
                (best < 0 || dist[static_cast<std::size_t>(c)] > dist[static_cast<std::size_t>(best)]))
                best = c;
        return best;
    };
    const int sweepStart = farthest(bfs(g, {piece.front()}, isFree));
    const auto fromStart = bfs(g, {sweepStart}, [&](int c) { return inPiece[static_cast<std::size_t>(c)] != 0; });

    for (int k : fleet) {
        const int target = targets[static_cast<std::size_t>(k)];
        // Seed: the free cell nearest the sweep's start (ties: lowest index).
        int seed = -1;
        for (int c : piece)
            if (isFree(c) && (seed < 0 || fromStart[static_cast<std::size_t>(c)] < fromStart[static_cast<std::size_t>(seed)]))
                seed = c;
        if (seed < 0)
            break;
        // Priority: most neighbours in the subarea, most walls, nearest the sweep start, lowest index.
        using Key = std::tuple<int, int, int, int>;
        std::priority_queue<Key> frontier;
        auto walls = [&](int c) {
            int w = 0;
            for (int d = 0; d < 4; ++d)
                if (!g.canMove(c, d) || !isFree(g.neighbour(c, d)))
                    ++w;
            return w;
        };
        auto push = [&](int c) {
            frontier.emplace(as.neighboursIn(c, k), walls(c), -fromStart[static_cast<std::size_t>(c)], -c);
        };
        as.assign(seed, k);
        int grown = 1;
        for (int d = 0; d < 4; ++d)
            if (g.canMove(seed, d) && isFree(g.neighbour(seed, d)))
                push(g.neighbour(seed, d));
        while (grown < target && !frontier.empty()) {
            const auto [nIn, nWalls, negDist, negC] = frontier.top();
            frontier.pop();
            const int c = -negC;
            if (!isFree(c) || nIn != as.neighboursIn(c, k) || nWalls != walls(c))
                continue; // stale entry: a fresher one is queued
            as.assign(c, k);
            ++grown;
            for (int d = 0; d < 4; ++d) {
                if (!g.canMove(c, d))
                    continue;
                const int n = g.neighbour(c, d);
                if (isFree(n))
                    push(n); // its counts changed: queue it afresh (walls count direct neighbours only)
            }
        }
    }

    // Leftovers (paper fig. 9): each free piece joins the adjacent subarea furthest below target.
    for (int c : piece) {
        if (!isFree(c))
            continue;
        const auto dist = bfs(g, {c}, isFree);
        std::vector<int> left;
        for (int x : piece)
            if (dist[static_cast<std::size_t>(x)] >= 0)
                left.push_back(x);
        int bestK = -1;
        double bestDeficit = -std::numeric_limits<double>::infinity();
        int bestShared = -1;
        std::vector<int> shared(static_cast<std::size_t>(as.aircraft()), 0);
        for (int x : left)
            for (int d = 0; d < 4; ++d)
                if (g.canMove(x, d)) {
                    const int o = as.owner(g.neighbour(x, d));
                    if (o >= 0)
                        ++shared[static_cast<std::size_t>(o)];
                }
        for (int k : fleet) {
            if (shared[static_cast<std::size_t>(k)] == 0)
                continue;
            const double deficit = targets[static_cast<std::size_t>(k)] - as.size(k);
            if (deficit > bestDeficit || (deficit == bestDeficit && shared[static_cast<std::size_t>(k)] > bestShared)) {
                bestK = k;
                bestDeficit = deficit;
                bestShared = shared[static_cast<std::size_t>(k)];
            }
        }
        if (bestK < 0)
            bestK = fleet.front(); // nothing grown here (cannot happen with a non-empty fleet)
        for (int x : left)
            as.assign(x, bestK);
    }

    // Redistribution to the targets (paper fig. 9), along chains of adjacent subareas.
    std::set<std::pair<int, int>> blocked;
    const int maxMoves = 4 * static_cast<int>(piece.size()) + 16;
    for (int moves = 0, rounds = 0; moves < maxMoves && rounds < maxMoves; ++rounds) {
        int over = -1;
        for (int k : fleet)
            if (as.size(k) > targets[static_cast<std::size_t>(k)] &&
                (over < 0 || as.size(k) - targets[static_cast<std::size_t>(k)] >
                                 as.size(over) - targets[static_cast<std::size_t>(over)]) &&
                !blocked.count({k, -1}))
                over = k;
        if (over < 0)
            break;
        const auto adj = as.adjacency();
        // BFS over subareas from `over` to the nearest one below target, avoiding blocked edges.
        std::vector<int> prev(static_cast<std::size_t>(as.aircraft()), -2);
        std::deque<int> q{over};
        prev[static_cast<std::size_t>(over)] = -1;
        int under = -1;
        while (!q.empty() && under < 0) {
            const int a = q.front();
            q.pop_front();
            for (int b : fleet) {
                if (prev[static_cast<std::size_t>(b)] != -2 || adj[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)] == 0 ||
                    blocked.count({a, b}))
                    continue;
                prev[static_cast<std::size_t>(b)] = a;
                if (as.size(b) < targets[static_cast<std::size_t>(b)]) {
                    under = b;
                    break;
                }
                q.push_back(b);
            }
        }
        if (under < 0) {
            blocked.insert({over, -1});
            continue;
        }
        // Move cells along each edge of the chain, from the receiving end backwards, so that the
        // subareas in between end up with as many cells as before.
        int amount = std::min(as.size(over) - targets[static_cast<std::size_t>(over)],
                              targets[static_cast<std::size_t>(under)] - as.size(under));
        bool stuck = false;
        for (int b = under; prev[static_cast<std::size_t>(b)] >= 0 && !stuck; b = prev[static_cast<std::size_t>(b)]) {
            const int a = prev[static_cast<std::size_t>(b)];
            const int done = static_cast<int>(as.transfer(a, b, amount).size());
            moves += done;
            if (done == 0) {
                blocked.insert({a, b});
                stuck = true;
            }
            amount = done;
        }
        if (!stuck)
            blocked.clear();
    }
}

} // namespace

// ---------------------------------------------------------------------------------------------
// BaseGrid

BaseGrid BaseGrid::fromGrid(const grid::Grid& g) {
    BaseGrid b;
    b.cols = g.cols();
    b.rows = g.rows();
    b.cellSize = g.cellSize();
    b.angleDeg = g.angleDeg();
    b.origin = g.origin();
    const auto n = static_cast<std::size_t>(g.cellCount());
    b.active.assign(n, 0);
    b.moves.assign(n, 0);
    b.touches.assign(n, 0);
    for (int i = 0; i < g.cellCount(); ++i) {
        const auto s = g.state(i);
        b.touches[static_cast<std::size_t>(i)] = s != grid::CellState::Outside;
        b.active[static_cast<std::size_t>(i)] = g.needsVisit(i);
        std::uint8_t m = 0;
        for (int d = 0; d < 4; ++d)
            if (g.canMove(i, grid::kDirs[d]))
                m |= static_cast<std::uint8_t>(1u << d);
        b.moves[static_cast<std::size_t>(i)] = m;
    }
    return b;
}

BaseGrid BaseGrid::fromMask(int cols, int rows, const std::vector<std::uint8_t>& mask, double cellSize,
                            geo::Vec2 origin) {
    BaseGrid b;
    b.cols = cols;
    b.rows = rows;
    b.cellSize = cellSize;
    b.origin = origin;
    const auto n = static_cast<std::size_t>(cols * rows);
    b.active.assign(n, 0);
    b.moves.assign(n, 0);
    for (std::size_t i = 0; i < n && i < mask.size(); ++i)
        b.active[i] = mask[i] != 0;
    b.touches = b.active;
    for (int i = 0; i < cols * rows; ++i) {
        if (!b.active[static_cast<std::size_t>(i)])
            continue;
        for (int d = 0; d < 4; ++d) {
            const int nb = b.neighbour(i, d);
            if (nb >= 0 && b.active[static_cast<std::size_t>(nb)])
                b.moves[static_cast<std::size_t>(i)] |= static_cast<std::uint8_t>(1u << d);
        }
    }
    return b;
}

int BaseGrid::neighbour(int i, int d) const {
    const int x = i % cols + kDx[d], y = i / cols + kDy[d];
    if (x < 0 || y < 0 || x >= cols || y >= rows)
        return -1;
    return y * cols + x;
}

geo::Vec2 BaseGrid::cellCenter(int i) const {
    const double a = angleDeg * M_PI / 180.0;
    const geo::Vec2 u(std::cos(a), std::sin(a)), v(-std::sin(a), std::cos(a));
    return origin + ((i % cols) + 0.5) * cellSize * u + ((i / cols) + 0.5) * cellSize * v;
}

geo::Ring BaseGrid::cellSquare(int i) const {
    const double a = angleDeg * M_PI / 180.0;
    const geo::Vec2 u(std::cos(a), std::sin(a)), v(-std::sin(a), std::cos(a));
    const geo::Vec2 p = origin + (i % cols) * cellSize * u + (i / cols) * cellSize * v;
    return {p, p + cellSize * u, p + cellSize * (u + v), p + cellSize * v};
}

// ---------------------------------------------------------------------------------------------

bool isConnected(const BaseGrid& g, const std::vector<int>& cells) {
    if (cells.empty())
        return false;
    std::vector<std::uint8_t> in(static_cast<std::size_t>(g.cellCount()), 0);
    for (int c : cells)
        in[static_cast<std::size_t>(c)] = 1;
    const auto dist = bfs(g, {cells.front()}, [&](int c) { return in[static_cast<std::size_t>(c)] != 0; });
    return std::all_of(cells.begin(), cells.end(), [&](int c) { return dist[static_cast<std::size_t>(c)] >= 0; });
}

Result<Partition> partitionCells(const BaseGrid& g, const std::vector<double>& shares) {
    const int n = static_cast<int>(shares.size());
    if (n == 0)
        return makeError(ErrorCode::InvalidInput, "No aircraft to share the area between.");
    for (int k = 0; k < n; ++k)
        if (!(shares[static_cast<std::size_t>(k)] > 0) || !std::isfinite(shares[static_cast<std::size_t>(k)]))
            return makeError(ErrorCode::InvalidInput,
                             "The share of aircraft " + std::to_string(k + 1) + " is not a positive number.");
    if (g.active.size() != static_cast<std::size_t>(g.cellCount()) || g.moves.size() != g.active.size())
        return makeError(ErrorCode::Internal, "The base grid's cell arrays do not match its size.");
    std::vector<int> activeCells;
    for (int c = 0; c < g.cellCount(); ++c)
        if (g.active[static_cast<std::size_t>(c)])
            activeCells.push_back(c);
    if (static_cast<int>(activeCells.size()) < n)
        return makeError(ErrorCode::InvalidInput,
                         "The area has only " + std::to_string(activeCells.size()) +
                             (activeCells.size() == 1 ? " cell" : " cells") + " to photograph, fewer than the " +
                             std::to_string(n) + " aircraft: use fewer aircraft or a smaller footprint.");

    // Pieces of the area (separated by no-fly zones or gaps), largest first.
    std::vector<std::vector<int>> pieces;
    {
        std::vector<std::uint8_t> seen(static_cast<std::size_t>(g.cellCount()), 0);
        for (int c : activeCells) {
            if (seen[static_cast<std::size_t>(c)])
                continue;
            const auto dist = bfs(g, {c}, [&](int x) { return g.active[static_cast<std::size_t>(x)] != 0; });
            std::vector<int> piece;
            for (int x : activeCells)
                if (dist[static_cast<std::size_t>(x)] >= 0) {
                    piece.push_back(x);
                    seen[static_cast<std::size_t>(x)] = 1;
                }
            pieces.push_back(std::move(piece));
        }
        std::stable_sort(pieces.begin(), pieces.end(), [](const auto& a, const auto& b) { return a.size() > b.size(); });
    }

    const double sumShares = std::accumulate(shares.begin(), shares.end(), 0.0);
    const double total = static_cast<double>(activeCells.size());
    // Aircraft to pieces: the strongest aircraft first, each to the piece with the most cells not yet
    // claimed by the shares already given to it.
    std::vector<int> order(static_cast<std::size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return shares[static_cast<std::size_t>(a)] > shares[static_cast<std::size_t>(b)]; });
    std::vector<std::vector<int>> fleetOf(pieces.size());
    std::vector<double> claimed(pieces.size(), 0.0);
    for (int k : order) {
        std::size_t best = 0;
        double bestRest = -std::numeric_limits<double>::infinity();
        for (std::size_t p = 0; p < pieces.size(); ++p) {
            if (pieces[p].size() < fleetOf[p].size() + 1)
                continue;
            const double rest = static_cast<double>(pieces[p].size()) - claimed[p];
            if (rest > bestRest) {
                bestRest = rest;
                best = p;
            }
        }
        fleetOf[best].push_back(k);
        claimed[best] += total * shares[static_cast<std::size_t>(k)] / sumShares;
    }

    Assignment as(g, n);
    std::vector<int> targets(static_cast<std::size_t>(n), 0);
    for (std::size_t p = 0; p < pieces.size(); ++p) {
        if (fleetOf[p].empty())
            continue;
        std::sort(fleetOf[p].begin(), fleetOf[p].end());
        std::vector<double> w;
        for (int k : fleetOf[p])
            w.push_back(shares[static_cast<std::size_t>(k)]);
        const auto t = largestRemainder(w, static_cast<int>(pieces[p].size()));
        for (std::size_t i = 0; i < fleetOf[p].size(); ++i)
            targets[static_cast<std::size_t>(fleetOf[p][i])] = t[i];
        partitionPiece(g, pieces[p], fleetOf[p], targets, as);
    }
    // Pieces without an aircraft of their own go, whole, to the aircraft whose cells are nearest.
    for (std::size_t p = 0; p < pieces.size(); ++p) {
        if (!fleetOf[p].empty())
            continue;
        int bestK = 0;
        double bestD = std::numeric_limits<double>::infinity();
        const geo::Vec2 c0 = g.cellCenter(pieces[p].front());
        for (int c : activeCells) {
            const int k = as.owner(c);
            if (k < 0)
                continue;
            const double d = (g.cellCenter(c) - c0).squaredNorm();
            if (d < bestD) {
                bestD = d;
                bestK = k;
            }
        }
        for (int c : pieces[p])
            as.assign(c, bestK);
        targets[static_cast<std::size_t>(bestK)] += static_cast<int>(pieces[p].size());
    }
    return as.toPartition(targets);
}

Result<BalanceReport> balanceByTime(const BaseGrid& g, Partition& p, const TimeEstimator& estimate,
                                    const BalanceOptions& opt) {
    const int n = static_cast<int>(p.cells.size());
    if (n == 0)
        return makeError(ErrorCode::InvalidInput, "No subareas to balance.");
    if (!estimate)
        return makeError(ErrorCode::InvalidInput, "No flight time estimator to balance the subareas with.");
    BalanceReport rep;
    Assignment as(g, p);
    std::vector<double> times(static_cast<std::size_t>(n), 0.0);
    auto cellsOf = [&](int k) {
        std::vector<int> cells;
        for (int c = 0; c < g.cellCount(); ++c)
            if (as.owner(c) == k)
                cells.push_back(c);
        return cells;
    };
    auto est = [&](int k) -> Result<double> {
        ++rep.estimatorCalls;
        auto t = estimate(k, cellsOf(k));
        if (!t)
            return t.error();
        if (!std::isfinite(*t) || *t < 0)
            return makeError(ErrorCode::Internal,
                             "The flight time estimate of aircraft " + std::to_string(k + 1) + " is not a valid duration.");
        return *t;
    };
    for (int k = 0; k < n; ++k) {
        if (p.cells[static_cast<std::size_t>(k)].empty())
            continue;
        auto t = est(k);
        if (!t)
            return t.error();
        times[static_cast<std::size_t>(k)] = *t;
    }
    auto at = [&](int k) -> double& { return times[static_cast<std::size_t>(k)]; };
    auto makespan = [](const std::vector<double>& t) { return *std::max_element(t.begin(), t.end()); };
    const std::vector<int> targets = p.targets;
    std::vector<int> bestOwner = p.owner;
    std::vector<double> bestTimes = times;
    int moved = 0, bestMoved = 0;
    const int maxEstimates = rep.estimatorCalls + opt.maxEstimates;

    // One trial: move cells along `chain` (each link hands `counts[i]` cells to the next), re-estimate
    // the subareas involved and undo. Returns the slowest re-estimated time (infinity if a link had
    // nothing to give) and the fresh times. Transfers are deterministic, so a trial can be replayed.
    struct Trial {
        std::vector<int> chain;
        std::vector<int> counts;
        bool sweep = false;
        double worst = std::numeric_limits<double>::infinity();
        std::vector<double> fresh;
    };
    auto apply = [&](const Trial& t, std::vector<std::pair<int, std::vector<int>>>& done) {
        for (std::size_t i = t.counts.size(); i-- > 0;) {
            auto cells = as.transfer(t.chain[i], t.chain[i + 1], t.counts[i], t.sweep);
            const bool empty = cells.empty();
            done.emplace_back(t.chain[i], std::move(cells));
            if (empty)
                return false;
        }
        return true;
    };
    auto undo = [&](std::vector<std::pair<int, std::vector<int>>>& done) {
        for (auto it = done.rbegin(); it != done.rend(); ++it)
            for (auto c = it->second.rbegin(); c != it->second.rend(); ++c)
                as.assign(*c, it->first);
    };
    auto evaluate = [&](Trial& t) -> Status {
        std::vector<std::pair<int, std::vector<int>>> done;
        if (apply(t, done)) {
            for (int k : t.chain) {
                auto e = est(k);
                if (!e) {
                    undo(done);
                    return e.error();
                }
                t.fresh.push_back(*e);
            }
            t.worst = *std::max_element(t.fresh.begin(), t.fresh.end());
        }
        undo(done);
        return {};
    };
    auto commit = [&](const Trial& t) {
        std::vector<std::pair<int, std::vector<int>>> done;
        apply(t, done);
        for (std::size_t i = 0; i < t.chain.size(); ++i)
            at(t.chain[i]) = t.fresh[i];
        for (const auto& d : done)
            moved += static_cast<int>(d.second.size());
    };

    int kicks = 0;
    std::pair<int, int> tabu{-1, -1};
    for (rep.rounds = 0; rep.rounds < opt.maxRounds && rep.estimatorCalls < maxEstimates; ++rep.rounds) {
        const double ideal = std::accumulate(times.begin(), times.end(), 0.0) / n;
        const int s = static_cast<int>(std::max_element(times.begin(), times.end()) - times.begin());
        const double ts = at(s);
        if (ts <= (1.0 + opt.tolerance) * ideal)
            break;
        const auto adj = as.adjacency();
        std::vector<int> neighbours;
        for (int k = 0; k < n; ++k)
            if (adj[static_cast<std::size_t>(s)][static_cast<std::size_t>(k)] > 0)
                neighbours.push_back(k);
        std::stable_sort(neighbours.begin(), neighbours.end(), [&](int a, int b) { return at(a) < at(b); });
        // How many cells close the gap between s and r, from their times per cell (damped).
        auto cellsFor = [&](int from, int to) {
            const double perFrom = at(from) / std::max(1, as.size(from));
            const double perTo = at(to) > 0 ? at(to) / std::max(1, as.size(to)) : perFrom;
            const int m = static_cast<int>(std::floor(opt.damping * (at(from) - at(to)) / (perFrom + perTo)));
            return std::clamp(m, 1, std::max(1, as.size(from) - 1));
        };
        // Step sizes to try: the linear estimate first, then larger ones (an aircraft whose own cells
        // are several base cells wide only changes its plan once a whole strip of them is handed
        // over), then smaller ones; at most half the giver.
        auto stepSizes = [](int m0, int giverSize) {
            std::vector<int> out;
            for (int m : {m0, 2 * m0, 4 * m0, 8 * m0, m0 / 2, m0 / 4, 1})
                if (m >= 1 && m <= giverSize / 2 && std::find(out.begin(), out.end(), m) == out.end())
                    out.push_back(m);
            return out;
        };
        // Direct moves to a faster neighbour: every step size, both cell orders; the best trial wins.
        // Planned times are not smooth in the cells given (a grid of larger cells may not change at
        // all, a protruding cell may cost a whole extra stride), hence the search.
        Trial best;
        // The best trial that makes the slowest subarea faster, whatever it does to the others: the
        // kick below takes it (a trial that changes nothing for s would only spend a kick).
        Trial kick;
        const auto consider = [&](const Trial& t) {
            if (t.worst < best.worst)
                best = t;
            if (!t.fresh.empty() && t.fresh.front() < ts - 1e-9 && t.worst < kick.worst)
                kick = t;
        };
        // A trial that brings both subareas within the tolerance is taken at once (saves estimates).
        const double goodEnough = (1.0 + opt.tolerance) * ideal;
        for (int r : neighbours) {
            if (at(r) >= ts)
                break;
            if (tabu == std::make_pair(s, r))
                continue;
            for (int m : stepSizes(cellsFor(s, r), as.size(s)))
                for (bool sweep : {false, true}) {
                    if (rep.estimatorCalls >= maxEstimates)
                        break;
                    if (best.worst <= goodEnough)
                        break;
                    Trial t{{s, r}, {m}, sweep, std::numeric_limits<double>::infinity(), {}};
                    if (auto st = evaluate(t); !st)
                        return st.error();
                    consider(t);
                }
        }
        // Otherwise through a neighbour: s gives to r, which passes as many on to its fastest other
        // neighbour.
        if (!(best.worst < ts - 1e-9))
            for (int r : neighbours) {
                int f = -1;
                for (int k = 0; k < n; ++k)
                    if (k != s && k != r && adj[static_cast<std::size_t>(r)][static_cast<std::size_t>(k)] > 0 &&
                        at(k) < ts && (f < 0 || at(k) < at(f)))
                        f = k;
                if (f < 0)
                    continue;
                for (int m : stepSizes(cellsFor(s, f), as.size(s))) {
                    if (rep.estimatorCalls >= maxEstimates)
                        break;
                    Trial t{{s, r, f}, {m, m}, true, std::numeric_limits<double>::infinity(), {}};
                    if (auto st = evaluate(t); !st)
                        return st.error();
                    consider(t);
                }
            }
        const bool accepted = best.worst < ts - 1e-9;
        if (accepted) {
            commit(best);
        } else if (kicks < opt.maxKicks && std::isfinite(kick.worst)) {
            // Stuck in a local minimum of a rough landscape: take the least bad move that relieves
            // the slowest subarea anyway (the best partition seen is kept), and forbid handing the
            // cells straight back next round.
            ++kicks;
            commit(kick);
            tabu = {kick.chain[1], kick.chain[0]};
            continue;
        }
        tabu = {-1, -1};
        if (!accepted)
            break; // no move found that makes the slowest subarea faster
        if (makespan(times) < makespan(bestTimes)) {
            bestTimes = times;
            for (int c = 0; c < g.cellCount(); ++c)
                bestOwner[static_cast<std::size_t>(c)] = as.owner(c);
            bestMoved = moved;
        }
    }

    Partition best;
    best.owner = bestOwner;
    best.targets = targets;
    best.cells.assign(static_cast<std::size_t>(n), {});
    for (int c = 0; c < g.cellCount(); ++c)
        if (bestOwner[static_cast<std::size_t>(c)] >= 0)
            best.cells[static_cast<std::size_t>(bestOwner[static_cast<std::size_t>(c)])].push_back(c);
    best.disconnectedSubareas = p.disconnectedSubareas;
    p = std::move(best);
    rep.times = bestTimes;
    rep.makespan = makespan(bestTimes);
    rep.ideal = std::accumulate(bestTimes.begin(), bestTimes.end(), 0.0) / n;
    rep.cellsMoved = bestMoved;
    return rep;
}

geo::MultiPolygon cellsPolygon(const BaseGrid& g, const std::vector<int>& cells, const geo::MultiPolygon& clipTo) {
    if (cells.empty())
        return {};
    // Runs of consecutive cells in a row become one rectangle: far fewer pieces for GEOS to unite.
    std::vector<int> sorted = cells;
    std::sort(sorted.begin(), sorted.end());
    geo::MultiPolygon rects;
    for (std::size_t i = 0; i < sorted.size();) {
        std::size_t j = i;
        while (j + 1 < sorted.size() && sorted[j + 1] == sorted[j] + 1 && sorted[j + 1] / g.cols == sorted[i] / g.cols)
            ++j;
        const auto a = g.cellSquare(sorted[i]);
        const auto b = g.cellSquare(sorted[j]);
        rects.push_back(geo::Polygon{{a[0], b[1], b[2], a[3]}, {}});
        i = j + 1;
    }
    auto merged = geo::unite(rects);
    if (clipTo.empty())
        return merged;
    geo::MultiPolygon out;
    for (const auto& clip : clipTo)
        for (auto& piece : geo::intersection(merged, clip))
            out.push_back(std::move(piece));
    return out;
}

std::vector<geo::MultiPolygon> subareaPolygons(const BaseGrid& g, const Partition& p, const geo::MultiPolygon& clipTo) {
    // Cells touching the area but not active (no flyable point) still hold some of the area: give
    // each to the nearest subarea (8-neighbour BFS from the assigned cells, then plain distance).
    std::vector<int> owner = p.owner;
    const bool haveTouches = g.touches.size() == static_cast<std::size_t>(g.cellCount());
    if (haveTouches) {
        std::deque<int> q;
        for (int c = 0; c < g.cellCount(); ++c)
            if (owner[static_cast<std::size_t>(c)] >= 0)
                q.push_back(c);
        while (!q.empty()) {
            const int c = q.front();
            q.pop_front();
            const int cx = c % g.cols, cy = c / g.cols;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int x = cx + dx, y = cy + dy;
                    if ((dx == 0 && dy == 0) || x < 0 || y < 0 || x >= g.cols || y >= g.rows)
                        continue;
                    const int nb = y * g.cols + x;
                    if (owner[static_cast<std::size_t>(nb)] >= 0 || !g.touches[static_cast<std::size_t>(nb)])
                        continue;
                    owner[static_cast<std::size_t>(nb)] = owner[static_cast<std::size_t>(c)];
                    q.push_back(nb);
                }
        }
        for (int c = 0; c < g.cellCount(); ++c) {
            if (!g.touches[static_cast<std::size_t>(c)] || owner[static_cast<std::size_t>(c)] >= 0)
                continue;
            double bestD = std::numeric_limits<double>::infinity();
            for (int x = 0; x < g.cellCount(); ++x)
                if (p.owner[static_cast<std::size_t>(x)] >= 0) {
                    const double d = (g.cellCenter(x) - g.cellCenter(c)).squaredNorm();
                    if (d < bestD) {
                        bestD = d;
                        owner[static_cast<std::size_t>(c)] = p.owner[static_cast<std::size_t>(x)];
                    }
                }
        }
    }
    std::vector<std::vector<int>> cells(p.cells.size());
    for (int c = 0; c < g.cellCount(); ++c)
        if (owner[static_cast<std::size_t>(c)] >= 0)
            cells[static_cast<std::size_t>(owner[static_cast<std::size_t>(c)])].push_back(c);
    std::vector<geo::MultiPolygon> out;
    for (const auto& cs : cells)
        out.push_back(cellsPolygon(g, cs, clipTo));
    return out;
}

} // namespace pf::fleet
