// Tests of `photoflight-cli eval --survey` and `eval --generate`: exit codes, output, files written.
#include "tests/core/cli/cli_test_util.h"

#include "core/plan/evaluation.h"

#include <algorithm>
#include <filesystem>

namespace {

using namespace pf::cli::test;

std::string sample(const std::string& name) {
    return std::string("'") + PF_RESOURCES_DIR + "/areas/" + name + ".geojson'";
}

std::filesystem::path freshDir(const std::string& name) {
    const auto dir = std::filesystem::path(testing::TempDir()) / name;
    std::filesystem::remove_all(dir);
    return dir;
}

TEST(CliEvalGenerate, WritesAreaFilesThatEvalReads) {
    const auto dir = freshDir("pf_cli_generate");
    const CliRun r = cli("eval --generate 3 --seed 4 --zones 2-5 --out '" + dir.string() + "'");
    ASSERT_EQ(r.code, 0) << r.err;
    int files = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
        ++files;
        auto a = pf::plan::loadEvalArea(e.path().string());
        ASSERT_TRUE(a.ok()) << a.error().message;
        EXPECT_GE(a->noFly.size(), 2u);
        EXPECT_LE(a->noFly.size(), 5u);
        EXPECT_TRUE(has(r.out, e.path().filename().string())) << r.out;
    }
    EXPECT_EQ(files, 3);
    EXPECT_TRUE(has(r.err, "generated 3 areas (seed 4")) << r.err;
    std::filesystem::remove_all(dir);
}

TEST(CliEvalGenerate, BadOptionsExitWithTwo) {
    expectBadInput("eval --generate 0 --out /tmp/x", "--generate: give the number of areas");
    expectBadInput("eval --generate 3", "give --out DIR");
    expectBadInput("eval --generate 3 --zones 5-2 --out /tmp/x", "--zones: the smallest value comes first");
    expectBadInput("eval --generate 3 --shapes hexagon --out /tmp/x", "--shapes: unknown shape 'hexagon'");
}

TEST(CliEvalSurvey, BadOptionsExitWithTwo) {
    expectBadInput("eval --survey", "no area given");
    expectBadInput("eval --survey --planners foo " + sample("c_l_shape"), "--planners: unknown planner 'foo' (use auto, sweep, stride");
    expectBadInput("eval --survey --planner stride " + sample("c_l_shape"), "the planners with --planners");
    expectBadInput("eval --survey --zones 3 " + sample("c_l_shape"), "--zones: goes with --generate N");
}

// Two generated areas compared with the stride planner: the table, the CSV and the pictures.
TEST(CliEvalSurvey, ComparesGeneratedAreasAndWritesTheFiles) {
    const auto dir = freshDir("pf_cli_survey");
    const CliRun r = cli("eval --survey --generate 2 --seed 5 --zones 0-3 --planners stride --out '" + dir.string() + "'");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(has(r.out, "Median over all 2 areas, planner / lawnmower:")) << r.out;
    EXPECT_TRUE(has(r.out, "flight time (one model, stops included)")) << r.out;
    EXPECT_TRUE(has(r.out, "the same + 3 s per turn")) << r.out;
    EXPECT_TRUE(has(r.out, "gen-s5-001-rectangle")) << r.out;
    const std::string csv = slurp((dir / "survey.csv").string());
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 2 * 2) << csv;
    EXPECT_TRUE(has(csv, ",lawnmower,1,")) << csv;
    EXPECT_TRUE(has(csv, ",stride,1,")) << csv;
    EXPECT_TRUE(std::filesystem::exists(dir / "areas" / "gen-s5-001-rectangle.geojson"));
    if (has(r.out, "PNG picture")) { // builds with Qt draw one picture per area
        int pictures = 0;
        for (const auto& e : std::filesystem::directory_iterator(dir))
            pictures += e.path().extension() == ".png" && std::filesystem::file_size(e.path()) > 1000;
        EXPECT_EQ(pictures, 2);
        EXPECT_TRUE(std::filesystem::exists(dir / "survey_gen-s5-001-rectangle.png"));
    }
    std::filesystem::remove_all(dir);
}

} // namespace
