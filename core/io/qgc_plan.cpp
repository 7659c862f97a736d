#include "core/io/qgc_plan.h"

#include "core/io/waypoint_format_util.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace pf::io {

namespace {

// The kind of aircraft a .plan was written for: its vehicleType (MAV_TYPE: 1 fixed wing, 19 to 25
// VTOL as QGroundControl reads them), else what its items say (kindFromItems).
std::optional<fleet::AircraftKind> planKind(const CPLJSONObject& mission, const std::vector<MissionItem>& items) {
    const int type = mission.GetInteger("vehicleType", 0);
    if (type == 1)
        return fleet::AircraftKind::FixedWing;
    if (type >= 19 && type <= 25)
        return fleet::AircraftKind::Vtol;
    return kindFromItems(items);
}

using detail::parseJson;

CPLJSONArray numbers(std::initializer_list<double> values) {
    CPLJSONArray a;
    for (double v : values)
        a.Add(v);
    return a;
}

// Params as QGroundControl writes them: a NaN ("not used") is null. CPLJSONArray cannot add a
// null, so an array holding nulls is parsed from text (numbers with 17 digits read back exactly).
CPLJSONArray params(const std::array<double, 7>& values) {
    bool allFinite = true;
    for (double v : values)
        allFinite = allFinite && std::isfinite(v);
    CPLJSONArray a;
    if (allFinite) {
        for (double v : values)
            a.Add(v);
        return a;
    }
    std::string text = "[";
    for (std::size_t i = 0; i < values.size(); ++i) {
        char buf[40];
        std::snprintf(buf, sizeof buf, "%.17g", values[i]);
        text += (i ? "," : "") + (std::isfinite(values[i]) ? std::string(buf) : std::string("null"));
    }
    CPLJSONDocument doc;
    if (!doc.LoadMemory(text + "]"))
        return a;
    return doc.GetRoot().ToArray();
}

class ItemWriter {
public:
    explicit ItemWriter(CPLJSONArray& items) : m_items(items) {}

    void add(const MissionItem& it) {
        CPLJSONObject item;
        item.Add("type", "SimpleItem");
        item.Add("command", it.command);
        item.Add("frame", it.frame);
        item.Add("autoContinue", true);
        item.Add("doJumpId", ++m_jumpId);
        item.Add("params", params(it.params));
        if (it.hasPosition()) {
            // The three altitude keys are written together (QGroundControl rejects an item with
            // only some of them); a command without a position has none of them.
            // AltitudeMode as QGroundControl numbers it: 1 relative to home, 2 above sea level
            // (frame 0), 4 terrain frame (frame 10, the vehicle follows its terrain data).
            item.Add("Altitude", it.params[6]);
            item.Add("AltitudeMode", it.frame == mav::kFrameGlobal              ? 2
                                     : it.frame == mav::kFrameGlobalTerrainAlt ? 4
                                                                               : 1);
            item.AddNull("AMSLAltAboveTerrain");
        }
        m_items.Add(item);
    }

private:
    CPLJSONArray& m_items;
    int m_jumpId = 0;
};

} // namespace

Result<std::string> qgcPlanJson(const ExportContext& ctx, std::size_t routeIndex,
                                const ExportOptions& options) {
    auto missionItemList = missionItems(ctx, routeIndex, options);
    if (!missionItemList)
        return missionItemList.error();
    const route::Route& r = ctx.routes[routeIndex];
    const MissionItem home = homeItem(ctx, routeIndex, options);

    CPLJSONObject root;
    root.Add("fileType", "Plan");
    root.Add("version", 1);
    root.Add("groundStation", "Photoflight");

    CPLJSONObject mission;
    mission.Add("version", 2);
    mission.Add("firmwareType", static_cast<int>(options.firmware));
    mission.Add("vehicleType", mavVehicleType(ctx.kindFor(routeIndex))); // MAV_TYPE of the aircraft's kind
    mission.Add("cruiseSpeed", r.cruiseSpeedMps);
    mission.Add("hoverSpeed", options.hoverSpeedMps.value_or(r.cruiseSpeedMps));
    mission.Add("plannedHomePosition", numbers({home.params[4], home.params[5], home.params[6]}));

    CPLJSONArray items;
    ItemWriter w(items);
    for (const auto& it : *missionItemList)
        w.add(it);
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
    for (const auto& p : rallyItems(ctx, routeIndex))
        points.Add(numbers({p.params[4], p.params[5], p.params[6]}));
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
        std::vector<MissionItem> parsed;
        bool speedItem = false;
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
            auto p = numberArray(*paramsV, key + ".params", 7, 7);
            if (!p)
                return p.error();
            MissionItem mi;
            mi.command = cmd->ToInteger();
            mi.frame = frame->ToInteger();
            std::copy(p->begin(), p->end(), mi.params.begin());
            speedItem = speedItem || mi.command == mav::kDoChangeSpeed;
            if (mi.command == mav::kNavWaypoint) {
                const auto& q = mi.params;
                if (!std::isfinite(q[4]) || !std::isfinite(q[5]) || !std::isfinite(q[6]))
                    return keyError(key + ".params",
                                    "the waypoint has no position (latitude, longitude, altitude)");
                if (std::abs(q[4]) > 90 || std::abs(q[5]) > 180)
                    return keyError(key + ".params", "latitude or longitude out of range");
                if (mi.frame == mav::kFrameGlobal)
                    mi.params[6] -= homeAlt;
                else if (mi.frame == mav::kFrameGlobalTerrainAlt)
                    return keyError(key + ".frame",
                                    "frame 10 (altitude above terrain) cannot be read back without the terrain "
                                    "model: export with altitudes above sea level or relative to home");
                else if (mi.frame != mav::kFrameGlobalRelativeAlt && mi.frame != 6 /* relative int */)
                    return keyError(key + ".frame",
                                    "frame " + std::to_string(mi.frame) +
                                        " is not supported (use 3, altitude relative to home)");
                mi.frame = mav::kFrameGlobalRelativeAlt;
            }
            parsed.push_back(mi);
        }
        auto read = routeFromItems(parsed);
        if (!read)
            return keyError("mission.items", read.error().message);
        route::Route r = std::move(*read);
        r.home = out.home;
        out.kinds.push_back(planKind(*mission, parsed));
        out.cameraTiltDeg = cameraTiltFromItems(parsed);
        if (!speedItem)
            r.cruiseSpeedMps = mission->GetDouble("cruiseSpeed", r.cruiseSpeedMps);
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
