#include "core/io/qgc_plan.h"

#include "core/io/waypoint_format_util.h"

#include <cmath>
#include <limits>

namespace pf::io {

namespace {

using detail::parseJson;

CPLJSONArray numbers(std::initializer_list<double> values) {
    CPLJSONArray a;
    for (double v : values)
        a.Add(v);
    return a;
}

class ItemWriter {
public:
    explicit ItemWriter(CPLJSONArray& items) : m_items(items) {}

    // A command at a position: the three altitude keys are written together (QGroundControl
    // rejects an item with only some of them).
    void navigation(int command, double p1, double p2, double p3, double yaw, geo::LonLat at,
                    double altitudeM) {
        CPLJSONObject item = base(command, mav::kFrameGlobalRelativeAlt);
        item.Add("params", numbers({p1, p2, p3, yaw, at.lat, at.lon, altitudeM}));
        item.Add("Altitude", altitudeM);
        item.Add("AltitudeMode", 1); // relative to home
        item.AddNull("AMSLAltAboveTerrain");
        m_items.Add(item);
    }

    // A command without a position: no altitude keys at all.
    void action(int command, std::initializer_list<double> params) {
        CPLJSONObject item = base(command, mav::kFrameMission);
        item.Add("params", numbers(params));
        m_items.Add(item);
    }

private:
    CPLJSONObject base(int command, int frame) {
        CPLJSONObject item;
        item.Add("type", "SimpleItem");
        item.Add("command", command);
        item.Add("frame", frame);
        item.Add("autoContinue", true);
        item.Add("doJumpId", ++m_jumpId);
        return item;
    }

    CPLJSONArray& m_items;
    int m_jumpId = 0;
};

} // namespace

Result<std::string> qgcPlanJson(const ExportContext& ctx, std::size_t routeIndex,
                                const ExportOptions& options) {
    if (routeIndex >= ctx.routes.size())
        return makeError(ErrorCode::InvalidInput,
                         "there is no route " + std::to_string(routeIndex + 1) + " to export");
    const route::Route& r = ctx.routes[routeIndex];
    const std::string label = ctx.routeLabel(routeIndex);
    if (r.waypoints.empty())
        return makeError(ErrorCode::InvalidInput, label + ": the route has no waypoints to export");
    const geo::LonLat home = ctx.homeFor(routeIndex).value_or(r.waypoints.front().position);
    const geo::LonLat landing = ctx.landingFor(routeIndex).value_or(home);

    CPLJSONObject root;
    root.Add("fileType", "Plan");
    root.Add("version", 1);
    root.Add("groundStation", "Photoflight");

    CPLJSONObject mission;
    mission.Add("version", 2);
    mission.Add("firmwareType", static_cast<int>(options.firmware));
    mission.Add("vehicleType", 2); // MAV_TYPE_QUADROTOR: every catalog aircraft is a multirotor
    mission.Add("cruiseSpeed", r.cruiseSpeedMps);
    mission.Add("hoverSpeed", options.hoverSpeedMps.value_or(r.cruiseSpeedMps));
    mission.Add("plannedHomePosition", numbers({home.lat, home.lon, 0.0}));

    CPLJSONArray items;
    ItemWriter w(items);
    const route::Waypoint& first = r.waypoints.front();
    w.navigation(mav::kNavTakeoff, 0, 0, 0, first.headingDeg, home, first.altitudeM);
    for (const auto& wp : r.waypoints) {
        w.navigation(mav::kNavWaypoint, 0, 0, 0, detail::normaliseHeading(wp.headingDeg),
                     wp.position, wp.altitudeM);
        if (wp.kind != route::WaypointKind::Photo)
            continue;
        if (options.capture == CaptureCommand::ImageStartCapture)
            w.action(mav::kImageStartCapture, {0, 0, 1, 0, 0, 0, 0}); // all cameras, one image
        else
            w.action(mav::kDoDigicamControl, {0, 0, 0, 0, 1, 0, 0}); // param 5 = 1: shoot
    }
    if (options.end == MissionEnd::ReturnToLaunch)
        w.action(mav::kNavReturnToLaunch, {0, 0, 0, 0, 0, 0, 0});
    else
        w.navigation(mav::kNavLand, 0, 0, 0, r.waypoints.back().headingDeg, landing, 0.0);
    mission.Add("items", items);
    root.Add("mission", mission);

    CPLJSONObject fence;
    fence.Add("version", 2);
    CPLJSONArray polygons;
    for (const auto& z : ctx.mission.noFlyZones) {
        CPLJSONObject p;
        p.Add("inclusion", false);
        p.Add("version", 1);
        CPLJSONArray ring;
        for (const auto& v : z.polygon.outer)
            ring.Add(numbers({v.lat, v.lon}));
        p.Add("polygon", ring);
        polygons.Add(p);
    }
    fence.Add("polygons", polygons);
    fence.Add("circles", CPLJSONArray());
    root.Add("geoFence", fence);

    CPLJSONObject rally;
    rally.Add("version", 2);
    CPLJSONArray points;
    points.Add(numbers({home.lat, home.lon, 0.0}));
    rally.Add("points", points);
    root.Add("rallyPoints", rally);

    CPLJSONDocument doc;
    doc.SetRoot(root);
    return doc.SaveAsString();
}

Status writeQgcPlan(const ExportContext& ctx, std::size_t routeIndex, const std::string& path,
                    const ExportOptions& options) {
    auto text = qgcPlanJson(ctx, routeIndex, options);
    if (!text)
        return text.error();
    return detail::writeTextFile(path, *text);
}

namespace {

class PlanReader {
public:
    explicit PlanReader(std::string source) : m_src(std::move(source)) {}

    Error keyError(const std::string& key, const std::string& what) const {
        return makeError(ErrorCode::ParseError, m_src + ": " + key + ": " + what);
    }

    // A required member of the given type.
    Result<CPLJSONObject> member(const CPLJSONObject& obj, const std::string& parent,
                                 const std::string& name, CPLJSONObject::Type type,
                                 const char* typeName) const {
        const std::string key = parent.empty() ? name : parent + "." + name;
        CPLJSONObject v = obj.GetObj(name);
        if (!v.IsValid())
            return keyError(key, "missing");
        const auto t = v.GetType();
        const bool numeric = type == CPLJSONObject::Type::Double &&
                             (t == CPLJSONObject::Type::Integer || t == CPLJSONObject::Type::Long);
        if (t != type && !numeric)
            return keyError(key, std::string("expected ") + typeName);
        return v;
    }

    // Numbers of an array; null (QGroundControl's NaN) reads as NaN.
    Result<std::vector<double>> numberArray(const CPLJSONObject& v, const std::string& key,
                                            std::size_t minSize, std::size_t maxSize) const {
        if (v.GetType() != CPLJSONObject::Type::Array)
            return keyError(key, "expected an array of numbers");
        const CPLJSONArray a = v.ToArray();
        const auto n = static_cast<std::size_t>(a.Size());
        if (n < minSize || n > maxSize)
            return keyError(key, "expected " +
                                     (minSize == maxSize ? std::to_string(minSize)
                                                         : std::to_string(minSize) + " to " +
                                                               std::to_string(maxSize)) +
                                     " numbers but found " + std::to_string(n));
        std::vector<double> out;
        for (int i = 0; i < a.Size(); ++i) {
            const CPLJSONObject e = a[i];
            const auto t = e.GetType();
            if (t == CPLJSONObject::Type::Null)
                out.push_back(std::numeric_limits<double>::quiet_NaN());
            else if (t == CPLJSONObject::Type::Double || t == CPLJSONObject::Type::Integer ||
                     t == CPLJSONObject::Type::Long)
                out.push_back(e.ToDouble());
            else
                return keyError(key + "[" + std::to_string(i) + "]", "expected a number");
        }
        return out;
    }

    Result<ImportedWaypoints> read(const CPLJSONObject& root) const {
        using T = CPLJSONObject::Type;
        auto fileType = member(root, "", "fileType", T::String, "a string");
        if (!fileType)
            return fileType.error();
        if (fileType->ToString() != "Plan")
            return keyError("fileType",
                            "expected \"Plan\" but found \"" + fileType->ToString() + "\"");
        for (const char* key : {"version", "groundStation", "geoFence", "rallyPoints"})
            if (!root.GetObj(key).IsValid())
                return keyError(key, "missing");
        auto mission = member(root, "", "mission", T::Object, "an object");
        if (!mission)
            return mission.error();
        auto version = member(*mission, "mission", "version", T::Integer, "an integer");
        if (!version)
            return version.error();
        if (version->ToInteger() != 2)
            return keyError("mission.version", "only mission version 2 is supported (found " +
                                                   std::to_string(version->ToInteger()) + ")");
        auto homeV = member(*mission, "mission", "plannedHomePosition", T::Array, "an array");
        if (!homeV)
            return homeV.error();
        auto home = numberArray(*homeV, "mission.plannedHomePosition", 3, 3);
        if (!home)
            return home.error();
        auto itemsV = member(*mission, "mission", "items", T::Array, "an array");
        if (!itemsV)
            return itemsV.error();

        ImportedWaypoints out;
        const double homeAlt = std::isfinite((*home)[2]) ? (*home)[2] : 0.0;
        if (std::isfinite((*home)[0]) && std::isfinite((*home)[1]))
            out.home = geo::LonLat{(*home)[1], (*home)[0]};
        route::Route r;
        r.home = out.home;
        r.cruiseSpeedMps = mission->GetDouble("cruiseSpeed", r.cruiseSpeedMps);
        std::vector<bool> photo;
        const CPLJSONArray items = itemsV->ToArray();
        for (int i = 0; i < items.Size(); ++i) {
            const std::string key = "mission.items[" + std::to_string(i) + "]";
            const CPLJSONObject item = items[i];
            if (item.GetType() != T::Object)
                return keyError(key, "expected an object");
            auto type = member(item, key, "type", T::String, "a string");
            if (!type)
                return type.error();
            if (type->ToString() != "SimpleItem")
                return keyError(key + ".type",
                                "a \"" + type->ToString() +
                                    "\" item (survey or pattern) cannot be edited as waypoints; "
                                    "convert it to waypoints in QGroundControl first");
            auto cmd = member(item, key, "command", T::Integer, "an integer");
            if (!cmd)
                return cmd.error();
            auto frame = member(item, key, "frame", T::Integer, "an integer");
            if (!frame)
                return frame.error();
            for (const char* k : {"autoContinue", "doJumpId"})
                if (!item.GetObj(k).IsValid())
                    return keyError(key + "." + k, "missing");
            auto paramsV = member(item, key, "params", T::Array, "an array");
            if (!paramsV)
                return paramsV.error();
            auto params = numberArray(*paramsV, key + ".params", 7, 7);
            if (!params)
                return params.error();
            const int command = cmd->ToInteger();
            if (command == mav::kImageStartCapture || command == mav::kDoDigicamControl) {
                if (!photo.empty())
                    photo.back() = true;
                continue;
            }
            if (command != mav::kNavWaypoint)
                continue; // take-off, return, land and settings are regenerated on export
            const auto& p = *params;
            if (!std::isfinite(p[4]) || !std::isfinite(p[5]) || !std::isfinite(p[6]))
                return keyError(key + ".params",
                                "the waypoint has no position (latitude, longitude, altitude)");
            if (std::abs(p[4]) > 90 || std::abs(p[5]) > 180)
                return keyError(key + ".params", "latitude or longitude out of range");
            double alt = p[6];
            if (frame->ToInteger() == mav::kFrameGlobal)
                alt -= homeAlt;
            else if (frame->ToInteger() != mav::kFrameGlobalRelativeAlt &&
                     frame->ToInteger() != 6 /* relative int */)
                return keyError(key + ".frame",
                                "frame " + std::to_string(frame->ToInteger()) +
                                    " is not supported (use 3, altitude relative to home)");
            route::Waypoint wp;
            wp.position = {p[5], p[4]};
            wp.altitudeM = alt;
            wp.headingDeg = std::isfinite(p[3])
                                ? detail::normaliseHeading(p[3])
                                : (r.waypoints.empty() ? 0.0 : r.waypoints.back().headingDeg);
            r.waypoints.push_back(wp);
            photo.push_back(false);
        }
        detail::inferNonPhotoKinds(r.waypoints, photo);
        out.routes.push_back(std::move(r));

        const CPLJSONObject fence = root.GetObj("geoFence");
        const CPLJSONArray polys = fence.GetArray("polygons");
        for (int i = 0; polys.IsValid() && i < polys.Size(); ++i) {
            const std::string key = "geoFence.polygons[" + std::to_string(i) + "]";
            const CPLJSONObject poly = polys[i];
            if (poly.GetBool("inclusion", true))
                continue; // an inclusion fence is not a no-fly zone
            const CPLJSONArray pts = poly.GetArray("polygon");
            if (!pts.IsValid())
                return keyError(key + ".polygon", "missing");
            mission::NoFlyZone z;
            z.name = "Geofence " + std::to_string(i + 1);
            for (int k = 0; k < pts.Size(); ++k) {
                auto ll = numberArray(pts[k], key + ".polygon[" + std::to_string(k) + "]", 2, 2);
                if (!ll)
                    return ll.error();
                z.polygon.outer.push_back({(*ll)[1], (*ll)[0]});
            }
            out.noFlyZones.push_back(std::move(z));
        }
        return out;
    }

private:
    std::string m_src;
};

} // namespace

Result<ImportedWaypoints> parseQgcPlan(const std::string& text, const std::string& source) {
    auto root = parseJson(text, source);
    if (!root)
        return root.error();
    return PlanReader(source).read(*root);
}

Result<ImportedWaypoints> readQgcPlan(const std::string& path) {
    auto text = detail::readTextFile(path);
    if (!text)
        return text.error();
    return parseQgcPlan(*text, path);
}

} // namespace pf::io
