// What the stages of one mosaic run share: the part of the job's progress a stage reports in, a
// parallel loop over the photos, and what becomes of each placed photo. Internal to buildMosaic.
#pragma once

#include "core/mosaic/photo_geometry.h"
#include "core/progress.h"
#include "core/result.h"

#include <algorithm>
#include <atomic>
#include <string>
#include <thread>
#include <vector>

namespace pf::mosaic::detail {

// The part [base, base + span] of the job's progress.
struct Stage {
    Progress& progress;
    double base;
    double span;
    std::string name;
    bool operator()(double f) {
        progress.report(base + span * std::clamp(f, 0.0, 1.0), name);
        return !progress.cancelled();
    }
};

// Runs fn(i) for i in [0, n) on `threads` threads (the caller's among them).
template <class Fn> void parallelFor(int n, int threads, Fn fn) {
    std::atomic<int> next{0};
    auto worker = [&] {
        for (int i = next++; i < n; i = next++)
            fn(i);
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < std::min(threads, n); ++t)
        pool.emplace_back(worker);
    worker();
    for (auto& t : pool)
        t.join();
}

inline Error cancelled() {
    return makeError(ErrorCode::Cancelled, "the mosaic was cancelled");
}

// Per placed photo (in capture order): its geometry on the output grid's ground, whether it gives
// colour to the mosaic and, in words, what became of it.
struct PhotoUse {
    std::vector<PhotoGeometry> geoms;
    std::vector<char> active;
    std::vector<std::string> status;
};

} // namespace pf::mosaic::detail
