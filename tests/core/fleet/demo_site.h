// The fixed demo site (Rheinhafen training ground) in a local frame, for the fleet tests.
#pragma once

#include "core/geo/local_frame.h"

#include <cmath>
#include <vector>

namespace pf::fleet::test {

struct DemoSite {
    geo::Polygon area;
    std::vector<geo::Polygon> noFly; // warehouse, radio mast
    geo::Vec2 home{0, 0};
};

inline DemoSite demoSite() {
    const geo::GeoPolygon area{{{8.3272608, 49.0109209},
                                {8.3324653, 49.0108309},
                                {8.3327392, 49.0123597},
                                {8.3308218, 49.0125396},
                                {8.3305478, 49.0133489},
                                {8.3273978, 49.013259}},
                               {}};
    auto frame = geo::LocalFrame::forArea(area);
    DemoSite s;
    s.area = frame->toLocal(area);
    s.noFly.push_back(frame->toLocal(geo::GeoPolygon{{{8.3291782, 49.0118201},
                                                       {8.3297261, 49.0118201},
                                                       {8.3297261, 49.0121799},
                                                       {8.3291782, 49.0121799}},
                                                      {}}));
    const geo::Vec2 mast = frame->toLocal(geo::LonLat{8.3316435, 49.0115504});
    geo::Polygon mastZone;
    for (int i = 0; i < 16; ++i)
        mastZone.outer.push_back(mast + 20.0 * geo::Vec2(std::cos(i * M_PI / 8), std::sin(i * M_PI / 8)));
    s.noFly.push_back(mastZone);
    s.home = frame->toLocal(geo::LonLat{8.3270554, 49.010741});
    return s;
}

} // namespace pf::fleet::test
