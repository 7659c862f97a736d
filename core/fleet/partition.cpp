// Partitioning the base grid's cells between aircraft: seeds, flood-fill growth, leftovers and
// redistribution to the capability targets.
#include "core/fleet/partition.h"

#include "core/fleet/cell_assignment.h"
#include "core/grid/grid.h"
#include "core/job_scope.h"

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

// The connected piece being partitioned: its cells, which cells belong to it, and the assignment
// its subareas are grown in.
struct PieceState {
    PieceState(const grid::Grid& grid, const std::vector<int>& pieceCells,
               CellAssignment& assignment)
        : g(grid), cells(pieceCells), inPiece(static_cast<std::size_t>(grid.cellCount()), 0),
          as(assignment) {
        for (int c : cells)
            inPiece[static_cast<std::size_t>(c)] = 1;
    }
    bool contains(int c) const { return inPiece[static_cast<std::size_t>(c)] != 0; }
    bool isFree(int c) const { return contains(c) && as.owner(c) < 0; }

    const grid::Grid& g;
    const std::vector<int>& cells;
    std::vector<std::uint8_t> inPiece;
    CellAssignment& as;
};

// The piece's cell furthest by `dist` (ties: the first in the piece); -1 if none is reached.
int farthestCell(const PieceState& piece, const std::vector<int>& dist) {
    int best = -1;
    for (int c : piece.cells)
        if (dist[static_cast<std::size_t>(c)] >= 0 &&
            (best < 0 || dist[static_cast<std::size_t>(c)] > dist[static_cast<std::size_t>(best)]))
            best = c;
    return best;
}

// Move counts over the piece from the sweep's start, the far end of a double BFS sweep: the
// subareas are seeded and grown in this order.
std::vector<int> sweepDistances(const PieceState& piece) {
    const auto isFree = [&](int c) { return piece.isFree(c); };
    const int sweepStart =
        farthestCell(piece, moveDistances(piece.g, {piece.cells.front()}, isFree));
    return moveDistances(piece.g, {sweepStart}, [&](int c) { return piece.contains(c); });
}

// The free cell nearest the sweep's start (ties: lowest index); -1 when none is left.
int seedCell(const PieceState& piece, const std::vector<int>& fromStart) {
    int seed = -1;
    for (int c : piece.cells)
        if (piece.isFree(c) && (seed < 0 || fromStart[static_cast<std::size_t>(c)] <
                                                fromStart[static_cast<std::size_t>(seed)]))
            seed = c;
    return seed;
}

// Sides of c that are walls to the growth: no move that way, or no free cell behind it.
int walls(const PieceState& piece, int c) {
    int w = 0;
    for (int d = 0; d < 4; ++d)
        if (!piece.g.canMove(c, grid::kDirs[d]) ||
            !piece.isFree(piece.g.neighbour(c, grid::kDirs[d])))
            ++w;
    return w;
}

// Grows aircraft k's subarea from a seed to `target` cells, the most enclosed free cell first.
// False when no free cell is left to seed it.
bool growSubarea(PieceState& piece, int k, int target, const std::vector<int>& fromStart) {
    const grid::Grid& g = piece.g;
    const int seed = seedCell(piece, fromStart);
    if (seed < 0)
        return false;
    // Priority: most neighbours in the subarea, most walls, nearest the sweep start, lowest index.
    using Key = std::tuple<int, int, int, int>;
    std::priority_queue<Key> frontier;
    auto push = [&](int c) {
        frontier.emplace(piece.as.neighboursIn(c, k), walls(piece, c),
                         -fromStart[static_cast<std::size_t>(c)], -c);
    };
    piece.as.assign(seed, k);
    int grown = 1;
    for (int d = 0; d < 4; ++d)
        if (g.canMove(seed, grid::kDirs[d]) && piece.isFree(g.neighbour(seed, grid::kDirs[d])))
            push(g.neighbour(seed, grid::kDirs[d]));
    while (grown < target && !frontier.empty()) {
        const auto [nIn, nWalls, negDist, negC] = frontier.top();
        frontier.pop();
        const int c = -negC;
        if (!piece.isFree(c) || nIn != piece.as.neighboursIn(c, k) || nWalls != walls(piece, c))
            continue; // stale entry: a fresher one is queued
        piece.as.assign(c, k);
        ++grown;
        for (int d = 0; d < 4; ++d) {
            if (!g.canMove(c, grid::kDirs[d]))
                continue;
            const int n = g.neighbour(c, grid::kDirs[d]);
            if (piece.isFree(n))
                push(n); // its counts changed: queue it afresh (walls count direct neighbours only)
        }
    }
    return true;
}

// The subarea a free piece `left` joins: the adjacent one furthest below its target (ties: the
// most shared edges).
int leftoverOwner(const PieceState& piece, const std::vector<int>& left,
                  const std::vector<int>& fleet, const std::vector<int>& targets) {
    const grid::Grid& g = piece.g;
    int bestK = -1;
    double bestDeficit = -std::numeric_limits<double>::infinity();
    int bestShared = -1;
    std::vector<int> shared(static_cast<std::size_t>(piece.as.aircraft()), 0);
    for (int x : left)
        for (int d = 0; d < 4; ++d)
            if (g.canMove(x, grid::kDirs[d])) {
                const int o = piece.as.owner(g.neighbour(x, grid::kDirs[d]));
                if (o >= 0)
                    ++shared[static_cast<std::size_t>(o)];
            }
    for (int k : fleet) {
        if (shared[static_cast<std::size_t>(k)] == 0)
            continue;
        const double deficit = targets[static_cast<std::size_t>(k)] - piece.as.size(k);
        if (deficit > bestDeficit ||
            (deficit == bestDeficit && shared[static_cast<std::size_t>(k)] > bestShared)) {
            bestK = k;
            bestDeficit = deficit;
            bestShared = shared[static_cast<std::size_t>(k)];
        }
    }
    if (bestK < 0)
        bestK = fleet.front(); // nothing grown here (cannot happen with a non-empty fleet)
    return bestK;
}

// Leftovers (paper fig. 9): each free piece joins the adjacent subarea furthest below target.
void placeLeftovers(PieceState& piece, const std::vector<int>& fleet,
                    const std::vector<int>& targets) {
    for (int c : piece.cells) {
        if (!piece.isFree(c))
            continue;
        const auto dist = moveDistances(piece.g, {c}, [&](int x) { return piece.isFree(x); });
        std::vector<int> left;
        for (int x : piece.cells)
            if (dist[static_cast<std::size_t>(x)] >= 0)
                left.push_back(x);
        const int k = leftoverOwner(piece, left, fleet, targets);
        for (int x : left)
            piece.as.assign(x, k);
    }
}

// The subarea furthest over its target and not blocked; -1 when none is.
int mostOverTarget(const CellAssignment& as, const std::vector<int>& fleet,
                   const std::vector<int>& targets, const std::set<std::pair<int, int>>& blocked) {
    int over = -1;
    for (int k : fleet)
        if (as.size(k) > targets[static_cast<std::size_t>(k)] &&
            (over < 0 || as.size(k) - targets[static_cast<std::size_t>(k)] >
                             as.size(over) - targets[static_cast<std::size_t>(over)]) &&
            !blocked.count({k, -1}))
            over = k;
    return over;
}

// BFS over subareas from `over` to the nearest one below target, avoiding blocked edges: that
// subarea (-1 if none) and, in `prev`, the chain back to `over`.
int nearestUnderTarget(const CellAssignment& as, const std::vector<int>& fleet,
                       const std::vector<int>& targets,
                       const std::set<std::pair<int, int>>& blocked, int over,
                       std::vector<int>& prev) {
    const auto adj = as.adjacency();
    prev.assign(static_cast<std::size_t>(as.aircraft()), -2);
    std::deque<int> q{over};
    prev[static_cast<std::size_t>(over)] = -1;
    int under = -1;
    while (!q.empty() && under < 0) {
        const int a = q.front();
        q.pop_front();
        for (int b : fleet) {
            if (prev[static_cast<std::size_t>(b)] != -2 ||
                adj[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)] == 0 ||
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
    return under;
}

// Moves cells along each edge of the chain from `over` to `under`, from the receiving end
// backwards, so that the subareas in between end up with as many cells as before. Counts the cells
// moved in `moves`; false (the edge blocked) if an edge moved none.
bool moveAlongChain(CellAssignment& as, const std::vector<int>& targets, int over, int under,
                    const std::vector<int>& prev, std::set<std::pair<int, int>>& blocked,
                    int& moves) {
    int amount = std::min(as.size(over) - targets[static_cast<std::size_t>(over)],
                          targets[static_cast<std::size_t>(under)] - as.size(under));
    bool stuck = false;
    for (int b = under; prev[static_cast<std::size_t>(b)] >= 0 && !stuck;
         b = prev[static_cast<std::size_t>(b)]) {
        const int a = prev[static_cast<std::size_t>(b)];
        const int done = static_cast<int>(as.transfer(a, b, amount).size());
        moves += done;
        if (done == 0) {
            blocked.insert({a, b});
            stuck = true;
        }
        amount = done;
    }
    return !stuck;
}

// Redistribution to the targets (paper fig. 9), along chains of adjacent subareas.
void redistribute(CellAssignment& as, int pieceSize, const std::vector<int>& fleet,
                  const std::vector<int>& targets) {
    std::set<std::pair<int, int>> blocked;
    const int maxMoves = 4 * pieceSize + 16;
    for (int moves = 0, rounds = 0; moves < maxMoves && rounds < maxMoves && !stopRequested();
         ++rounds) {
        const int over = mostOverTarget(as, fleet, targets, blocked);
        if (over < 0)
            break;
        std::vector<int> prev;
        const int under = nearestUnderTarget(as, fleet, targets, blocked, over, prev);
        if (under < 0) {
            blocked.insert({over, -1});
            continue;
        }
        if (moveAlongChain(as, targets, over, under, prev, blocked, moves))
            blocked.clear();
    }
}

// Grows one subarea per aircraft in `fleet` over the connected piece `piece`, then places the
// leftovers and redistributes to `targets` (indexed by aircraft).
void partitionPiece(const grid::Grid& g, const std::vector<int>& piece,
                    const std::vector<int>& fleet, const std::vector<int>& targets,
                    CellAssignment& as) {
    PieceState state(g, piece, as);
    const auto fromStart = sweepDistances(state);
    for (int k : fleet)
        if (!growSubarea(state, k, targets[static_cast<std::size_t>(k)], fromStart))
            break;
    placeLeftovers(state, fleet, targets);
    redistribute(as, static_cast<int>(piece.size()), fleet, targets);
}

} // namespace

bool isConnected(const grid::Grid& g, const std::vector<int>& cells) {
    if (cells.empty())
        return false;
    std::vector<std::uint8_t> in(static_cast<std::size_t>(g.cellCount()), 0);
    for (int c : cells)
        in[static_cast<std::size_t>(c)] = 1;
    const auto dist = moveDistances(g, {cells.front()}, [&](int c) { return in[static_cast<std::size_t>(c)] != 0; });
    return std::all_of(cells.begin(), cells.end(), [&](int c) { return dist[static_cast<std::size_t>(c)] >= 0; });
}

Result<Partition> partitionCells(const grid::Grid& g, const std::vector<double>& shares) {
    const int n = static_cast<int>(shares.size());
    if (n == 0)
        return makeError(ErrorCode::InvalidInput, "No aircraft to share the area between.");
    for (int k = 0; k < n; ++k)
        if (!(shares[static_cast<std::size_t>(k)] > 0) || !std::isfinite(shares[static_cast<std::size_t>(k)]))
            return makeError(ErrorCode::InvalidInput,
                             "The share of aircraft " + std::to_string(k + 1) + " is not a positive number.");
    std::vector<int> activeCells;
    for (int c = 0; c < g.cellCount(); ++c)
        if (g.needsVisit(c))
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
            const auto dist = moveDistances(g, {c}, [&](int x) { return g.needsVisit(x); });
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

    CellAssignment as(g, n);
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
        if (stopRequested()) // a piece broken off is no partition
            return makeError(ErrorCode::Cancelled, "planning cancelled");
    }
    // Pieces without an aircraft of their own go, whole, to the aircraft whose cells are nearest.
    for (std::size_t p = 0; p < pieces.size(); ++p) {
        if (!fleetOf[p].empty())
            continue;
        int bestK = 0;
        double bestD = std::numeric_limits<double>::infinity();
        const geo::Vec2 c0 = baseCellCenter(g, pieces[p].front());
        for (int c : activeCells) {
            const int k = as.owner(c);
            if (k < 0)
                continue;
            const double d = (baseCellCenter(g, c) - c0).squaredNorm();
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

} // namespace pf::fleet
