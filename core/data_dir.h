// Where the bundled data lives (catalog.json, the demo map and DEM, sample areas): the folders
// searched, most specific first, and the first that holds catalog.json. Used by the catalog, the
// terrain stage and the GUI; core-wide, below every stage.
#pragma once

#include <string>
#include <vector>

namespace pf {

// $PHOTOFLIGHT_DATA_DIR, <the executable's folder>/../share/photoflight (a relocated installation),
// the installed data directory, the source tree's resources (a build that runs without installing).
std::vector<std::string> dataDirectoryCandidates();

// True if `path` names an existing regular file (not a folder): how the data folders and the user's
// catalog are looked for.
bool isFile(const std::string& path);

// The directory holding the bundled data (catalog.json, demo/), searched as above; empty if none.
std::string dataDirectory();

} // namespace pf
