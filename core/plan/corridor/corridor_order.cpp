#include "core/plan/corridor/corridor_order.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace pf::plan::corridor_detail {

namespace {

using geo::Vec2;
constexpr double kInf = std::numeric_limits<double>::infinity();

// sections[s][lane]: the runs of that lane in section s, in station order.
using Sections = std::vector<std::vector<std::vector<CorridorRun>>>;

// A run cut where its stations cross the boundaries; each part keeps only points between its first
// and last photo (a part without a photo is dropped).
std::vector<std::pair<int, CorridorRun>> splitRun(const CorridorRun& run,
                                                  const std::vector<double>& bounds) {
    std::vector<std::pair<int, CorridorRun>> parts;
    auto sectionOf = [&](double s) {
        return static_cast<int>(std::upper_bound(bounds.begin(), bounds.end(), s) - bounds.begin());
    };
    for (const auto& p : run.points) {
        const int sec = sectionOf(p.station);
        if (parts.empty() || parts.back().first != sec)
            parts.push_back({sec, CorridorRun{run.lane, {}}});
        parts.back().second.points.push_back(p);
    }
    std::vector<std::pair<int, CorridorRun>> out;
    for (auto& [sec, part] : parts) {
        auto& pts = part.points;
        while (!pts.empty() && !pts.back().photo)
            pts.pop_back();
        const auto first =
            std::find_if(pts.begin(), pts.end(), [](const CorridorPoint& q) { return q.photo; });
        pts.erase(pts.begin(), first);
        if (!pts.empty())
            out.push_back({sec, std::move(part)});
    }
    return out;
}

Sections sectionsOf(const OrderInput& in, const std::vector<double>& bounds) {
    Sections s(bounds.size() + 1,
               std::vector<std::vector<CorridorRun>>(static_cast<std::size_t>(in.lanes)));
    for (const auto& run : in.runs)
        for (auto& [sec, part] : splitRun(run, bounds))
            s[static_cast<std::size_t>(sec)][static_cast<std::size_t>(run.lane)].push_back(
                std::move(part));
    for (auto& sec : s)
        for (auto& lane : sec)
            std::sort(lane.begin(), lane.end(), [](const CorridorRun& a, const CorridorRun& b) {
                return a.firstStation() < b.firstStation();
            });
    return s;
}

// The runs of one lane of a section in the direction of flight.
std::vector<CorridorRun> laneInDirection(const std::vector<CorridorRun>& runs, bool forward) {
    std::vector<CorridorRun> out;
    if (forward) {
        out = runs;
    } else {
        for (auto it = runs.rbegin(); it != runs.rend(); ++it)
            out.push_back(reversed(*it));
    }
    return out;
}

// Lanes back and forth in each section, sections along the line.
std::vector<CorridorRun> orderOf(const Sections& sections, bool forward, bool startLow,
                                 const std::optional<Vec2>& home) {
    std::vector<CorridorRun> out;
    // Where the flight is (a plain point and a flag: an optional here trips GCC's
    // maybe-uninitialized).
    Vec2 at = home ? *home : Vec2(0, 0);
    bool located = home.has_value();
    const std::size_t n = sections.size();
    for (std::size_t i = 0; i < n; ++i) {
        const auto& sec = sections[forward ? i : n - 1 - i];
        const int lanes = static_cast<int>(sec.size());
        // The side to start from: given for the first section, then the one nearer to where the
        // flight is.
        auto entry = [&](int lane) -> std::optional<Vec2> {
            const auto& r = sec[static_cast<std::size_t>(lane)];
            if (r.empty())
                return std::nullopt;
            return forward ? r.front().points.front().pos : r.back().points.back().pos;
        };
        int first = startLow ? 0 : lanes - 1;
        if (!out.empty() && located) {
            const auto lo = entry(0), hi = entry(lanes - 1);
            if (lo && hi)
                first = (*lo - at).norm() <= (*hi - at).norm() ? 0 : lanes - 1;
        }
        bool dir = forward;
        for (int k = 0; k < lanes; ++k) {
            const int lane = first == 0 ? k : lanes - 1 - k;
            const auto& runs = sec[static_cast<std::size_t>(lane)];
            if (runs.empty())
                continue;
            for (auto& r : laneInDirection(runs, dir))
                out.push_back(std::move(r));
            dir = !dir;
        }
        if (!out.empty()) {
            at = out.back().points.back().pos;
            located = true;
        }
    }
    return out;
}

// The order's links and time; +infinity when a link has no safe way.
class Timer {
public:
    explicit Timer(const OrderInput& in) : m_in(in) {}

    FlightOrder finish(const std::vector<CorridorRun>& runs, int sections) {
        FlightOrder o;
        o.sections = sections;
        FlightTimeAccumulator acc(m_in.time);
        o.timeS = kInf; // until every way is known to exist
        o.runs = runs;
        if (runs.empty())
            return o;
        // The way from home and back, as the time of an order must count it.
        const auto* out = m_in.home ? link(*m_in.home, runs.front().points.front().pos) : &m_none;
        const std::optional<Vec2> end = m_in.landing ? m_in.landing : m_in.home;
        const auto* back = end ? link(runs.back().points.back().pos, *end) : &m_none;
        if (!out || !back)
            return o;
        if (m_in.home)
            acc.add(*m_in.home);
        for (const auto& p : *out)
            acc.add(p);
        o.homeLink = *out;
        o.landingLink = *back;
        for (std::size_t i = 0; i < runs.size(); ++i) {
            if (i > 0) {
                const auto* l = link(runs[i - 1].points.back().pos, runs[i].points.front().pos);
                if (!l)
                    return o;
                for (const auto& p : *l)
                    acc.add(p);
                o.links.push_back(*l);
            }
            for (const auto& p : runs[i].points)
                acc.add(p.pos);
        }
        for (const auto& p : *back)
            acc.add(p);
        if (end)
            acc.add(*end);
        o.timeS = acc.result().totalS;
        return o;
    }

private:
    const std::vector<Vec2>* link(const Vec2& a, const Vec2& b) {
        const auto key = std::make_tuple(std::llround(a.x() * 1e3), std::llround(a.y() * 1e3),
                                         std::llround(b.x() * 1e3), std::llround(b.y() * 1e3));
        auto it = m_links.find(key);
        if (it == m_links.end())
            it = m_links.emplace(key, m_in.link(a, b)).first;
        return it->second ? &*it->second : nullptr;
    }

    const OrderInput& m_in;
    const std::vector<Vec2> m_none;
    std::map<std::tuple<long long, long long, long long, long long>,
             std::optional<std::vector<Vec2>>>
        m_links;
};

FlightOrder bestFor(const OrderInput& in, const std::vector<double>& bounds, Timer& timer) {
    const Sections sections = sectionsOf(in, bounds);
    FlightOrder best;
    best.timeS = kInf;
    for (bool forward : {true, false})
        for (bool startLow : {true, false}) {
            FlightOrder o = timer.finish(orderOf(sections, forward, startLow, in.home),
                                         static_cast<int>(sections.size()));
            if (o.timeS < best.timeS - 1e-9 || best.runs.empty())
                best = std::move(o);
        }
    return best;
}

} // namespace

CorridorRun reversed(CorridorRun run) {
    std::reverse(run.points.begin(), run.points.end());
    for (auto& p : run.points)
        p.headingDeg = std::fmod(p.headingDeg + 180.0, 360.0);
    return run;
}

FlightOrder chooseOrder(const OrderInput& in) {
    Timer timer(in);
    std::vector<double> mids;
    for (const auto& [lo, hi] : in.cuts)
        mids.push_back(0.5 * (lo + hi));
    const auto boundsOf = [&](const std::vector<bool>& use) {
        std::vector<double> b;
        for (std::size_t i = 0; i < mids.size(); ++i)
            if (use[i])
                b.push_back(mids[i]);
        return b;
    };
    std::vector<bool> use(mids.size(), false);
    FlightOrder best = bestFor(in, {}, timer);
    if (mids.empty())
        return best;
    std::vector<bool> all(mids.size(), true);
    if (FlightOrder o = bestFor(in, boundsOf(all), timer); o.timeS < best.timeS - 1e-6) {
        best = std::move(o);
        use = all;
    }
    // Each cut toggled once, kept while the flight gets sooner.
    for (std::size_t i = 0; i < mids.size(); ++i) {
        use[i] = !use[i];
        FlightOrder o = bestFor(in, boundsOf(use), timer);
        if (o.timeS < best.timeS - 1e-6)
            best = std::move(o);
        else
            use[i] = !use[i];
    }
    return best;
}

} // namespace pf::plan::corridor_detail
