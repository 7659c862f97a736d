// Catalog: the bundled figures against the papers and published specifications, the search order,
// the user's additions, and errors that name the file and the entry.
#include "core/data_dir.h"
#include "core/io/catalog.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace pf;
using namespace pf::io;

namespace {

const std::string kBundled = std::string(PF_RESOURCES_DIR) + "/catalog.json";

std::string makeTempDir() {
    std::string tmpl = ::testing::TempDir() + "pf_catalog_XXXXXX";
    char* dir = ::mkdtemp(tmpl.data());
    return dir ? std::string(dir) : std::string();
}

void writeText(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

// Sets an environment variable for the lifetime of the object, then restores it.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const std::string& value) : m_name(name) {
        if (const char* old = std::getenv(name))
            m_old = old;
        ::setenv(name, value.c_str(), 1);
    }
    ~ScopedEnv() {
        if (m_old)
            ::setenv(m_name, m_old->c_str(), 1);
        else
            ::unsetenv(m_name);
    }

private:
    const char* m_name;
    std::optional<std::string> m_old;
};

std::string catalogText(const std::string& cameras, const std::string& aircraft) {
    return R"({"format": "photoflight-catalog", "version": 1, "cameras": [)" + cameras + R"(], "aircraft": [)" +
           aircraft + "]}";
}

const char* const kCam = R"({"name": "Cam", "sensor_width_mm": 13.2, "sensor_height_mm": 8.8,
  "focal_length_mm": 8.8, "image_width_px": 5472, "image_height_px": 3648})";
const char* const kPlane = R"({"name": "Plane", "cruise_speed_mps": 10, "turn_rate_deg_s": 90,
  "endurance_min": 25, "max_altitude_m": 120, "default_camera": "Cam"})";

std::string errorOfText(const std::string& text) {
    const std::string dir = makeTempDir();
    const std::string path = dir + "/c.json";
    writeText(path, text);
    auto r = loadCatalog(path);
    std::remove(path.c_str());
    ::rmdir(dir.c_str());
    if (r)
        return "<loaded>";
    // Report relative to the file name so expectations do not depend on the temporary folder.
    std::string msg = r.error().message;
    if (msg.rfind(path, 0) == 0)
        msg = "c.json" + msg.substr(path.size());
    return msg;
}

} // namespace

TEST(Catalog, BundledCatalogHasThePapersCamerasAndAircraft) {
    auto cat = loadCatalog(kBundled);
    ASSERT_TRUE(cat) << cat.error().message;

    const auto* medium = cat->findCamera("GoPro Hero3 Medium");
    const auto* wide = cat->findCamera("gopro hero3 WIDE"); // names are case-insensitive
    ASSERT_TRUE(medium && wide);
    // Paper 004, table II.
    EXPECT_EQ(medium->hfovDeg, 94.4);
    EXPECT_EQ(medium->vfovDeg, 55.0);
    EXPECT_EQ(wide->hfovDeg, 125.3);
    EXPECT_EQ(wide->vfovDeg, 69.5);
    EXPECT_EQ(medium->imageWidthPx, 3840);
    EXPECT_EQ(medium->imageHeightPx, 2880);

    // Paper 001: about 120 x 90 m at 100 m.
    const auto* falconCam = cat->findCamera("Falcon 8 camera");
    ASSERT_TRUE(falconCam);
    auto fp = sensor::footprintAt(*falconCam, 100.0);
    ASSERT_TRUE(fp);
    EXPECT_NEAR(fp->longSideM, 120.0, 1e-9);
    EXPECT_NEAR(fp->shortSideM, 90.0, 1e-9);

    const auto* falcon = cat->findAircraft("Falcon 8");
    ASSERT_TRUE(falcon);
    EXPECT_EQ(falcon->enduranceMin, 20.0); // paper 001
    EXPECT_EQ(falcon->defaultCamera, "Falcon 8 camera");
    const auto* pelican = cat->findAircraft("AscTec Pelican");
    ASSERT_TRUE(pelican);
    EXPECT_EQ(pelican->cruiseSpeedMps, 16.0); // paper 004
    EXPECT_EQ(pelican->turnRateDegS, 60.0);

    int optical = 0;
    for (const auto& c : cat->cameras) {
        EXPECT_TRUE(sensor::validate(c)) << c.name;
        optical += c.hasOptics() ? 1 : 0;
    }
    EXPECT_GE(optical, 4);
    EXPECT_GE(cat->aircraft.size(), 5u);
    for (const auto& a : cat->aircraft) {
        EXPECT_NE(cat->findCamera(a.defaultCamera), nullptr) << a.name << " -> " << a.defaultCamera;
        EXPECT_FALSE(a.notes.empty()) << a.name << " has no note saying where its figures come from";
    }
}

TEST(Catalog, SurveyCameraGsdMatchesPublishedFigures) {
    auto cat = loadCatalog(kBundled);
    ASSERT_TRUE(cat);
    // Phantom 4 Pro: 100 * 13.2 / (8.8 * 5472) = 2.7412 cm/px; DJI publishes H/36.5 = 2.74 cm at 100 m.
    EXPECT_NEAR(*sensor::gsdCmAt(*cat->findCamera("DJI Phantom 4 Pro camera"), 100.0), 100.0 / 36.5, 0.005);
    // RedEdge-MX: 120 * 4.8 / (5.4 * 1280) = 8.33 cm/px; MicaSense publishes 8 cm/px at 120 m.
    EXPECT_NEAR(*sensor::gsdCmAt(*cat->findCamera("MicaSense RedEdge-MX"), 120.0), 8.3333, 1e-4);
    // Zenmuse P1 35 mm: 100 * 35.9 / (35 * 8192) = 1.2521 cm/px.
    EXPECT_NEAR(*sensor::gsdCmAt(*cat->findCamera("DJI Zenmuse P1 35 mm"), 100.0), 1.2521, 1e-4);
}

TEST(Catalog, MergeReplacesByNameAndAppendsTheRest) {
    Catalog base;
    base.cameras.push_back({});
    base.cameras[0].name = "Cam";
    base.cameras[0].hfovDeg = 60;
    fleet::AircraftSpec plane;
    plane.name = "Plane";
    base.aircraft.push_back(plane);

    Catalog extra;
    extra.cameras.push_back({});
    extra.cameras[0].name = "CAM"; // same name, other case: replaces
    extra.cameras[0].hfovDeg = 70;
    extra.cameras.push_back({});
    extra.cameras[1].name = "Other";
    fleet::AircraftSpec mine;
    mine.name = "Mine";
    extra.aircraft.push_back(mine);

    const Catalog merged = mergeCatalogs(base, extra);
    ASSERT_EQ(merged.cameras.size(), 2u);
    EXPECT_EQ(merged.findCamera("cam")->hfovDeg, 70);
    EXPECT_NE(merged.findCamera("Other"), nullptr);
    ASSERT_EQ(merged.aircraft.size(), 2u);
    EXPECT_EQ(merged.findAircraft("Missing"), nullptr);
}

TEST(Catalog, DefaultCatalogFollowsDataDirAndMergesTheUsersCatalog) {
    const std::string dataDir = makeTempDir();
    const std::string userHome = makeTempDir();
    writeText(dataDir + "/catalog.json", catalogText(kCam, kPlane));
    ::mkdir((userHome + "/photoflight").c_str(), 0755);
    writeText(userHome + "/photoflight/catalog.json",
              catalogText(R"({"name": "My cam", "hfov_deg": 80, "vfov_deg": 60, "image_width_px": 4000,
                              "image_height_px": 3000})",
                          R"({"name": "plane", "cruise_speed_mps": 5, "turn_rate_deg_s": 30, "endurance_min": 12,
                              "max_altitude_m": 50, "default_camera": "My cam"})"));
    {
        ScopedEnv data("PHOTOFLIGHT_DATA_DIR", dataDir);
        ScopedEnv xdg("XDG_DATA_HOME", userHome);
        EXPECT_EQ(pf::dataDirectory(), dataDir);
        auto cat = loadDefaultCatalog();
        ASSERT_TRUE(cat) << cat.error().message;
        EXPECT_EQ(cat->cameras.size(), 2u);
        ASSERT_EQ(cat->aircraft.size(), 1u);
        EXPECT_EQ(cat->aircraft[0].cruiseSpeedMps, 5.0); // the user's entry replaced the bundled one
        EXPECT_EQ(cat->aircraft[0].defaultCamera, "My cam");

        // A broken user catalog is reported with its path, not silently ignored.
        writeText(userHome + "/photoflight/catalog.json", catalogText(R"({"name": "Broken"})", ""));
        auto broken = loadDefaultCatalog();
        ASSERT_FALSE(broken);
        EXPECT_EQ(broken.error().message, userHome + "/photoflight/catalog.json: cameras[0] (\"Broken\"): "
                                                     "image_width_px: missing required field");

        // A default camera that exists in neither file.
        writeText(userHome + "/photoflight/catalog.json",
                  catalogText("", R"({"name": "Lost", "cruise_speed_mps": 5, "turn_rate_deg_s": 30,
                                      "endurance_min": 12, "max_altitude_m": 50, "default_camera": "Nowhere"})"));
        auto lost = loadDefaultCatalog();
        ASSERT_FALSE(lost);
        EXPECT_EQ(lost.error().message, userHome + "/photoflight/catalog.json: aircraft \"Lost\": default camera "
                                                   "\"Nowhere\" is not in the catalog");
    }
    std::system(("rm -rf '" + dataDir + "' '" + userHome + "'").c_str());
}

TEST(Catalog, DefaultCatalogFallsBackToTheSourceTree) {
    ScopedEnv data("PHOTOFLIGHT_DATA_DIR", "/nonexistent/photoflight");
    ScopedEnv xdg("XDG_DATA_HOME", "/nonexistent/xdg");
    const std::string dir = pf::dataDirectory();
    ASSERT_FALSE(dir.empty());
    auto cat = loadDefaultCatalog();
    ASSERT_TRUE(cat) << cat.error().message;
    EXPECT_NE(cat->findAircraft("Falcon 8"), nullptr);
}

// ---- bad input: each with the message the user sees ----

TEST(CatalogErrors, MissingFile) {
    auto r = loadCatalog("/nonexistent/catalog.json");
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().message, "/nonexistent/catalog.json: cannot open the catalog: No such file or directory");
}

TEST(CatalogErrors, NotACatalog) {
    EXPECT_EQ(errorOfText("{\"cameras\": []"),
              "c.json: not valid JSON: JSON parsing error: the text ends before the JSON is complete at line 1, column 15");
    EXPECT_EQ(errorOfText(R"({"format": "photoflight-mission", "version": 1})"),
              "c.json: format: not a Photoflight catalog (expected \"format\": \"photoflight-catalog\")");
    EXPECT_EQ(errorOfText(R"({"format": "photoflight-catalog", "version": 3})"),
              "c.json: version: unknown catalog version 3 (expected 1)");
}

TEST(CatalogErrors, EntriesAreNamed) {
    EXPECT_EQ(errorOfText(catalogText(std::string(kCam) + R"(, {"name": "Bad", "sensor_width_mm": "wide"})", "")),
              "c.json: cameras[1] (\"Bad\"): sensor_width_mm: expected a number but found a string");
    EXPECT_EQ(errorOfText(catalogText(R"({"sensor_width_mm": 1})", "")),
              "c.json: cameras[0]: name: missing required field");
    EXPECT_EQ(errorOfText(catalogText(R"({"name": "Zero", "sensor_width_mm": 13.2, "sensor_height_mm": 0,
        "focal_length_mm": 8.8, "image_width_px": 5472, "image_height_px": 3648})", "")),
              "c.json: cameras[0] (\"Zero\"): camera 'Zero': sensor height must be greater than 0 mm (got 0 mm)");
    EXPECT_EQ(errorOfText(catalogText(std::string(kCam) + ", " + kCam, "")),
              "c.json: cameras[1] (\"Cam\"): a camera with this name is listed twice");
    EXPECT_EQ(errorOfText(catalogText(kCam, R"({"name": "Slow", "cruise_speed_mps": 0, "turn_rate_deg_s": 90,
        "endurance_min": 25, "max_altitude_m": 120})")),
              "c.json: aircraft[0] (\"Slow\"): cruise_speed_mps: must be greater than 0");
    EXPECT_EQ(errorOfText(catalogText(kCam, R"({"name": "NoTime", "cruise_speed_mps": 5, "turn_rate_deg_s": 90,
        "max_altitude_m": 120})")),
              "c.json: aircraft[0] (\"NoTime\"): endurance_min: missing required field");
    EXPECT_EQ(
        errorOfText(
            catalogText(kCam, R"({"name": "Typo", "cruise_speed_mps": 5, "turn_rate_deg_s": 90,
        "endurance_min": 25, "max_altitude_m": 120, "default_camer": "Cam"})")),
        "c.json: aircraft[0] (\"Typo\"): default_camer: unknown field (known here: name, kind, "
        "cruise_speed_mps, turn_rate_deg_s, acceleration_mps2, endurance_min, max_altitude_m, "
        "plane, "
        "default_camera)");
    EXPECT_EQ(errorOfText(R"({"format": "photoflight-catalog", "version": 1, "aircraft": {}})"),
              "c.json: aircraft: expected an array but found an object");
}

// ---- photoflight-cli catalog ----

namespace {

struct RunResult {
    int exitCode = -1;
    std::string out;
};

RunResult runCli(const std::string& args) {
    RunResult r;
    const std::string cmd = std::string("'") + PF_CLI_PATH + "' " + args + " 2>&1";
    FILE* p = ::popen(cmd.c_str(), "r");
    if (!p)
        return r;
    char buf[4096];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, p)) > 0)
        r.out.append(buf, n);
    const int status = ::pclose(p);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

} // namespace

TEST(CatalogCli, ListsCamerasAndAircraftInColumns) {
    ScopedEnv xdg("XDG_DATA_HOME", "/nonexistent/xdg"); // no user additions
    const RunResult r = runCli("catalog --catalog '" + kBundled + "'");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    // Falcon 8 camera at 100 m: 120 x 90 m; GSD = 120 m / 4000 px = 3.00 cm/px.
    EXPECT_NE(r.out.find("Falcon 8 camera"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("120.0 x 90.0 m"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("3.00 cm/px"), std::string::npos) << r.out;
    // Phantom 4 Pro camera: 150 x 100 m, 2.74 cm/px.
    EXPECT_NE(r.out.find("13.2 x 8.8 mm, f 8.8 mm"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("150.0 x 100.0 m"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("2.74 cm/px"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("AscTec Pelican"), std::string::npos) << r.out;
    // Columns are aligned: in the aircraft table, "SPEED" starts where every speed starts.
    const auto header = r.out.find("AIRCRAFT");
    ASSERT_NE(header, std::string::npos);
    const auto lineStart = [&](std::size_t pos) { return r.out.rfind('\n', pos) + 1; };
    const std::size_t speedCol = r.out.find("SPEED", header) - header;
    const auto falconLine = r.out.find("\nFalcon 8  ", header) + 1;
    EXPECT_EQ(r.out.find("8 m/s", falconLine) - lineStart(falconLine), speedCol) << r.out;
}

TEST(CatalogCli, JsonOutputIsACatalogThatReadsBackEqual) {
    const RunResult r = runCli("catalog --json --catalog '" + kBundled + "'");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const std::string dir = makeTempDir();
    writeText(dir + "/out.json", r.out);
    auto back = loadCatalog(dir + "/out.json");
    auto bundled = loadCatalog(kBundled);
    ASSERT_TRUE(back) << back.error().message;
    ASSERT_TRUE(bundled);
    EXPECT_EQ(back->cameras, bundled->cameras);
    EXPECT_EQ(back->aircraft, bundled->aircraft);
    std::remove((dir + "/out.json").c_str());
    ::rmdir(dir.c_str());
}

TEST(CatalogCli, BadCatalogAndArguments) {
    RunResult r = runCli("catalog --catalog /nonexistent/c.json");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.out, "photoflight-cli: error: /nonexistent/c.json: cannot open the catalog: No such file or directory\n");
    r = runCli("catalog cameras");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.out, "photoflight-cli: error: catalog: unexpected argument 'cameras' (see --help)\n");
    r = runCli("catalog --help");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.out.rfind("Usage: photoflight-cli catalog", 0), 0u) << r.out;
}
