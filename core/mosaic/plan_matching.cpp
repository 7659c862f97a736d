// Matching photos to the plan's photo points (see plan_matching.h).
#include "core/mosaic/plan_matching.h"

#include <algorithm>
#include <cstdio>

namespace pf::mosaic::detail {

std::string fmt(const char* format, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

void addFinding(ResolvedPoses& out, PhotoWork& w, PhotoFinding::Kind kind, bool exclude,
                const std::string& message) {
    out.findings.push_back({w.file, kind, exclude, message});
    if (exclude)
        w.excluded = true;
}

std::vector<int> matchToPlan(std::vector<PhotoWork>& work, const std::vector<PlannedPhoto>& points,
                             const std::vector<geo::Vec2>& plannedLocal, double tolerance,
                             bool anyPosition, ResolvedPoses& out) {
    auto report = [&](PhotoFinding::Kind kind, PhotoWork& w, bool exclude, const std::string& message) {
        addFinding(out, w, kind, exclude, message);
    };
    std::vector<int> takenBy(points.size(), -1);
    struct Pair {
        double d;
        int photo;
        int planned;
    };
    std::vector<Pair> pairs;
    for (int i = 0; i < static_cast<int>(work.size()); ++i) {
        if (!work[i].local || work[i].excluded)
            continue;
        for (int j = 0; j < static_cast<int>(plannedLocal.size()); ++j) {
            const double d = (plannedLocal[j] - *work[i].local).norm();
            if (d <= tolerance)
                pairs.push_back({d, i, j});
        }
    }
    std::sort(pairs.begin(), pairs.end(),
              [](const Pair& a, const Pair& b) { return a.d < b.d; });
    for (const auto& p : pairs) {
        if (work[p.photo].planned >= 0 || takenBy[p.planned] >= 0)
            continue;
        work[p.photo].planned = p.planned;
        work[p.photo].planOffset = p.d;
        takenBy[p.planned] = p.photo;
    }
    for (auto& w : work) {
        if (!w.local || w.excluded || w.planned >= 0)
            continue;
        int nearest = -1;
        double d = 1e300;
        for (int j = 0; j < static_cast<int>(plannedLocal.size()); ++j) {
            const double dj = (plannedLocal[j] - *w.local).norm();
            if (dj < d) {
                d = dj;
                nearest = j;
            }
        }
        if (d <= tolerance)
            report(PhotoFinding::Kind::Duplicate, w, false,
                   "a second photo at planned point " + points[nearest].label() + " (" +
                       fmt("%.1f m", d) + " away; " + work[takenBy[nearest]].file +
                       " is nearer): mosaicked where its EXIF says");
        else
            report(PhotoFinding::Kind::FarFromPlan, w, false,
                   fmt("%.1f m", d) + " from the nearest planned point (" +
                       points[nearest].label() + "; tolerance " +
                       fmt("%.1f m", tolerance) + "): mosaicked where its EXIF says");
    }

    // Photos without a position take the planned points between their placed neighbours, in
    // order.
    const int n = static_cast<int>(work.size());
    int i = 0;
    bool warnedCount = false;
    while (i < n) {
        if (work[i].position) {
            ++i;
            continue;
        }
        int j = i;
        while (j < n && !work[j].position)
            ++j;
        // Photos [i, j) have no position. Their neighbours' planned indices bound them.
        int before = -1, after = static_cast<int>(points.size());
        for (int k = i - 1; k >= 0; --k)
            if (work[k].planned >= 0) {
                before = work[k].planned;
                break;
            }
        for (int k = j; k < n; ++k)
            if (work[k].planned >= 0) {
                after = work[k].planned;
                break;
            }
        const int run = j - i;
        const int room = after - before - 1;
        const bool noneHasPosition = !anyPosition;
        if (room == run || (noneHasPosition && run > 0)) {
            if (noneHasPosition && run != room && !warnedCount) {
                warnedCount = true;
                out.notes.push_back(
                    std::to_string(run) + " photos without a GPS position for " +
                    std::to_string(room) +
                    " planned photo points: matched in capture order; every photo after a "
                    "missed or extra shot is misplaced, check the seams");
            }
            for (int k = 0; k < run; ++k) {
                const int planned = before + 1 + k;
                if (planned >= static_cast<int>(points.size()) || takenBy[planned] >= 0) {
                    report(PhotoFinding::Kind::NoPosition, work[i + k], true,
                           "no GPS position, and no planned photo point left for it in capture "
                           "order");
                    continue;
                }
                work[i + k].planned = planned;
                work[i + k].inOrder = true;
                work[i + k].position = points[planned].position;
                takenBy[planned] = i + k;
            }
        } else {
            for (int k = i; k < j; ++k)
                report(PhotoFinding::Kind::NoPosition, work[k], true,
                       "no GPS position, and the photos before and after it leave " +
                           std::to_string(std::max(room, 0)) + " planned point(s) for " +
                           std::to_string(run) +
                           " photo(s) without a position: cannot tell which is which");
        }
        i = j;
    }
    return takenBy;
}

} // namespace pf::mosaic::detail
