// buildMosaic(): the photos of a flight to a georeferenced mosaic (direct georeferencing: each
// photo's pose, its footprint on the ground, seams by the most vertical view), with a report.
#pragma once

#include "core/mosaic/mosaic_types.h"
#include "core/progress.h"
#include "core/result.h"

namespace pf::mosaic {

// Reads and places the photos (bad ones are reported and left out), draws the seams, warps every
// photo once (streamed: each worker holds one decoded photo), writes the GeoTIFF and the vector
// layers and reports what it did. Fails (and writes nothing) on bad options, when no photo can be
// placed, when the output cannot be written, or when `progress` is cancelled.
Result<MosaicReport> buildMosaic(const MosaicOptions& options, Progress& progress);

// The vector file written beside `outputPath` when MosaicOptions::vectorPath is empty
// ("site/mosaic.tif" -> "site/mosaic.gpkg").
std::string defaultVectorPath(const std::string& outputPath);

} // namespace pf::mosaic
