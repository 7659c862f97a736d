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

namespace {

// Each photo with a position to the nearest free planned point within the tolerance, nearest pairs
// first. Returns, for each planned point, the photo that took it (-1: none).
std::vector<int> matchNearest(std::vector<PhotoWork>& work,
                              const std::vector<geo::Vec2>& plannedLocal, double tolerance) {
    std::vector<int> takenBy(plannedLocal.size(), -1);
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
    std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) { return a.d < b.d; });
    for (const auto& p : pairs) {
        if (work[p.photo].planned >= 0 || takenBy[p.planned] >= 0)
            continue;
        work[p.photo].planned = p.planned;
        work[p.photo].planOffset = p.d;
        takenBy[p.planned] = p.photo;
    }
    return takenBy;
}

// A finding for every photo with a position that took no point: a second photo at a point, or one
// far from every point (both still mosaicked where their EXIF says).
void reportUnmatched(std::vector<PhotoWork>& work, const std::vector<PlannedPhoto>& points,
                     const std::vector<geo::Vec2>& plannedLocal, const std::vector<int>& takenBy,
                     double tolerance, ResolvedPoses& out) {
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
            addFinding(out, w, PhotoFinding::Kind::Duplicate, false,
                       "a second photo at planned point " + points[nearest].label() + " (" +
                           fmt("%.1f m", d) + " away; " + work[takenBy[nearest]].file +
                           " is nearer): mosaicked where its EXIF says");
        else
            addFinding(out, w, PhotoFinding::Kind::FarFromPlan, false,
                       fmt("%.1f m", d) + " from the nearest planned point (" +
                           points[nearest].label() + "; tolerance " + fmt("%.1f m", tolerance) +
                           "): mosaicked where its EXIF says");
    }
}

// Photos [i, j) have no position: they take the planned points between their placed neighbours'
// (before, after), in order, when as many are left as there are photos (or when no photo has a
// position, with a note when the counts differ); else each gets a finding.
void placeRun(std::vector<PhotoWork>& work, int i, int j, int before, int after,
              const std::vector<PlannedPhoto>& points, std::vector<int>& takenBy, bool anyPosition,
              bool& warnedCount, ResolvedPoses& out) {
    const int run = j - i;
    const int room = after - before - 1;
    const bool noneHasPosition = !anyPosition;
    if (!(room == run || (noneHasPosition && run > 0))) {
        for (int k = i; k < j; ++k)
            addFinding(out, work[k], PhotoFinding::Kind::NoPosition, true,
                       "no GPS position, and the photos before and after it leave " +
                           std::to_string(std::max(room, 0)) + " planned point(s) for " +
                           std::to_string(run) +
                           " photo(s) without a position: cannot tell which is which");
        return;
    }
    if (noneHasPosition && run != room && !warnedCount) {
        warnedCount = true;
        out.notes.push_back(std::to_string(run) + " photos without a GPS position for " +
                            std::to_string(room) +
                            " planned photo points: matched in capture order; every photo after a "
                            "missed or extra shot is misplaced, check the seams");
    }
    for (int k = 0; k < run; ++k) {
        const int planned = before + 1 + k;
        if (planned >= static_cast<int>(points.size()) || takenBy[planned] >= 0) {
            addFinding(out, work[i + k], PhotoFinding::Kind::NoPosition, true,
                       "no GPS position, and no planned photo point left for it in capture "
                       "order");
            continue;
        }
        work[i + k].planned = planned;
        work[i + k].inOrder = true;
        work[i + k].position = points[planned].position;
        takenBy[planned] = i + k;
    }
}

} // namespace

std::vector<int> matchToPlan(std::vector<PhotoWork>& work, const std::vector<PlannedPhoto>& points,
                             const std::vector<geo::Vec2>& plannedLocal, double tolerance,
                             bool anyPosition, ResolvedPoses& out) {
    std::vector<int> takenBy = matchNearest(work, plannedLocal, tolerance);
    reportUnmatched(work, points, plannedLocal, takenBy, tolerance, out);
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
        // Their neighbours' planned indices bound them.
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
        placeRun(work, i, j, before, after, points, takenBy, anyPosition, warnedCount, out);
        i = j;
    }
    return takenBy;
}

} // namespace pf::mosaic::detail
