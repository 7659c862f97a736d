// Keeping the best of candidates offered in turn, with the planners' one tie rule, and the one
// tolerance for comparing flight times.
#pragma once

#include <cmath>
#include <limits>
#include <utility>

namespace pf::plan {

// Flight times this close (seconds) are a tie: sums of the same legs in another order differ by
// rounding, and a plan must not change with the order its legs were added in.
constexpr double kTimeTieS = 1e-9;
// True if time a is sooner than time b by more than a tie.
inline bool sooner(double a, double b) { return a < b - kTimeTieS; }
// True if times a and b are a tie.
inline bool sameTime(double a, double b) { return std::fabs(a - b) <= kTimeTieS; }

// The best of candidates offered one after the other, by their scores. The tie rule: a candidate is
// kept only when it is strictly better (`better(score, kept)`) than the one kept so far, so among equal
// candidates the first offered wins. Planners offer their candidates in their documented order of
// preference (the paper's rules first, then variants), which makes that order the tie-breaker and the
// plans deterministic. The caller keeps the candidate itself when offer() returns true.
template <class Score, class Better>
class BestCandidate {
public:
    explicit BestCandidate(Better better) : m_better(std::move(better)) {}
    // With a bound: a candidate must also be better than `bound` to be kept at all.
    BestCandidate(Better better, Score bound) : m_better(std::move(better)), m_score(std::move(bound)), m_bounded(true) {}

    // Offers the next candidate; true if it is now the best (the caller keeps it).
    bool offer(const Score& score) {
        const int index = m_offered++;
        if ((m_index >= 0 || m_bounded) && !m_better(score, m_score))
            return false;
        m_score = score;
        m_index = index;
        return true;
    }

    bool empty() const { return m_index < 0; }
    // The position of the best candidate in the order offered (from 0), -1 if none was kept.
    int index() const { return m_index; }
    const Score& score() const { return m_score; }

private:
    Better m_better;
    Score m_score{};
    bool m_bounded = false;
    int m_index = -1;
    int m_offered = 0;
};

// The soonest of candidate times (BestCandidate with `sooner`); with no candidate better than +inf
// kept, a non-finite time is never chosen.
inline auto soonestTime() {
    return BestCandidate<double, bool (*)(double, double)>(&sooner, std::numeric_limits<double>::infinity());
}

} // namespace pf::plan
