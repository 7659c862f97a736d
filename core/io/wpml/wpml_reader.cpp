// Reading a DJI WPML .kmz back: the waylines of wpmz/waylines.wpml (the file the aircraft executes)
// as routes, with the take-off reference point of wpmz/template.kml.
#include "core/geo/geodesic.h"
#include "core/io/waypoint_format_util.h"
#include "core/io/wpml/kmz_archive.h"
#include "core/io/wpml/wayline.h"
#include "core/io/wpml/wpml_enums.h"
#include "core/io/wpml_kmz.h"

#include <cpl_error.h>
#include <cpl_minixml.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

namespace pf::io {

namespace {

using detail::parseNumber;
using detail::splitChar;
using detail::trim;

constexpr const char* kWaylines = "wpmz/waylines.wpml";
constexpr const char* kTemplate = "wpmz/template.kml";
constexpr const char* kWpmlNamespacePrefix = "http://www.dji.com/wpmz/";

struct TreeDeleter {
    void operator()(CPLXMLNode* n) const { CPLDestroyXMLNode(n); }
};
using Tree = std::unique_ptr<CPLXMLNode, TreeDeleter>;

// A parsed document with the prefix its root binds to DJI's WPML namespace ("wpml" in DJI's files).
struct WpmlXml {
    Tree tree;
    const CPLXMLNode* document = nullptr;
    std::string prefix;

    // The first child element `wpml:<local>` (or a KML element when `local` has no prefix).
    const CPLXMLNode* child(const CPLXMLNode* n, const std::string& local, bool wpml = true) const {
        const std::string name = wpml ? prefix + ":" + local : local;
        for (const CPLXMLNode* c = n ? n->psChild : nullptr; c; c = c->psNext)
            if (c->eType == CXT_Element && name == c->pszValue)
                return c;
        return nullptr;
    }
    std::vector<const CPLXMLNode*> children(const CPLXMLNode* n, const std::string& local,
                                            bool wpml) const {
        const std::string name = wpml ? prefix + ":" + local : local;
        std::vector<const CPLXMLNode*> out;
        for (const CPLXMLNode* c = n ? n->psChild : nullptr; c; c = c->psNext)
            if (c->eType == CXT_Element && name == c->pszValue)
                out.push_back(c);
        return out;
    }
    // The first element `wpml:<local>` anywhere below n, depth first.
    const CPLXMLNode* find(const CPLXMLNode* n, const std::string& local) const {
        for (const CPLXMLNode* c = n ? n->psChild : nullptr; c; c = c->psNext) {
            if (c->eType != CXT_Element)
                continue;
            if (prefix + ":" + local == c->pszValue)
                return c;
            if (const CPLXMLNode* below = find(c, local))
                return below;
        }
        return nullptr;
    }
    static std::string text(const CPLXMLNode* n) {
        std::string s;
        for (const CPLXMLNode* c = n ? n->psChild : nullptr; c; c = c->psNext)
            if (c->eType == CXT_Text)
                s += c->pszValue;
        return std::string(trim(s));
    }
    std::optional<double> number(const CPLXMLNode* n, const std::string& local) const {
        const CPLXMLNode* c = child(n, local);
        return c ? parseNumber(text(c)) : std::nullopt;
    }
    std::string string(const CPLXMLNode* n, const std::string& local) const {
        return text(child(n, local));
    }
};

Result<WpmlXml> parseWpml(const std::string& xml, const std::string& where) {
    WpmlXml out;
    CPLErrorReset();
    CPLPushErrorHandler(CPLQuietErrorHandler);
    out.tree.reset(CPLParseXMLString(xml.c_str()));
    const std::string why = CPLGetLastErrorMsg();
    CPLPopErrorHandler();
    if (!out.tree)
        return makeError(ErrorCode::ParseError, where + " is not well-formed XML" +
                                                    (why.empty() ? std::string() : ": " + why));
    const CPLXMLNode* kml = nullptr;
    for (const CPLXMLNode* n = out.tree.get(); n; n = n->psNext)
        if (n->eType == CXT_Element && std::string(n->pszValue) == "kml")
            kml = n;
    if (!kml)
        return makeError(ErrorCode::ParseError,
                         where + " is not a KML document (no <kml> element)");
    for (const CPLXMLNode* a = kml->psChild; a; a = a->psNext) {
        const std::string name = a->pszValue;
        if (a->eType == CXT_Attribute && name.rfind("xmlns:", 0) == 0 &&
            WpmlXml::text(a).rfind(kWpmlNamespacePrefix, 0) == 0)
            out.prefix = name.substr(6);
    }
    if (out.prefix.empty())
        return makeError(ErrorCode::ParseError, where + " does not declare DJI's WPML namespace (" +
                                                    std::string(kWpmlNamespacePrefix) +
                                                    "1.0.x): not a DJI WPML file");
    out.document = out.child(kml, "Document", false);
    if (!out.document)
        return makeError(ErrorCode::ParseError, where + " has no <Document>");
    return out;
}

// "longitude,latitude" (a third value, if any, is ignored: heights are in their own elements).
std::optional<geo::LonLat> coordinates(const std::string& text) {
    const auto parts = splitChar(trim(text), ',');
    if (parts.size() < 2)
        return std::nullopt;
    auto lon = parseNumber(parts[0]), lat = parseNumber(parts[1]);
    if (!lon || !lat || std::abs(*lon) > 180 || std::abs(*lat) > 90)
        return std::nullopt;
    return geo::LonLat{*lon, *lat};
}

// The take-off reference point of template.kml: "latitude,longitude,ellipsoidal height".
struct RefPoint {
    geo::LonLat position;
    double ellipsoidHeightM = 0.0;
};
std::optional<RefPoint> takeOffRefPoint(const std::string& archive) {
    auto text = wpml::readZipArchiveFile(archive, kTemplate);
    if (!text)
        return std::nullopt;
    auto xml = parseWpml(*text, archive + ": " + kTemplate);
    if (!xml)
        return std::nullopt;
    const std::string value =
        xml->string(xml->child(xml->document, "missionConfig"), "takeOffRefPoint");
    const auto parts = splitChar(value, ',');
    if (parts.size() != 3)
        return std::nullopt;
    auto lat = parseNumber(parts[0]), lon = parseNumber(parts[1]), h = parseNumber(parts[2]);
    if (!lat || !lon || !h || std::abs(*lon) > 180 || std::abs(*lat) > 90)
        return std::nullopt;
    return RefPoint{{*lon, *lat}, *h};
}

struct RawPoint {
    route::Waypoint waypoint;
    double height = 0.0;
    std::optional<double> headingDeg;
};

// A wayline's photos: at reachPoint photo waypoints, and every `spacing` metres of a distance
// (or time x speed) trigger from its start waypoint to its end waypoint.
struct PhotoPlan {
    std::vector<bool> at;                      // a photo on reaching waypoint i
    std::vector<std::vector<double>> interior; // distances along segment i -> i + 1
};

bool hasTakePhoto(const WpmlXml& x, const CPLXMLNode* group) {
    for (const CPLXMLNode* a : x.children(group, "action", true))
        if (x.string(a, "actionActuatorFunc") == "takePhoto")
            return true;
    return false;
}

void addDistancePhotos(PhotoPlan& plan, const std::vector<RawPoint>& pts, std::size_t s,
                       std::size_t e, double d) {
    std::vector<double> c{0.0};
    for (std::size_t j = s; j < e; ++j)
        c.push_back(c.back() +
                    geo::geodesicDistance(pts[j].waypoint.position, pts[j + 1].waypoint.position));
    const double len = c.back();
    double n = std::floor(len / d + 1e-9);
    // A spacing written rounded (Photoflight: down to a micrometre) that divides the length into a
    // whole number of intervals: those intervals exactly, as the plan placed them.
    if (const double m = std::round(len / d); m >= 1 && std::abs(len / d - m) < 1e-3) {
        n = m;
        d = len / m;
    }
    constexpr double kSameM = 0.01;
    for (double k = 0; k <= n; ++k) {
        const double at = k * d;
        std::size_t j = 0;
        while (j + 1 < c.size() - 1 && c[j + 1] <= at + kSameM)
            ++j;
        if (std::abs(at - c[j]) <= kSameM)
            plan.at[s + j] = true;
        else if (std::abs(at - c[j + 1]) <= kSameM)
            plan.at[s + j + 1] = true;
        else
            plan.interior[s + j].push_back(at - c[j]);
    }
}

Result<PhotoPlan> photoPlan(const WpmlXml& x, const std::vector<const CPLXMLNode*>& placemarks,
                            const std::vector<RawPoint>& pts, const std::string& where) {
    PhotoPlan plan{std::vector<bool>(pts.size(), false),
                   std::vector<std::vector<double>>(pts.size())};
    for (const CPLXMLNode* pm : placemarks)
        for (const CPLXMLNode* g : x.children(pm, "actionGroup", true)) {
            if (!hasTakePhoto(x, g))
                continue;
            const auto s = x.number(g, "actionGroupStartIndex"),
                       e = x.number(g, "actionGroupEndIndex");
            if (!s || !e || *s < 0 || *e < *s || *e >= static_cast<double>(pts.size()))
                return makeError(ErrorCode::ParseError,
                                 where + ": an action group's start or end index is not a "
                                         "waypoint of its wayline");
            const CPLXMLNode* trigger = x.child(g, "actionTrigger");
            const std::string type = x.string(trigger, "actionTriggerType");
            const auto param = x.number(trigger, "actionTriggerParam");
            const auto start = static_cast<std::size_t>(*s), end = static_cast<std::size_t>(*e);
            if (type == "multipleDistance" || type == "multipleTiming") {
                const double speed = x.number(pm, "waypointSpeed").value_or(0.0);
                const double d =
                    type == "multipleDistance" ? param.value_or(0) : param.value_or(0) * speed;
                if (!(d > 0))
                    return makeError(ErrorCode::ParseError,
                                     where + ": a " + type +
                                         " photo trigger without a "
                                         "positive interval (actionTriggerParam)");
                addDistancePhotos(plan, pts, start, end, d);
            } else {
                plan.at[start] = true; // reachPoint (and anything else): a photo at the waypoint
            }
        }
    return plan;
}

route::Waypoint between(const RawPoint& a, const RawPoint& b, double along) {
    const double len = geo::geodesicDistance(a.waypoint.position, b.waypoint.position);
    const double t = len > 0 ? along / len : 0.0;
    route::Waypoint w = a.waypoint;
    w.position = geo::geodesicDirect(
        a.waypoint.position, geo::initialBearingDeg(a.waypoint.position, b.waypoint.position),
        along);
    w.altitudeM = a.waypoint.altitudeM + t * (b.waypoint.altitudeM - a.waypoint.altitudeM);
    return w;
}

// Heights above the take-off point from the wayline's height mode.
Status toAltitudes(std::vector<RawPoint>& pts, const std::string& mode,
                   const std::optional<RefPoint>& ref, std::optional<double>& homeAmsl,
                   const std::string& where) {
    if (mode == "relativeToStartPoint") {
        for (auto& p : pts)
            p.waypoint.altitudeM = p.height;
        return {};
    }
    if (mode != "WGS84")
        return makeError(ErrorCode::Unsupported,
                         where + ": executeHeightMode \"" + mode +
                             "\" cannot be read as heights above the take-off point "
                             "(known: relativeToStartPoint, WGS84)");
    if (!ref)
        return makeError(ErrorCode::ParseError,
                         where + ": the heights are above the WGS84 ellipsoid but "
                                 "wpmz/template.kml gives no take-off reference point "
                                 "(wpml:takeOffRefPoint) to measure them from");
    std::vector<geo::LonLat> at{ref->position};
    for (const auto& p : pts)
        at.push_back(p.waypoint.position);
    auto n = wpml::egm96Undulations(at);
    if (!n)
        return makeError(n.error().code, where + ": " + n.error().message);
    homeAmsl = ref->ellipsoidHeightM - n->front();
    for (std::size_t i = 0; i < pts.size(); ++i)
        pts[i].waypoint.altitudeM = pts[i].height - (*n)[i + 1] - *homeAmsl;
    return {};
}

Result<std::vector<RawPoint>>
rawPoints(const WpmlXml& x, std::vector<const CPLXMLNode*>& placemarks, const std::string& where) {
    std::map<long, const CPLXMLNode*> byIndex;
    for (std::size_t k = 0; k < placemarks.size(); ++k) {
        const auto idx = x.number(placemarks[k], "index");
        const std::string label = where + ": waypoint " +
                                  (idx ? std::to_string(static_cast<long>(*idx))
                                       : "#" + std::to_string(k + 1) + " (no wpml:index)");
        if (!idx || *idx < 0 || *idx != std::floor(*idx) ||
            !byIndex.emplace(static_cast<long>(*idx), placemarks[k]).second)
            return makeError(ErrorCode::ParseError,
                             label + ": wpml:index must be a whole number, unique in its wayline");
    }
    placemarks.clear();
    std::vector<RawPoint> pts;
    for (const auto& [idx, pm] : byIndex) {
        const std::string label = where + ": waypoint " + std::to_string(idx);
        auto pos =
            coordinates(WpmlXml::text(x.child(x.child(pm, "Point", false), "coordinates", false)));
        if (!pos)
            return makeError(ErrorCode::ParseError,
                             label + " has no coordinates (<Point><coordinates>longitude,"
                                     "latitude</coordinates></Point>)");
        const auto h = x.number(pm, "executeHeight");
        if (!h)
            return makeError(ErrorCode::ParseError, label + " has no wpml:executeHeight");
        RawPoint p;
        p.waypoint.position = *pos;
        p.height = *h;
        if (const CPLXMLNode* hp = x.child(pm, "waypointHeadingParam"))
            p.headingDeg = x.number(hp, "waypointHeadingAngle");
        pts.push_back(p);
        placemarks.push_back(pm);
    }
    return pts;
}

Result<route::Route> readWayline(const WpmlXml& x, const CPLXMLNode* folder,
                                 const std::optional<RefPoint>& ref, const std::string& where) {
    std::vector<const CPLXMLNode*> placemarks = x.children(folder, "Placemark", false);
    if (placemarks.empty())
        return makeError(ErrorCode::ParseError, where + " holds no waypoints (Placemark)");
    auto pts = rawPoints(x, placemarks, where);
    if (!pts)
        return pts.error();
    route::Route r;
    if (auto st =
            toAltitudes(*pts, x.string(folder, "executeHeightMode"), ref, r.homeElevationM, where);
        !st)
        return st.error();
    // Without a yaw of its own (followWayline and the like) a waypoint faces along its leg.
    for (std::size_t i = 0; i < pts->size(); ++i) {
        auto& p = (*pts)[i];
        double h = 0.0;
        if (p.headingDeg)
            h = *p.headingDeg;
        else if (i + 1 < pts->size())
            h = geo::initialBearingDeg(p.waypoint.position, (*pts)[i + 1].waypoint.position);
        else if (i > 0)
            h = geo::initialBearingDeg((*pts)[i - 1].waypoint.position, p.waypoint.position);
        p.waypoint.headingDeg = detail::normaliseHeading(h);
    }
    auto photos = photoPlan(x, placemarks, *pts, where);
    if (!photos)
        return photos.error();
    std::vector<bool> isPhoto;
    for (std::size_t i = 0; i < pts->size(); ++i) {
        r.waypoints.push_back((*pts)[i].waypoint);
        isPhoto.push_back(photos->at[i]);
        for (double along : photos->interior[i]) {
            r.waypoints.push_back(between((*pts)[i], (*pts)[i + 1], along));
            isPhoto.push_back(true);
        }
    }
    detail::inferNonPhotoKinds(r.waypoints, isPhoto);
    if (auto s = x.number(folder, "autoFlightSpeed"); s && *s > 0)
        r.cruiseSpeedMps = *s;
    if (ref)
        r.home = ref->position;
    return r;
}

std::string aircraftName(const WpmlXml& x) {
    const CPLXMLNode* info = x.child(x.child(x.document, "missionConfig"), "droneInfo");
    const auto e = x.number(info, "droneEnumValue"), s = x.number(info, "droneSubEnumValue");
    if (!e)
        return "DJI aircraft";
    const int sub = s ? static_cast<int>(*s) : 0;
    if (const auto* d = wpml::findDroneType(static_cast<int>(*e), sub))
        return d->name;
    return "DJI aircraft " + detail::formatNumber(*e, 0) + "/" + std::to_string(sub);
}

} // namespace

Result<ImportedWaypoints> readWpmlKmz(const std::string& path) {
    auto files = wpml::zipArchiveFiles(path);
    if (!files)
        return files.error();
    if (std::find(files->begin(), files->end(), kWaylines) == files->end())
        return makeError(ErrorCode::ParseError,
                         path + ": not a DJI WPML mission: the archive holds no " +
                             std::string(kWaylines) + " (the file the aircraft flies)");
    auto text = wpml::readZipArchiveFile(path, kWaylines);
    if (!text)
        return text.error();
    const std::string where = path + ": " + kWaylines;
    auto xml = parseWpml(*text, where);
    if (!xml)
        return xml.error();
    const std::optional<RefPoint> ref = takeOffRefPoint(path);
    const auto folders = xml->children(xml->document, "Folder", false);
    if (folders.empty())
        return makeError(ErrorCode::ParseError, where + " holds no wayline (Folder)");
    ImportedWaypoints out;
    const std::string name = aircraftName(*xml);
    for (std::size_t f = 0; f < folders.size(); ++f) {
        const std::string label =
            folders.size() > 1 ? where + ": wayline " + std::to_string(f + 1) : where;
        auto r = readWayline(*xml, folders[f], ref, label);
        if (!r)
            return r.error();
        r->aircraft = folders.size() > 1 ? name + " wayline " + std::to_string(f + 1) : name;
        out.routes.push_back(std::move(*r));
    }
    if (ref)
        out.home = ref->position;
    // The gimbal's pitch (the first gimbalRotate): oblique photos keep their tilt when converted.
    if (const CPLXMLNode* pitch = xml->find(xml->document, "gimbalPitchRotateAngle"))
        if (auto v = detail::parseNumber(WpmlXml::text(pitch)))
            out.cameraTiltDeg = cameraTiltFromPitch(*v);
    return out;
}

} // namespace pf::io
