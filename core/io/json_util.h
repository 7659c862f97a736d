// JSON helpers shared by the io readers and writers (CPLJSON). Internal: include from .cpp files only.
#pragma once

#include "core/fleet/aircraft.h"
#include "core/sensor/camera.h"

#include <cpl_json.h>

namespace pf::io::detail {

// A JSON number holding the shortest decimal that reads back to exactly `v`. json-c's own double
// printing drops the last digit now and then (so a write/read cycle could change a coordinate);
// json-c keeps the text of a parsed number and writes it back verbatim, so the number is built by
// parsing its exact text.
CPLJSONObject jsonNumber(double v);

// A camera as the mission file and the catalog store it: only the definition in use is written
// (optics or field of view); absent values read back as 0.
CPLJSONObject cameraToJson(const sensor::Camera& c);

// A plane's figures as the mission file and the catalog store them ("plane": {"turn_radius_m",
// "bank_deg", "climb_rate_mps", "sink_rate_mps", "run_in_m", "stall_speed_mps"}); the optional
// values only when set.
CPLJSONObject planeToJson(const fleet::PlanePerformance& p);

} // namespace pf::io::detail
