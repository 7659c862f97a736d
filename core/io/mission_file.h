// The mission file: a documented, versioned JSON document (docs/files.md, "Mission file").
#pragma once

#include "core/mission/mission.h"
#include "core/result.h"

#include <string>

namespace pf::io {

namespace detail {
// The "format" value of every mission file.
inline constexpr const char* kMissionFormatName = "photoflight-mission";
} // namespace detail

// Reads and checks a mission file. Errors name the file, the field and what is wrong.
Result<mission::Mission> readMissionFile(const std::string& path);
// Parses mission JSON text; `sourceName` is used in messages (a path or "<clipboard>").
Result<mission::Mission> parseMissionJson(const std::string& text, const std::string& sourceName);
// Serialises a mission; parseMissionJson(missionToJson(m)) == m exactly.
std::string missionToJson(const mission::Mission& m);
// Refuses what could not be read back (a NaN, a waypoint off the globe): "<path>: not saved: <why>".
// writeMissionFile checks it; other writers (the desktop application's QSaveFile) call it first.
Status checkWritable(const mission::Mission& m, const std::string& path);
// Writes atomically: to a temporary file beside `path`, then renames it over `path`.
Status writeMissionFile(const mission::Mission& m, const std::string& path);

} // namespace pf::io
