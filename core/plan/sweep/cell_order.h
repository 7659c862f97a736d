// The order in which a sweep flies its cells, and how it enters each: a construction plus local search.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

namespace pf::plan {

// A cell can be swept in a few ways (lane direction, first lane's direction); each way runs from one
// end point to another and can be flown forwards (a -> b) or backwards (b -> a) for the same cost,
// because the flight-time model is symmetric under reversal.
struct OrderWay {
    int a = 0, b = 0;   // end points (ids into the caller's points)
    double costS = 0.0; // flying the cell this way, from a to b
};

struct OrderCell {
    std::vector<OrderWay> ways; // at least one
};

// Costs of moving between cells, in seconds, supplied by the caller: link(u, v) from end point u
// (where a cell's flight ends) to end point v (where the next begins); symmetric. start(v): from the
// take-off point to v (0 when the flight may start anywhere); finish(u) likewise for the landing.
// lowerBound(u, v) <= link(u, v), cheap: lets the search skip moves that cannot pay.
struct OrderProblem {
    std::vector<OrderCell> cells;
    std::function<double(int u, int v)> link;
    std::function<double(int u, int v)> lowerBound;
    std::function<double(int v)> start;
    std::function<double(int u)> finish;
    // Optional: end points near point p (any order). When set, the local search only tries moves that
    // create a link to a near point, so it scales to many thousands of cells.
    std::function<const std::vector<int>&(int p)> near;
    // Optional: a natural order of the cells (across the area, as a sweep meets them); the construction
    // also tries it, forwards and backwards, each cell flown its best way.
    std::vector<int> sweepOrder;
};

struct OrderOptions {
    int maxRounds = 50;        // local-search passes (each tries every move once), >= 0
    int maxStarts = 8;         // first cells tried by the construction when the start is free
    // Kicks of an iterated local search (a seeded double bridge, then the local search again, kept
    // when better); 0: none. Only without neighbour lists (cell-sized problems).
    int kicks = 0;
    bool improve = true;       // false: the construction alone (for tests and comparisons)
    // With neighbour lists: only moves that remove a link dearer than this many seconds are tried
    // (links between neighbouring lanes of a cell are as good as they get).
    double focusAboveS = -1.0;
};

struct OrderStep {
    int cell = 0;
    int way = 0;
    bool reversed = false;     // flown b -> a
    int entry(const OrderProblem& p) const;
    int exit(const OrderProblem& p) const;
};

struct OrderResult {
    std::vector<OrderStep> steps;
    double costS = 0.0;            // start + cells + links + finish
    double constructedCostS = 0.0; // the same for the construction before local search
    std::vector<OrderStep> constructed; // the construction's sequence itself (what options.improve = false returns)
    int rounds = 0;                // local-search passes run
    int moves = 0;                 // improving moves applied
    std::int64_t linkEvaluations = 0;
};

// Nearest-neighbour construction (best of several first cells, and the sweep order when given), then 2-opt (reverse a run of cells),
// or-opt (move a run of up to three cells, either way round) and the best way for every cell given
// the order (a shortest path over the ways), until no move pays or maxRounds. Deterministic.
OrderResult orderCells(const OrderProblem& problem, const OrderOptions& options = {});

// Local search from a given sequence (every cell once), as orderCells does after its construction.
OrderResult improveOrder(const OrderProblem& problem, std::vector<OrderStep> steps, const OrderOptions& options = {});

// The cost of a given sequence (start + cells + links + finish).
double orderCost(const OrderProblem& problem, const std::vector<OrderStep>& steps);

} // namespace pf::plan
