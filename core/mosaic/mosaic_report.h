// The mosaic's report in words, as the CLI prints it and the desktop application shows it.
#pragma once

#include "core/mosaic/mosaic_types.h"

#include <string>

namespace pf::mosaic {

// Photos used and left out (with the reasons), the output, photos that do not match the plan, the
// planned points without a photo, coverage of the planned area and its gaps, notes. Lines end in
// '\n'; long lists are shortened (the vector layers hold everything).
std::string formatReport(const MosaicReport& report);

} // namespace pf::mosaic
