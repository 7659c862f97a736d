#include "core/mosaic/mosaic_vectors.h"

#include "core/geo/ogr_adapter.h"
#include "core/geo/polygon_ops.h"
#include "core/geo/gdal_util.h"

#include <ogrsf_frmts.h>

#include <filesystem>

namespace pf::mosaic {

namespace {

struct FieldSpec {
    const char* name;
    OGRFieldType type;
};

OGRLayer* makeLayer(GDALDataset& ds, const char* name, OGRSpatialReference* srs,
                    OGRwkbGeometryType type, std::initializer_list<FieldSpec> fields) {
    OGRLayer* layer = ds.CreateLayer(name, srs, type, nullptr);
    if (!layer)
        return nullptr;
    for (const auto& f : fields) {
        OGRFieldDefn defn(f.name, f.type);
        if (layer->CreateField(&defn) != OGRERR_NONE)
            return nullptr;
    }
    return layer;
}

// The layers of the vector file.
struct Layers {
    OGRLayer* footprints = nullptr;
    OGRLayer* seams = nullptr;
    OGRLayer* gaps = nullptr;
    OGRLayer* cameras = nullptr;
    OGRLayer* missing = nullptr;
    bool ok() const { return footprints && seams && gaps && cameras && missing; }
};

Layers createLayers(GDALDataset& ds, OGRSpatialReference* srs) {
    Layers l;
    l.footprints = makeLayer(ds, "footprints", srs, wkbPolygon,
                             {{"file", OFTString},
                              {"used", OFTInteger},
                              {"status", OFTString},
                              {"planned", OFTString},
                              {"plan_offset_m", OFTReal},
                              {"alt_m", OFTReal},
                              {"yaw_deg", OFTReal},
                              {"pitch_deg", OFTReal},
                              {"roll_deg", OFTReal},
                              {"gsd_m", OFTReal},
                              {"pose_from", OFTString},
                              {"camera", OFTString}});
    l.seams =
        makeLayer(ds, "seams", srs, wkbMultiPolygon, {{"file", OFTString}, {"area_m2", OFTReal}});
    l.gaps = makeLayer(ds, "gaps", srs, wkbPolygon, {{"area_m2", OFTReal}});
    l.cameras = makeLayer(
        ds, "camera_positions", srs, wkbPoint,
        {{"file", OFTString}, {"used", OFTInteger}, {"alt_m", OFTReal}, {"yaw_deg", OFTReal}});
    l.missing = makeLayer(ds, "missing_photos", srs, wkbPoint, {{"planned", OFTString}});
    return l;
}

// A photo's footprint (when it has one), seam (when it has one) and camera position; false when a
// feature could not be written.
bool addPhoto(const Layers& l, const VectorPhoto& p) {
    bool ok = true;
    if (p.footprint.size() >= 3) {
        OGRFeature f(l.footprints->GetLayerDefn());
        f.SetField("file", p.file.c_str());
        f.SetField("used", p.used ? 1 : 0);
        f.SetField("status", p.status.c_str());
        f.SetField("planned", p.planned.c_str());
        if (p.planOffsetM >= 0)
            f.SetField("plan_offset_m", p.planOffsetM);
        f.SetField("alt_m", p.altitudeM);
        f.SetField("yaw_deg", p.yawDeg);
        f.SetField("pitch_deg", p.pitchDeg);
        f.SetField("roll_deg", p.rollDeg);
        f.SetField("gsd_m", p.gsdM);
        f.SetField("pose_from", p.poseFrom.c_str());
        f.SetField("camera", p.cameraName.c_str());
        f.SetGeometryDirectly(geo::detail::toOgr(geo::Polygon{p.footprint, {}}).release());
        if (l.footprints->CreateFeature(&f) != OGRERR_NONE)
            ok = false;
    }
    if (!p.seam.empty()) {
        OGRFeature f(l.seams->GetLayerDefn());
        f.SetField("file", p.file.c_str());
        f.SetField("area_m2", geo::area(p.seam));
        f.SetGeometryDirectly(geo::detail::toOgr(p.seam).release());
        if (l.seams->CreateFeature(&f) != OGRERR_NONE)
            ok = false;
    }
    OGRFeature c(l.cameras->GetLayerDefn());
    c.SetField("file", p.file.c_str());
    c.SetField("used", p.used ? 1 : 0);
    c.SetField("alt_m", p.altitudeM);
    c.SetField("yaw_deg", p.yawDeg);
    c.SetGeometryDirectly(new OGRPoint(p.camera.x(), p.camera.y()));
    if (l.cameras->CreateFeature(&c) != OGRERR_NONE)
        ok = false;
    return ok;
}

// The gaps and the missing photos; false when a feature could not be written.
bool addGapsAndMissing(const Layers& l, const std::vector<geo::Polygon>& gaps,
                       const std::vector<VectorPoint>& missing) {
    bool ok = true;
    for (const auto& g : gaps) {
        OGRFeature f(l.gaps->GetLayerDefn());
        f.SetField("area_m2", geo::area(g));
        f.SetGeometryDirectly(geo::detail::toOgr(g).release());
        if (l.gaps->CreateFeature(&f) != OGRERR_NONE)
            ok = false;
    }
    for (const auto& m : missing) {
        OGRFeature f(l.missing->GetLayerDefn());
        f.SetField("planned", m.label.c_str());
        f.SetGeometryDirectly(new OGRPoint(m.at.x(), m.at.y()));
        if (l.missing->CreateFeature(&f) != OGRERR_NONE)
            ok = false;
    }
    return ok;
}

// Every layer written into a new GeoPackage at `temp` in one transaction.
Status writeLayers(GDALDriver* gpkg, const std::filesystem::path& temp, const std::string& path,
                   const std::string& wkt, const std::vector<VectorPhoto>& photos,
                   const std::vector<geo::Polygon>& gaps, const std::vector<VectorPoint>& missing,
                   geo::detail::GdalErrorCapture& errors) {
    auto failed = [&] {
        return makeError(ErrorCode::IoError,
                         "cannot write " + path + " (" + errors.message() + ")");
    };
    GDALDatasetUniquePtr ds(gpkg->Create(temp.string().c_str(), 0, 0, 0, GDT_Unknown, nullptr));
    if (!ds)
        return failed();
    OGRSpatialReference srs;
    srs.importFromWkt(wkt.c_str());
    srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    const Layers layers = createLayers(*ds, &srs);
    if (!layers.ok())
        return failed();
    bool ok = true;
    ds->StartTransaction();
    for (const auto& p : photos)
        ok = addPhoto(layers, p) && ok;
    ok = addGapsAndMissing(layers, gaps, missing) && ok;
    if (!ok || ds->CommitTransaction() != OGRERR_NONE)
        return failed();
    ds.reset();
    if (errors.failed())
        return failed();
    return {};
}

} // namespace

Status writeMosaicVectors(const std::string& path, const std::string& wkt,
                          const std::vector<VectorPhoto>& photos,
                          const std::vector<geo::Polygon>& gaps,
                          const std::vector<VectorPoint>& missing) {
    geo::detail::ensureGdalRegistered();
    GDALDriver* gpkg = GetGDALDriverManager()->GetDriverByName("GPKG");
    if (!gpkg)
        return makeError(ErrorCode::Unsupported, "this GDAL has no GeoPackage driver");
    const std::filesystem::path final(path);
    const std::filesystem::path temp =
        final.parent_path() / ("." + final.stem().string() + ".partial.gpkg");
    std::error_code ec;
    std::filesystem::remove(temp, ec);
    geo::detail::GdalErrorCapture errors;
    if (Status st = writeLayers(gpkg, temp, path, wkt, photos, gaps, missing, errors); !st) {
        std::filesystem::remove(temp, ec);
        return st;
    }
    std::filesystem::rename(temp, final, ec);
    if (ec) {
        std::filesystem::remove(temp, ec);
        return makeError(ErrorCode::IoError, "cannot write " + path + " (" + ec.message() + ")");
    }
    return {};
}

} // namespace pf::mosaic
