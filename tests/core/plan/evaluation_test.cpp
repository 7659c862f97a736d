#include "core/mission/evaluation_report.h"
#include "core/mission/planner_kinds.h"
#include "core/plan/evaluation.h"

#include <gtest/gtest.h>

#include <cpl_json.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace pf::plan {
namespace {

const char* const kAreas[] = {"a_concave", "b_teeth", "c_l_shape", "d_nofly", "e_staircase", "f_complex"};

std::string areaPath(const std::string& name) { return std::string(PF_RESOURCES_DIR) + "/areas/" + name + ".geojson"; }

TEST(Evaluation, SampleAreasHaveTheirDrawnCells) {
    for (const char* name : kAreas) {
        auto a = loadEvalArea(areaPath(name));
        ASSERT_TRUE(a.ok()) << a.error().message;
        EXPECT_EQ(a->name, name);
        EXPECT_DOUBLE_EQ(a->cellSizeM, 20.0);
        auto g = evalGrid(*a);
        ASSERT_TRUE(g.ok()) << g.error().message;
        // The file records how many cells were drawn; the grid must have exactly those.
        CPLJSONDocument doc;
        ASSERT_TRUE(doc.Load(areaPath(name)));
        const int drawn = doc.GetRoot().GetArray("features")[0].GetObj("properties").GetInteger("cells");
        EXPECT_EQ(g->visitCount(), drawn) << name;
        EXPECT_GE(drawn, 300) << name;
    }
    auto d = loadEvalArea(areaPath("d_nofly"));
    ASSERT_TRUE(d.ok());
    EXPECT_GE(d->noFly.size(), 4u);
}

TEST(Evaluation, EveryRunCoversEveryCellAndStrideNeverJumps) {
    EvalOptions opt;
    opt.maxStarts = 25;
    opt.planners = {PlannerKind::Stride, PlannerKind::Raster, PlannerKind::Wavefront};
    opt.wavefront.maxCandidates = 2;
    for (const char* name : kAreas) {
        auto a = loadEvalArea(areaPath(name));
        ASSERT_TRUE(a.ok());
        auto g = evalGrid(*a);
        ASSERT_TRUE(g.ok());
        const auto runs = evaluateArea(name, *g, opt);
        EXPECT_EQ(runs.size(), 75u) << name;
        for (const auto& r : runs) {
            EXPECT_TRUE(r.metrics.complete()) << name << " " << mission::plannerKindInfo(r.planner).id << " from " << r.startCell;
            if (r.planner != PlannerKind::Raster) {
                EXPECT_EQ(r.metrics.jumps, 0) << name << " from " << r.startCell;
            }
            EXPECT_TRUE(g->onContour(r.startCell));
        }
        const auto sum = summarise(runs, {3});
        ASSERT_EQ(sum.size(), 3u);
        EXPECT_EQ(sum[0].runs, 25);
        EXPECT_EQ(sum[0].incomplete, 0);
        EXPECT_EQ(sum[0].turnLowerBound, 3);
        EXPECT_LE(sum[0].minTurns, sum[0].avgTurns);
        EXPECT_GE(sum[0].maxTurns, sum[0].avgTurns);
    }
}

// The quality targets the stride planner reaches against the raster baseline (rasterWalk, the
// paper's original algorithm) on the sample areas: no jumps, complete coverage, and no more than 5
// % extra distance on average. The turn target (stride <= 0.7 x raster) is not reached on these
// areas (the raster's jumps cost it no way back); the ratios measured are in docs/planning.md; this
// test guards what holds: about as few turns as the raster without its jumps, and fewer than the
// paper's rules alone.
TEST(Evaluation, StrideDistanceWithinFivePercentOfTheRasterWithoutJumps) {
    EvalOptions opt;
    opt.maxStarts = 40;
    double ratioSum = 0;
    for (const char* name : kAreas) {
        auto a = loadEvalArea(areaPath(name));
        ASSERT_TRUE(a.ok());
        auto g = evalGrid(*a);
        ASSERT_TRUE(g.ok());
        const auto sum = summarise(evaluateArea(name, *g, opt));
        ASSERT_EQ(sum.size(), 2u);
        const EvalSummary& stride = sum[0].planner == PlannerKind::Stride ? sum[0] : sum[1];
        const EvalSummary& raster = sum[0].planner == PlannerKind::Stride ? sum[1] : sum[0];
        EXPECT_EQ(stride.incomplete, 0) << name;
        EXPECT_EQ(raster.incomplete, 0) << name;
        EXPECT_EQ(stride.avgJumps, 0.0) << name;
        ASSERT_GT(raster.avgDistanceM, 0.0);
        const double ratio = stride.avgDistanceM / raster.avgDistanceM;
        EXPECT_LE(ratio, 1.05) << name;
        ratioSum += ratio;
    }
    EXPECT_LE(ratioSum / std::size(kAreas), 1.05);
}

TEST(Evaluation, StrideTurnsNearTheRasterAndBelowThePaperRules) {
    EvalOptions opt;
    opt.maxStarts = 40;
    opt.planners = {PlannerKind::Stride, PlannerKind::Raster};
    EvalOptions paper = opt;
    paper.planners = {PlannerKind::Stride};
    paper.strideVariants = false;
    double ratioSum = 0, paperSum = 0;
    for (const char* name : kAreas) {
        auto a = loadEvalArea(areaPath(name));
        ASSERT_TRUE(a.ok());
        auto g = evalGrid(*a);
        ASSERT_TRUE(g.ok());
        const auto sum = summarise(evaluateArea(name, *g, opt));
        const auto rules = summarise(evaluateArea(name, *g, paper));
        ASSERT_EQ(sum.size(), 2u);
        ASSERT_EQ(rules.size(), 1u);
        const EvalSummary& stride = sum[0].planner == PlannerKind::Stride ? sum[0] : sum[1];
        const EvalSummary& raster = sum[0].planner == PlannerKind::Stride ? sum[1] : sum[0];
        EXPECT_EQ(stride.avgJumps, 0.0) << name;
        EXPECT_LE(stride.avgTurns, rules[0].avgTurns) << name;
        EXPECT_LE(stride.maxTurns, rules[0].maxTurns) << name;
        ratioSum += stride.avgTurns / raster.avgTurns;
        paperSum += rules[0].avgTurns / raster.avgTurns;
    }
    const double n = static_cast<double>(std::size(kAreas));
    EXPECT_LE(ratioSum / n, 1.02);
    EXPECT_LE(ratioSum / n, paperSum / n - 0.2) << "the variants must save a real share of the paper's turns";
}

TEST(Evaluation, CsvAndTable) {
    auto a = loadEvalArea(areaPath("c_l_shape"));
    ASSERT_TRUE(a.ok());
    auto g = evalGrid(*a);
    ASSERT_TRUE(g.ok());
    EvalOptions opt;
    opt.maxStarts = 4;
    const auto runs = evaluateArea("L", *g, opt);
    const std::string csv = mission::evalCsv(runs);
    EXPECT_EQ(csv.rfind("area,planner,start_cell,start_col,start_row,cells,visited,turns,", 0), 0u);
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 9);
    const std::string table = mission::evalTable(summarise(runs));
    EXPECT_NE(table.find("stride / raster"), std::string::npos);
    EXPECT_NE(table.find("mean of areas"), std::string::npos);
}

class BadAreaFile : public ::testing::Test {
protected:
    std::string write(const std::string& text) {
        const auto p = std::filesystem::temp_directory_path() /
                       ("pf_eval_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
                        std::to_string(m_count++) + ".geojson");
        std::ofstream(p) << text;
        m_files.push_back(p);
        return p.string();
    }
    ~BadAreaFile() override {
        for (const auto& f : m_files)
            std::filesystem::remove(f);
    }
    std::vector<std::filesystem::path> m_files;
    int m_count = 0;
};

TEST_F(BadAreaFile, Messages) {
    auto r = loadEvalArea("/nonexistent/area.geojson");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().message, "cannot read the area file /nonexistent/area.geojson (missing or not JSON)");

    std::string p = write(R"({"type": "Feature"})");
    r = loadEvalArea(p);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().message, p + ": not a GeoJSON FeatureCollection");

    p = write(R"({"type": "FeatureCollection", "features": []})");
    r = loadEvalArea(p);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().message, p + ": no feature has the role \"area\"");

    const std::string square = R"("geometry": {"type": "Polygon", "coordinates": [[[8.33, 49.02], [8.331, 49.02], [8.331, 49.021], [8.33, 49.02]]]})";
    p = write(R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"role": "lake"}, )" +
              square + "}]}");
    r = loadEvalArea(p);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().message,
              p + ": feature 1: the property \"role\" must be \"area\" or \"nofly\" (got \"lake\")");

    p = write(R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"role": "area"},
              "geometry": {"type": "Point", "coordinates": [8.33, 49.02]}}]})");
    r = loadEvalArea(p);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().message, p + ": feature 1 is not a Polygon");

    p = write(R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"role": "area",
              "cell_size_m": -5}, )" + square + "}]}");
    r = loadEvalArea(p);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().message, p + ": cell_size_m must be a positive number of metres");
}

} // namespace
} // namespace pf::plan
