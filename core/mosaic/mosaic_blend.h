// The mosaic's colour: every photo warped into the pixels it gives colour to and blended with its
// neighbour across a seam over the feather width. Internal to buildMosaic.
#pragma once

#include "core/mosaic/mosaic_canvas.h"
#include "core/mosaic/mosaic_run.h"
#include "core/mosaic/mosaic_types.h"
#include "core/mosaic/output_grid.h"
#include "core/mosaic/pose_resolver.h"
#include "core/mosaic/seam_map.h"
#include "core/mosaic/site_frame.h"
#include "core/progress.h"
#include "core/result.h"

#include <vector>

namespace pf::mosaic::detail {

// Warps every active photo (one decoded photo per worker) into its seam window of the canvas. A
// photo that cannot be warped is left out (use.active, use.status) with a finding; an I/O error of
// the scratch rasters stops the run (IoError), as does a cancel (Cancelled). featherGrid: the
// feather width in grid metres.
Status blendPhotos(const std::vector<PlacedPhoto>& photos, PhotoUse& use,
                   const ScaledGround& ground, const OutputGrid& grid, const SeamMap& seams,
                   MosaicCanvas& canvas, double featherGrid, int threads, Progress& progress,
                   std::vector<PhotoFinding>& findings);

} // namespace pf::mosaic::detail
