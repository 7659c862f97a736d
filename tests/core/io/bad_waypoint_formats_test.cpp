#include "core/io/waypoint_formats.h"

#include <gtest/gtest.h>

#include <string>

using namespace pf;

namespace {

std::string fixture(const std::string& name) {
    return std::string(PF_TEST_DATA_DIR) + "/formats/" + name;
}

std::string importError(const std::string& name) {
    auto r = io::importWaypoints(fixture(name));
    EXPECT_FALSE(r.ok()) << name << " was accepted";
    if (r.ok())
        return "";
    EXPECT_EQ(r.error().code, ErrorCode::ParseError) << name;
    return r.error().message;
}

struct BadFile {
    const char* file;
    const char* message; // after "<path>: "
};

class BadWaypointFile : public ::testing::TestWithParam<BadFile> {};

} // namespace

TEST_P(BadWaypointFile, NamesTheFileAndTheLineOrKey) {
    const BadFile& b = GetParam();
    EXPECT_EQ(importError(b.file), fixture(b.file) + ": " + b.message);
}

INSTANTIATE_TEST_SUITE_P(
    Formats, BadWaypointFile,
    ::testing::Values(
        BadFile{"truncated.plan",
                "line 16, column 30: invalid JSON (the file ends before the JSON is complete)"},
        BadFile{"empty.plan", "the file is empty"},
        BadFile{"missing_comma.plan",
                "line 10, column 5: invalid JSON (object value separator ',' expected)"},
        BadFile{"wrong_filetype.plan", "fileType: expected \"Plan\" but found \"Mission\""},
        BadFile{"missing_mission.plan", "mission: missing"},
        BadFile{"missing_params.plan", "mission.items[3].params: missing"},
        BadFile{"six_params.plan", "mission.items[1].params: expected 7 numbers but found 6"},
        BadFile{"non_numeric_param.plan", "mission.items[1].params[4]: expected a number"},
        BadFile{"empty.waypoints", "the file is empty"},
        BadFile{
            "wrong_header.waypoints",
            "line 1: only version 110 of the QGC WPL format is supported (found \"QGC WPL 120\")"},
        BadFile{"not_wpl.waypoints",
                "line 1: expected the header \"QGC WPL 110\" but found \"latitude,longitude\""},
        BadFile{"eleven_fields.waypoints", "line 4: expected 12 tab-separated fields but found 11"},
        BadFile{"non_numeric.waypoints", "line 4: latitude \"49.01l5\" is not a number"},
        BadFile{"empty.csv", "the file is empty"},
        BadFile{"wrong_header.csv",
                "line 1: not a Litchi waypoint CSV: the header has no \"latitude\" column"},
        BadFile{"short_row.csv", "line 3: expected 46 comma-separated fields but found 45"},
        BadFile{"non_numeric.csv", "line 4: column altitude(m): \"forty\" is not a number"},
        BadFile{"empty.geojson", "the file is empty"},
        BadFile{"truncated.geojson",
                "line 5, column 31: invalid JSON (the file ends before the JSON is complete)"},
        BadFile{"missing_altitude.geojson",
                "feature 2 (features[1]): missing property \"altitude_m\""},
        BadFile{"empty.gpx", "the file is empty"},
        BadFile{"missing_ele.gpx", "line 5: route point 2 has no <ele> (altitude above take-off)"}),
    [](const ::testing::TestParamInfo<BadFile>& info) {
        std::string n = info.param.file;
        for (char& c : n)
            if (!std::isalnum(static_cast<unsigned char>(c)))
                c = '_';
        return n;
    });

TEST(BadWaypointFiles, TruncatedGpxNamesTheLine) {
    // The XML parser's own message says where the document stops.
    const std::string msg = importError("truncated.gpx");
    EXPECT_EQ(msg.rfind(fixture("truncated.gpx") + ": ", 0), 0u) << msg;
    EXPECT_NE(msg.find("line 5"), std::string::npos) << msg;
}

TEST(BadWaypointFiles, MissingFileIsAnIoError) {
    auto r = io::importWaypoints(fixture("no_such_file.plan"));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::IoError);
    EXPECT_EQ(r.error().message,
              "cannot open " + fixture("no_such_file.plan") + ": No such file or directory");
}
