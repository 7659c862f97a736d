// The bad-input corpus: every damaged file and wrong parameter given to photoflight-cli must end with
// exit code 2 and a message on stderr that names the problem; never a crash, never exit code 1.
#include <gtest/gtest.h>

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace {

struct CliRun {
    int code = -1;     // exit code, or -1 when the program did not exit normally
    int signal = 0;    // the signal that ended it (a crash), 0 if none
    std::string err;
};

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Runs photoflight-cli in the test data folder (so arguments stay short); stdout is discarded.
CliRun cli(const std::string& args) {
    static int counter = 0;
    const std::string errPath =
        testing::TempDir() + "pf_corpus_stderr_" + std::to_string(::getpid()) + "_" + std::to_string(++counter);
    const std::string cmd = std::string("cd '") + PF_TEST_DATA_DIR + "' && '" + PF_CLI_PATH + "' " + args +
                            " >/dev/null 2>'" + errPath + "'";
    CliRun r;
    const int status = std::system(cmd.c_str());
    if (WIFEXITED(status)) {
        r.code = WEXITSTATUS(status);
        // The shell reports a child killed by a signal as 128 + signal.
        if (r.code > 128) r.signal = r.code - 128;
    } else if (WIFSIGNALED(status)) {
        r.signal = WTERMSIG(status);
    }
    r.err = slurp(errPath);
    std::remove(errPath.c_str());
    return r;
}

struct BadInput {
    const char* what;    // what is wrong, for the report
    const char* args;    // photoflight-cli arguments, paths relative to tests/data
    const char* message; // a part of the expected message on stderr
};

// Files are under tests/data: corpus/ (written for this test), bad/, import/ and formats/ (shared with
// the reader tests). `good` is cli/good_mission.json, for the parameter rows.
const BadInput kCorpus[] = {
    // --- damaged files ---
    {"empty file", "plan corpus/empty.json", "empty.json: cannot read the file"},
    {"binary garbage", "plan corpus/garbage.bin", "garbage.bin: unsupported or unrecognised format"},
    {"mission cut in half", "plan corpus/truncated_mission.json",
     "truncated_mission.json: not valid JSON: JSON parsing error: the text ends before the JSON is complete at line 54"},
    {"not JSON at all", "plan bad/not_json.json", "not_json.json: not valid JSON"},
    {"byte order mark and NUL byte", "plan corpus/bom_and_nul.json", "bom_and_nul.json: not valid JSON"},
    {"100000 nested arrays", "plan corpus/deep_nesting.json", "deep_nesting.json: not valid JSON: JSON parsing error: nesting too deep"},
    {"JSON array instead of a mission", "plan corpus/top_level_array.json", "top_level_array.json: cannot read the file"},
    {"another program's file", "plan corpus/wrong_format.json",
     "wrong_format.json: format: not a Photoflight mission file (format is \"qgc-plan\", expected \"photoflight-mission\")"},
    {"newer file version", "plan corpus/future_version.json",
     "future_version.json: version: the file has version 99, newer than the version"},
    {"version as text", "plan corpus/version_as_text.json", "version_as_text.json: version: expected a number but found a string"},
    {"missing area", "plan corpus/missing_area.json", "missing_area.json: area: missing required field"},
    {"area of the wrong type", "plan corpus/area_not_object.json", "area_not_object.json: area: expected an object but found a string"},
    {"coordinate as text", "plan corpus/coordinate_as_text.json",
     "coordinate_as_text.json: area.outer[2][0]: expected a number but found a string"},
    {"coordinate with one number", "plan corpus/coordinate_one_number.json",
     "area.outer[2]: expected a [longitude, latitude] array but found 1 values"},
    {"infinite coordinate", "plan corpus/infinite_coordinate.json",
     "infinite_coordinate.json: area.outer[1][0]: expected a finite number but found infinity"},
    {"latitude out of range", "plan bad/area_out_of_range.json", "area.outer[1][1]: latitude 98.3324653 is out of range (-90 to 90)"},
    {"home out of range", "plan corpus/home_out_of_range.json", "home[1]: latitude 149.0 is out of range (-90 to 90)"},
    {"camera named, not described", "plan corpus/unknown_camera.json",
     "unknown_camera.json: aircraft[0].camera: expected an object but found a string"},
    {"camera without field of view", "plan corpus/camera_zero_fov.json",
     "horizontal field of view must be between 0 and 180 degrees, exclusive (got 0 degrees)"},
    {"unknown planner", "plan corpus/unknown_planner.json",
     "planner.planner: unknown planner \"spiral\" (expected auto, sweep, stride, raster, wavefront or lawnmower)"},
    {"negative cell budget", "plan corpus/max_cells_negative.json", "planner.max_cells: value -5 is out of range"},
    // --- hand-edited routes (version 2): the message names the route, its aircraft and the waypoint ---
    {"edited waypoint without altitude", "plan corpus/route_waypoint_no_altitude.json",
     "route_waypoint_no_altitude.json: routes[1] (\"Falcon 8\"): waypoint 12: altitude_m: missing required field"},
    {"edited routes in a version 1 file", "validate corpus/route_in_version_1.json",
     "route_in_version_1.json: routes: hand-edited routes need version 2 of the mission file, but the file says "
     "version 1"},
    {"unknown waypoint kind", "plan corpus/route_unknown_kind.json",
     "routes[0] (\"Test copter\"): waypoint 5: kind: unknown kind \"hover\" (expected photo, turn or transit)"},
    {"waypoint as a bare coordinate", "plan corpus/route_waypoint_not_object.json",
     "routes[0] (\"Test copter\"): waypoint 8: expected an object but found an array"},
    {"routes as an object", "plan corpus/route_not_array.json",
     "route_not_array.json: routes: expected an array but found an object"},
    // --- geometry that cannot be planned ---
    {"self-intersecting area", "plan bad/area_self_intersecting.json", "the area intersects itself: edges 1-2 and 3-4 cross near"},
    {"bow-tie area (GeoJSON)", "plan bad/area_bow_tie.geojson", "the area intersects itself"},
    {"area with two vertices", "plan bad/area_two_vertices.json", "the area has 2 distinct vertices; a polygon needs at least 3"},
    {"area on a line", "plan bad/area_collinear.json", "the area has zero area: all its vertices lie on one line"},
    {"hole outside the area", "plan bad/hole_outside.json", "hole 1 of the area lies outside its outer ring"},
    {"two polygons as the area", "plan bad/area_two_polygons.geojson", "holds 2 polygons, but the area must be a single polygon"},
    {"self-intersecting no-fly zone", "plan bad/nofly_self_intersecting.json", "no-fly zone \"Yard\" intersects itself"},
    {"no-fly zone with two vertices", "plan corpus/nofly_two_vertices.json",
     "no-fly zone \"Warehouse\" has 2 distinct vertices; a polygon needs at least 3"},
    {"no-fly zone covering the area", "plan bad/nofly_covers_area.json",
     "no-fly zone \"Everything\" covers the whole area: nothing admissible is left to photograph"},
    // --- aircraft figures ---
    {"altitude 0 in the file", "plan corpus/altitude_zero.json", "the flight altitude must be greater than 0 m (got 0 m)"},
    {"altitude above the maximum", "plan corpus/altitude_above_max.json",
     "the flight altitude of 500.0 m is above its maximum of 120.0 m"},
    {"GSD 0 in the file", "plan corpus/gsd_zero.json", "the ground sample distance must be greater than 0 cm/px (got 0)"},
    {"negative overlap in the file", "plan corpus/negative_overlap.json", "the side overlap must lie in [0, 1), e.g. 0.7 for 70 % (got -0.2)"},
    {"overlap 1 in the file", "plan corpus/overlap_one.json", "the front overlap must lie in [0, 1), e.g. 0.7 for 70 % (got 1)"},
    // --- areas too large for the cell budget (about 580 million cells: gigabytes of grid) ---
    {"area of 400 x 400 km", "plan corpus/huge_area.json",
     "the area is too large for the cell budget: at 40.0 m (cell size 16.80 m) its grid would need 24,430 x 23,830 = "
     "582,166,900 cells, more than the budget of 4,000,000; an altitude of at least 482.7 m"},
    {"budget of 10 cells", "plan cli/good_mission.json --max-cells 10",
     "more than the budget of 10; an altitude of at least 154.7 m (cell size 133.60 m) would fit"},
    // --- area files ---
    {"damaged KML", "plan import/corrupt.kml", "corrupt.kml: cannot read the file: it is damaged or not a valid KML file"},
    {"damaged GeoPackage", "plan import/corrupt.gpkg", "corrupt.gpkg: cannot read the file: it is damaged or not a valid GeoPackage file"},
    {"points instead of an area", "plan import/points.geojson", "points.geojson: no polygon to import: it has 2 feature(s), only points or lines"},
    {"GeoJSON without features", "plan import/empty.geojson", "empty.geojson: no polygon to import: it has no features"},
    {"text file as an area", "validate import/unsupported.txt", "unsupported.txt: unsupported or unrecognised format"},
    {"missing file", "plan corpus/no_such_file.json", "no_such_file.json: cannot import: the file does not exist"},
    {"a folder", "plan corpus", "corpus: cannot import: this is a folder, not a file"},
    // --- parameters ---
    {"no file", "plan", "no mission or area file given"},
    {"unknown command", "frobnicate", "unknown command 'frobnicate'"},
    {"altitude 0", "plan cli/good_mission.json --altitude 0", "--altitude: must be greater than 0 m (got 0)"},
    {"altitude beyond double", "plan cli/good_mission.json --altitude 1e400", "option --altitude: '1e400' is not a number"},
    {"negative GSD", "plan cli/good_mission.json --gsd -1", "--gsd: must be greater than 0 cm/px (got -1)"},
    {"negative overlap", "plan cli/good_mission.json --overlap -0.1", "--overlap: must be in [0, 1), e.g. 0.7 for 70 % (got -0.1)"},
    {"unknown camera", "plan cli/good_mission.json --camera 'No such camera'",
     "--camera: no camera named 'No such camera' in the catalog"},
    {"output under a file", "plan cli/good_mission.json --out /dev/null/plan", "cannot create the output directory /dev/null/plan"},
    // --- waypoint files and the catalog ---
    {"truncated .plan", "convert formats/truncated.plan /dev/null/x.gpx", "truncated.plan: line 16, column 30: invalid JSON"},
    {"truncated GPX", "convert formats/truncated.gpx /dev/null/x.plan", "truncated.gpx: not a readable GPX file"},
    {"unknown output format", "convert formats/litchi_hub.csv out.xyz", "cannot tell the waypoint format from the extension \".xyz\""},
    {"kmz for a route no DJI aircraft flies", "convert formats/litchi_hub.csv out.kmz",
     "no catalog aircraft flies this route, so the DJI WPML file cannot say which DJI aircraft flies it"},
    // inputs the fuzzers found (undefined behaviour before the fix), kept as regressions
    {"huge MAVLink command", "convert fuzz/regressions/qgc_wpl_huge_frame.waypoints out.gpx",
     "line 2: command \"2222222222222222222222222222222222222222222222222222222222222222222222222222222222216\" is out of range"},
    {"huge Litchi action type", "convert fuzz/regressions/litchi_huge_action_type.csv out.gpx",
     "line 3: expected 46 comma-separated fields but found 34"},
    {"garbage as catalog", "catalog --catalog corpus/garbage.bin", "garbage.bin: not valid JSON"},
    // --- found while checking the exports against their readers (issue 17) ---
    {"GeoJSON waypoint at latitude 91", "convert corpus/waypoints_lat91.geojson corpus/never_written.plan",
     "waypoints_lat91.geojson: feature 1 (features[0]): latitude 91 is out of range (-90 to 90)"},
    {"GPX waypoint with a NaN latitude", "convert corpus/waypoints_nan_lat.gpx corpus/never_written.plan",
     "waypoints_nan_lat.gpx: line 3: waypoint 1: the latitude is not a number"},
    {"two aircraft with one name", "plan corpus/same_aircraft_name.json --format plan --out corpus/never_written",
     "aircraft 2 has the same name as aircraft 1 (\"Test copter\"): give each aircraft its own name"},
    {"altitude far above the ceiling", "plan cli/good_mission.json --altitude 1e9",
     "the flight altitude of 1e+09 m is above its maximum of 120.0 m"},
    {"empty area file", "validate corpus/empty_area.geojson", "empty_area.geojson: cannot read the file: it is empty (0 bytes)"},
    {"both fields of view zero", "plan corpus/camera_no_fov.json",
     "(both fields of view are 0 or missing; each must be between 0 and 180 degrees, exclusive)"},
    {"UTM GeoJSON without a CRS", "validate corpus/utm_no_crs.geojson",
     "are not longitude/latitude; a GeoJSON file without a CRS must be in WGS84: reproject it"},
};

class BadInputCorpus : public testing::TestWithParam<BadInput> {};

TEST_P(BadInputCorpus, ExitsWithCode2AndTheExpectedMessage) {
    const BadInput& c = GetParam();
    SCOPED_TRACE(std::string(c.what) + ": photoflight-cli " + c.args);
    const CliRun r = cli(c.args);
    EXPECT_EQ(r.signal, 0) << "photoflight-cli crashed; stderr: " << r.err;
    EXPECT_EQ(r.code, 2) << "stderr: " << r.err;
    EXPECT_NE(r.err.find("photoflight-cli: error: "), std::string::npos) << "stderr: " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << "expected \"" << c.message << "\"\nstderr: " << r.err;
    // GDAL and PROJ speak only through the product's message.
    EXPECT_EQ(r.err.find("ERROR 1:"), std::string::npos) << "stderr: " << r.err;
}

std::string caseName(const testing::TestParamInfo<BadInput>& info) {
    std::string name;
    for (const char* p = info.param.what; *p; ++p)
        name += std::isalnum(static_cast<unsigned char>(*p)) ? *p : '_';
    return std::to_string(info.index) + "_" + name;
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadInputCorpus, testing::ValuesIn(kCorpus), caseName);

TEST(BadInputCorpus, HasAtLeastThirtyEntries) {
    EXPECT_GE(std::size(kCorpus), 30u);
}

// A no-fly zone outside the area is not an error: it is ignored with a warning, and planning goes on.
TEST(BadInputCorpus, NoFlyZoneOutsideTheAreaIsAWarning) {
    const CliRun r = cli("plan bad/nofly_outside.json");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("warning: no-fly zone \"Far away\" lies entirely outside the area; it is ignored"),
              std::string::npos)
        << r.err;
}

// A mission file with hand-edited routes plans like any other; the user is told once that the
// edited routes are not part of the fresh plan.
TEST(BadInputCorpus, EditedRoutesAreNotedAndNotPlanned) {
    const CliRun r = cli("plan corpus/route_edited_mission.json");
    EXPECT_EQ(r.signal, 0) << r.err;
    EXPECT_EQ(r.code, 0) << r.err;
    const std::string note = "note: the mission file holds 1 hand-edited route; it is not used: this is a fresh plan";
    const auto at = r.err.find(note);
    EXPECT_NE(at, std::string::npos) << r.err;
    EXPECT_EQ(r.err.find(note, at + 1), std::string::npos) << "said more than once:\n" << r.err;
}

// Inputs that were refused with a wrong reason and are read now: a mission saved with a UTF-8
// byte-order mark.
TEST(BadInputCorpus, AMissionWithAByteOrderMarkIsRead) {
    const CliRun r = cli("validate corpus/bom_mission.json");
    EXPECT_EQ(r.signal, 0) << r.err;
    EXPECT_EQ(r.code, 0) << r.err;
}

// Figures the planner cannot use must be refused like the other aircraft figures (a negative cruise
// speed was once accepted and gave negative flight times).
TEST(BadInputCorpus, NegativeCruiseSpeedIsRefused) {
    const CliRun r = cli("plan corpus/speed_negative.json");
    EXPECT_EQ(r.signal, 0) << r.err;
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("cruise speed"), std::string::npos) << r.err;
}

} // namespace
