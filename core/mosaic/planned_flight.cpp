#include "core/mosaic/planned_flight.h"

#include "core/geo/ogr_adapter.h"
#include "core/geo/gdal_util.h"

#include <ogrsf_frmts.h>

#include <algorithm>
#include <map>
#include <cmath>
#include <filesystem>

namespace pf::mosaic {

namespace {

geo::GeoRing toGeoRing(const geo::Ring& r) {
    geo::GeoRing out;
    out.reserve(r.size());
    for (const auto& p : r)
        out.push_back({p.x(), p.y()});
    return out;
}

// The plan.geojson properties read, by index (-1: absent).
struct PlanFields {
    int kind, aircraft, seq, alt, heading, across, along;
    explicit PlanFields(const OGRFeatureDefn* defn)
        : kind(defn->GetFieldIndex("kind")), aircraft(defn->GetFieldIndex("aircraft")),
          seq(defn->GetFieldIndex("seq")), alt(defn->GetFieldIndex("alt_m")),
          heading(defn->GetFieldIndex("heading_deg")),
          across(defn->GetFieldIndex("footprint_across_m")),
          along(defn->GetFieldIndex("footprint_along_m")) {}
    std::string aircraftOf(OGRFeature& f) const {
        return aircraft >= 0 ? f.GetFieldAsString(aircraft) : "";
    }
    bool hasFootprint(OGRFeature& f) const {
        return across >= 0 && along >= 0 && f.IsFieldSetAndNotNull(across) &&
               f.IsFieldSetAndNotNull(along);
    }
};

// A "photo" feature (featureNo counts from 1, for messages). A photo without its own footprint has
// its aircraft's path's (plan.geojson gives it once).
Result<PlannedPhoto>
readPhoto(OGRFeature& f, const PlanFields& fields,
          const std::map<std::string, std::pair<double, double>>& pathFootprint,
          const std::string& name, int featureNo) {
    const OGRGeometry* g = f.GetGeometryRef();
    const auto* pt = g ? dynamic_cast<const OGRPoint*>(g) : nullptr;
    if (!pt)
        return makeError(ErrorCode::ParseError, name + ": feature " + std::to_string(featureNo) +
                                                    ": a photo must be a Point");
    if (fields.alt < 0 || !f.IsFieldSetAndNotNull(fields.alt))
        return makeError(ErrorCode::ParseError,
                         name + ": feature " + std::to_string(featureNo) + ": photo without alt_m");
    PlannedPhoto p;
    p.aircraft = fields.aircraftOf(f);
    p.seq = fields.seq >= 0 ? f.GetFieldAsInteger(fields.seq) : 0;
    p.position = {pt->getX(), pt->getY()};
    p.altitudeM = f.GetFieldAsDouble(fields.alt);
    p.headingDeg = fields.heading >= 0 ? f.GetFieldAsDouble(fields.heading) : 0.0;
    const bool ownFootprint = fields.hasFootprint(f);
    const auto fp = pathFootprint.find(p.aircraft);
    p.footprintAcrossM = ownFootprint                ? f.GetFieldAsDouble(fields.across)
                         : fp != pathFootprint.end() ? fp->second.first
                                                     : 0.0;
    p.footprintAlongM = ownFootprint                ? f.GetFieldAsDouble(fields.along)
                        : fp != pathFootprint.end() ? fp->second.second
                                                    : 0.0;
    if (!std::isfinite(p.position.lon) || !std::isfinite(p.position.lat) ||
        std::abs(p.position.lat) > 90 || std::abs(p.position.lon) > 180 ||
        !std::isfinite(p.altitudeM) || !(p.altitudeM > 0))
        return makeError(ErrorCode::ParseError, name + ": feature " + std::to_string(featureNo) +
                                                    ": photo position or altitude out of range");
    return p;
}

// Each aircraft's photos in flight order, aircraft in the order they appear.
void sortByAircraft(std::vector<PlannedPhoto>& photos) {
    std::vector<std::string> order;
    for (const auto& p : photos)
        if (std::find(order.begin(), order.end(), p.aircraft) == order.end())
            order.push_back(p.aircraft);
    std::stable_sort(
        photos.begin(), photos.end(), [&](const PlannedPhoto& a, const PlannedPhoto& b) {
            const auto ia = std::find(order.begin(), order.end(), a.aircraft) - order.begin();
            const auto ib = std::find(order.begin(), order.end(), b.aircraft) - order.begin();
            return ia != ib ? ia < ib : a.seq < b.seq;
        });
}

} // namespace

Result<PlannedFlight> readPlannedFlight(const std::string& pathIn) {
    std::filesystem::path path(pathIn);
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        path /= "plan.geojson";
    const std::string name = path.string();
    if (!std::filesystem::is_regular_file(path, ec))
        return makeError(ErrorCode::IoError,
                         name + ": no such file (give the plan's directory or its plan.geojson, "
                                "as written by photoflight-cli plan --out DIR)");
    geo::detail::ensureGdalRegistered();
    geo::detail::GdalErrorCapture errors;
    const char* const drivers[] = {"GeoJSON", nullptr};
    GDALDatasetUniquePtr ds(
        GDALDataset::Open(name.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, drivers));
    if (!ds || ds->GetLayerCount() < 1)
        return makeError(ErrorCode::ParseError,
                         name + ": not a GeoJSON plan" +
                             (errors.message().empty() ? "" : " (" + errors.message() + ")"));
    OGRLayer* layer = ds->GetLayer(0);
    const PlanFields fields(layer->GetLayerDefn());
    if (fields.kind < 0)
        return makeError(ErrorCode::ParseError,
                         name + ": no 'kind' property: not a plan written by photoflight-cli plan");

    PlannedFlight flight;
    flight.source = path.filename().string();
    int featureNo = 0;
    std::map<std::string, std::pair<double, double>> pathFootprint; // aircraft -> across, along
    layer->ResetReading();
    for (auto& f : *layer) {
        ++featureNo;
        const std::string k = f->GetFieldAsString(fields.kind);
        const OGRGeometry* g = f->GetGeometryRef();
        if (k == "photo") {
            auto p = readPhoto(*f, fields, pathFootprint, name, featureNo);
            if (!p)
                return p.error();
            flight.photos.push_back(*p);
        } else if (k == "path" && fields.hasFootprint(*f)) {
            pathFootprint[fields.aircraftOf(*f)] = {f->GetFieldAsDouble(fields.across),
                                                    f->GetFieldAsDouble(fields.along)};
        } else if (k == "subarea" && g) {
            const std::string owner = fields.aircraftOf(*f);
            for (const auto& poly : geo::detail::fromOgr(g)) {
                geo::GeoPolygon gp;
                gp.outer = toGeoRing(poly.outer);
                for (const auto& h : poly.holes)
                    gp.holes.push_back(toGeoRing(h));
                flight.area.push_back(gp);
                flight.areaAircraft.push_back(owner);
            }
        }
    }
    if (flight.photos.empty())
        return makeError(ErrorCode::InvalidInput, name + ": the plan has no photo points");
    sortByAircraft(flight.photos);
    return flight;
}

std::vector<std::string> PlannedFlight::aircraft() const {
    std::vector<std::string> out;
    for (const auto& p : photos)
        if (std::find(out.begin(), out.end(), p.aircraft) == out.end())
            out.push_back(p.aircraft);
    return out;
}

PlannedFlight plannedFlightFromPlan(const mission::MissionPlan& plan) {
    PlannedFlight flight;
    flight.source = "the current plan";
    for (const auto& a : plan.aircraft) {
        int seq = 0;
        for (const auto& w : a.route.waypoints) {
            if (w.kind != route::WaypointKind::Photo)
                continue;
            PlannedPhoto p;
            p.aircraft = a.aircraft;
            p.seq = ++seq;
            p.position = w.position;
            p.altitudeM = w.altitudeM;
            p.headingDeg = w.headingDeg;
            p.footprintAcrossM = a.footprint.real.longSideM;
            p.footprintAlongM = a.footprint.real.shortSideM;
            flight.photos.push_back(p);
        }
        if (plan.frame)
            for (const auto& poly : a.subarea) {
                flight.area.push_back(plan.frame->toGeo(poly));
                flight.areaAircraft.push_back(a.aircraft);
            }
    }
    return flight;
}

} // namespace pf::mosaic
