// JobScope: the Progress of the job a thread works for, so that deep loops can stop and report.
#pragma once

#include "core/progress.h"

#include <string>

namespace pf {

// Planning runs through some twenty stages and helpers (grid build, planners, photo placement,
// detours, sorties, the coverage check, the fleet split with its estimates). Rather than add a
// Progress parameter to each of them, the caller of a long job installs its Progress for the thread
// with a JobScope, and the loops ask stopRequested() (an atomic load, cheap enough to call every few
// thousand iterations); a loop that sees it breaks off, and the job's stage boundaries then return
// ErrorCode::Cancelled (no partial result escapes). A job that starts worker threads installs a
// scope in each of them (same Progress, its own share of the range). Scopes nest: a nested scope maps
// its [0, 1] onto a part of the enclosing one's range, so a stage reports its own fraction.
class JobScope {
public:
    // Installs `progress` (may be null: nothing to report, never cancelled) for this thread,
    // reporting into [lo, hi] of it with `prefix` before each stage name.
    explicit JobScope(Progress* progress, double lo = 0.0, double hi = 1.0, std::string prefix = {});
    // For a worker thread that does a side job beside the one reporting: it stops when `progress`
    // is cancelled, but its reports (and those of scopes nested in it) go nowhere.
    struct CancelOnly {};
    JobScope(Progress* progress, CancelOnly);
    // A part [lo, hi] of the current scope's range (of this thread), its stage names prefixed.
    JobScope(double lo, double hi, const std::string& prefix = {});
    // The current scope of this thread, to be installed in a worker thread that does part of its
    // work: the worker then stops with the job and reports into the same range.
    struct Share {
        Progress* progress = nullptr;
        double lo = 0.0;
        double hi = 1.0;
        std::string prefix;
        bool silent = false;
    };
    static Share share();
    explicit JobScope(const Share& share);
    ~JobScope();
    JobScope(const JobScope&) = delete;
    JobScope& operator=(const JobScope&) = delete;

    // The current thread's Progress (null outside any scope).
    static Progress* current();
    // Reports `fraction` of this scope's range, the stage named with the scope's prefix.
    void report(double fraction, const std::string& stage) const;

private:
    Progress* m_progress;
    double m_lo;
    double m_hi;
    std::string m_prefix;
    bool m_silent = false;
    JobScope* m_outer;
};

// True when the job the current thread works for was cancelled.
bool stopRequested();
// Reports `fraction` (of the current scope) done, in `stage`; nothing outside a scope.
void reportProgress(double fraction, const std::string& stage);

} // namespace pf
