// An independent reader of DJI WPML .kmz files for the tests, written from DJI's Cloud API
// documentation ("DJI WPML": overview, template.kml, waylines.wpml, Common Elements): it checks
// what the documentation requires of a file and draws the route the aircraft flies from
// waylines.wpml.
#pragma once

#include "core/geo/types.h"

#include <cstddef>
#include <string>
#include <vector>

namespace pf::test {

struct WpmlFlownPoint {
    geo::LonLat position;
    double executeHeightM = 0.0;
    bool photo = false; // a photo is taken here
};

struct WpmlCheck {
    std::vector<std::string> problems;     // every rule broken, in words; empty for a good file
    std::string executeHeightMode;         // of the (first) wayline
    std::string templateHeightMode;        // template.kml's heightMode
    std::vector<WpmlFlownPoint> waypoints; // waylines.wpml's waypoints, by index
    std::vector<WpmlFlownPoint> flown; // the waypoints with the photos taken between them, in order
    std::size_t photos = 0;            // photos the actions take
    int droneEnum = -1, droneSubEnum = -1, payloadEnum = -1;
    std::vector<double> templateHeights, templateEllipsoidHeights; // template.kml, by index
};

WpmlCheck checkWpmlKmz(const std::string& path);

} // namespace pf::test
