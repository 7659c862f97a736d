#include "core/geo/half_plane_clip.h"

namespace pf::geo {

void clipHalfPlane(const std::vector<Vec2>& in, std::vector<Vec2>& out, int axis, double v, bool keepAbove) {
    out.clear();
    const std::size_t n = in.size();
    if (n == 0)
        return;
    auto inside = [&](const Vec2& p) { return keepAbove ? p[axis] >= v : p[axis] <= v; };
    Vec2 prev = in[n - 1];
    bool prevIn = inside(prev);
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2& cur = in[i];
        const bool curIn = inside(cur);
        if (curIn != prevIn) {
            const double t = (v - prev[axis]) / (cur[axis] - prev[axis]);
            Vec2 x = prev + t * (cur - prev);
            x[axis] = v;
            out.push_back(x);
        }
        if (curIn)
            out.push_back(cur);
        prev = cur;
        prevIn = curIn;
    }
}

} // namespace pf::geo
