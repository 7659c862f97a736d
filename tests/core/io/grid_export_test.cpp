// Tests of the grid GeoJSON export: read back with OGR's GeoJSON driver and compared with the grid.
#include "core/io/grid_export.h"

#include "core/geo/polygon_ops.h"

#include <gtest/gtest.h>
#include <ogrsf_frmts.h>

#include <cstdio>
#include <map>
#include <string>

using namespace pf;

namespace {

struct Fixture {
    geo::LocalFrame frame;
    grid::Grid grid;
};

Fixture demoGrid() {
    const geo::GeoPolygon area{{{8.3272608, 49.0109209}, {8.3324653, 49.0108309}, {8.3327392, 49.0123597},
                                {8.3308218, 49.0125396}, {8.3305478, 49.0133489}, {8.3273978, 49.013259}},
                               {}};
    const geo::GeoPolygon warehouse{{{8.3291782, 49.0118201}, {8.3297261, 49.0118201}, {8.3297261, 49.0121799},
                                     {8.3291782, 49.0121799}},
                                    {}};
    auto frame = geo::LocalFrame::forArea(area);
    EXPECT_TRUE(frame.ok());
    auto g = grid::Grid::build(frame->toLocal(area), {frame->toLocal(warehouse)}, grid::GridOptions{25.0, 20.0, 12.0});
    EXPECT_TRUE(g.ok());
    return Fixture{*frame, *g};
}

} // namespace

TEST(GridExport, FeaturesMatchTheGrid) {
    GDALAllRegister();
    const Fixture fx = demoGrid();
    const std::string path = testing::TempDir() + "grid_export_test.geojson";
    ASSERT_TRUE(io::writeGridGeoJson(fx.grid, fx.frame, path).ok());

    GDALDataset* ds = static_cast<GDALDataset*>(GDALOpenEx(path.c_str(), GDAL_OF_VECTOR, nullptr, nullptr, nullptr));
    ASSERT_NE(ds, nullptr);
    OGRLayer* layer = ds->GetLayer(0);
    int features = 0;
    std::map<std::string, int> states;
    for (auto& f : *layer) {
        ++features;
        const int i = f->GetFieldAsInteger("index");
        ASSERT_GE(i, 0);
        ASSERT_LT(i, fx.grid.cellCount());
        EXPECT_EQ(f->GetFieldAsInteger("col"), fx.grid.col(i));
        EXPECT_EQ(f->GetFieldAsInteger("row"), fx.grid.row(i));
        const std::string st = f->GetFieldAsString("state");
        ++states[st];
        EXPECT_EQ(st == "free", fx.grid.state(i) == grid::CellState::Free);
        EXPECT_EQ(st == "shifted", fx.grid.state(i) == grid::CellState::Shifted);
        EXPECT_EQ(st == "unflyable", fx.grid.state(i) == grid::CellState::Unflyable);
        EXPECT_EQ(f->GetFieldAsInteger("contour") != 0, fx.grid.onContour(i));
        // The polygon is the cell in WGS84, within the 1e-8 degree rounding.
        const OGRPolygon* poly = f->GetGeometryRef()->toPolygon();
        const OGRLinearRing* ring = poly->getExteriorRing();
        ASSERT_EQ(ring->getNumPoints(), 5);
        const auto corners = fx.frame.toGeo(fx.grid.cellCorners(i));
        for (int k = 0; k < 4; ++k) {
            EXPECT_NEAR(ring->getX(k), corners[k].lon, 1e-8);
            EXPECT_NEAR(ring->getY(k), corners[k].lat, 1e-8);
        }
        if (fx.grid.needsVisit(i)) {
            const auto fp = fx.frame.toGeo(fx.grid.flightPosition(i));
            EXPECT_NEAR(f->GetFieldAsDouble("flight_lon"), fp.lon, 1e-8);
            EXPECT_NEAR(f->GetFieldAsDouble("flight_lat"), fp.lat, 1e-8);
        } else {
            EXPECT_TRUE(f->IsFieldNull(f->GetFieldIndex("flight_lon")));
        }
    }
    GDALClose(ds);
    int expected = 0;
    for (int i = 0; i < fx.grid.cellCount(); ++i)
        expected += fx.grid.state(i) != grid::CellState::Outside;
    EXPECT_EQ(features, expected);
    EXPECT_EQ(states["free"] + states["shifted"], fx.grid.visitCount());
    EXPECT_GT(states["shifted"] + states["unflyable"], 0); // the warehouse and its 12 m margin
    std::remove(path.c_str());
}

TEST(GridExport, OutsideCellsOnRequestAndMetadata) {
    const Fixture fx = demoGrid();
    const std::string all = io::gridToGeoJson(fx.grid, fx.frame, io::GridExportOptions{true});
    std::size_t n = 0;
    for (std::size_t p = all.find("\"Feature\""); p != std::string::npos; p = all.find("\"Feature\"", p + 1))
        ++n;
    EXPECT_EQ(n, static_cast<std::size_t>(fx.grid.cellCount()));
    EXPECT_NE(all.find("\"outside\""), std::string::npos);
    EXPECT_NE(all.find("\"photoflight_grid\""), std::string::npos);
    EXPECT_NE(all.find("\"cell_size_m\":25.0"), std::string::npos) << all.substr(0, 300);
}

TEST(GridExport, UnwritablePathIsAnError) {
    const Fixture fx = demoGrid();
    const auto s = io::writeGridGeoJson(fx.grid, fx.frame, "/nonexistent-dir/grid.geojson");
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().code, ErrorCode::IoError);
    EXPECT_EQ(s.error().message.rfind("/nonexistent-dir/grid.geojson: cannot write the grid: ", 0), 0u);
}
