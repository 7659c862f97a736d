// A KMZ (ZIP) archive written with minizip (Debian's libminizip, zlib's ZIP writer: GDAL 3.6's own
// writer stores no date) and read through GDAL's /vsizip/.
#pragma once

#include "core/result.h"

#include <ctime>
#include <string>
#include <vector>

namespace pf::io::wpml {

struct ArchiveEntry {
    std::string name; // path inside the archive, '/' separated: "wpmz/template.kml"
    std::string data;
};

// Writes the archive next to `path` and renames it over `path`, so a failed write never leaves half
// an archive behind. Every entry is dated `modified` (the export time; ZIP keeps local time to two
// seconds, from 1980 on). Errors name the file.
Status writeZipArchive(const std::string& path, const std::vector<ArchiveEntry>& entries,
                       std::time_t modified = std::time(nullptr));

// The names of the files in the archive (folders left out). Errors: the file cannot be read, or it
// is not a ZIP archive.
Result<std::vector<std::string>> zipArchiveFiles(const std::string& path);

// One file's content; NotFound when the archive holds no file of that name.
Result<std::string> readZipArchiveFile(const std::string& path, const std::string& name);

} // namespace pf::io::wpml
