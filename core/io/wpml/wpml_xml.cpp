// The two XML documents of a WPML .kmz, element by element as DJI's Cloud API documentation
// describes them ("DJI WPML": template.kml, waylines.wpml, Common Elements). Built as a CPLXML
// tree, so that the text is well-formed and escaped by GDAL's serializer.
#include "core/io/waypoint_format_util.h"
#include "core/io/wpml/wayline.h"

#include <cpl_minixml.h>

#include <memory>

namespace pf::io::wpml {

namespace {

using detail::formatNumber;

constexpr const char* kKmlNamespace = "http://www.opengis.net/kml/2.2";
// The namespace of the documentation's samples; DJI Pilot 2 reads files of this version.
constexpr const char* kWpmlNamespace = "http://www.dji.com/wpmz/1.0.2";

struct TreeDeleter {
    void operator()(CPLXMLNode* n) const { CPLDestroyXMLNode(n); }
};
using Tree = std::unique_ptr<CPLXMLNode, TreeDeleter>;

CPLXMLNode* add(CPLXMLNode* parent, const char* name, const std::string& value) {
    return CPLCreateXMLElementAndValue(parent, name, value.c_str());
}
CPLXMLNode* add(CPLXMLNode* parent, const char* name, double value, int decimals = 3) {
    return add(parent, name, formatNumber(value, decimals));
}
CPLXMLNode* node(CPLXMLNode* parent, const char* name) {
    return CPLCreateXMLNode(parent, CXT_Element, name);
}

// <?xml?> and <kml> with both namespaces; returns the <Document>.
CPLXMLNode* startDocument(Tree& tree) {
    tree.reset(CPLCreateXMLNode(nullptr, CXT_Element, "?xml"));
    CPLAddXMLAttributeAndValue(tree.get(), "version", "1.0");
    CPLAddXMLAttributeAndValue(tree.get(), "encoding", "UTF-8");
    CPLXMLNode* kml = CPLCreateXMLNode(nullptr, CXT_Element, "kml");
    CPLAddXMLSibling(tree.get(), kml);
    CPLAddXMLAttributeAndValue(kml, "xmlns", kKmlNamespace);
    CPLAddXMLAttributeAndValue(kml, "xmlns:wpml", kWpmlNamespace);
    return node(kml, "Document");
}

std::string serialize(const Tree& tree) {
    char* text = CPLSerializeXMLTree(tree.get());
    std::string out = text ? text : "";
    CPLFree(text);
    return out;
}

const char* finishAction(MissionEnd end) {
    // wpml:finishAction: "goHome" (exit the wayline and return home), "autoLand" (land on the
    // spot).
    return end == MissionEnd::Land ? "autoLand" : "goHome";
}

void missionConfig(CPLXMLNode* doc, const MissionSettings& s, bool inTemplate) {
    CPLXMLNode* c = node(doc, "wpml:missionConfig");
    // "safely": take off, climb to the first waypoint's altitude (at least the safe take-off
    // height), then fly level to it: the transit the plan assumes from the home.
    add(c, "wpml:flyToWaylineMode", "safely");
    add(c, "wpml:finishAction", finishAction(s.end));
    // A lost link ends the wayline and flies back to the take-off point ("executeLostAction" with
    // "goBack"), rather than surveying on out of the pilot's control.
    add(c, "wpml:exitOnRCLost", "executeLostAction");
    add(c, "wpml:executeRCLostAction", "goBack");
    add(c, "wpml:takeOffSecurityHeight", s.takeOffSecurityHeightM, 2);
    if (inTemplate && s.home) // "<latitude,longitude,altitude>", the altitude an ellipsoidal height
        add(c, "wpml:takeOffRefPoint",
            formatNumber(s.home->lat, 9) + "," + formatNumber(s.home->lon, 9) + "," +
                formatNumber(s.homeEllipsoidHeightM, 4));
    add(c, "wpml:globalTransitionalSpeed", s.transitionalSpeedMps, 2);
    add(c, "wpml:globalRTHHeight", s.rthHeightM, 2);
    CPLXMLNode* drone = node(c, "wpml:droneInfo");
    add(drone, "wpml:droneEnumValue", std::to_string(s.drone.droneEnum));
    add(drone, "wpml:droneSubEnumValue", std::to_string(s.drone.subEnum));
    CPLXMLNode* payload = node(c, "wpml:payloadInfo");
    add(payload, "wpml:payloadEnumValue", std::to_string(s.payloadEnum));
    add(payload, "wpml:payloadPositionIndex", "0"); // the main gimbal (M300/M350: front left)
}

void headingParam(CPLXMLNode* parent, const WaylinePoint& p) {
    CPLXMLNode* h = node(parent, "wpml:waypointHeadingParam");
    // "smoothTransition": the yaw given for each waypoint, changing evenly to the next one's: the
    // plan's heading along each lane, so every photo is taken with the orientation planned.
    add(h, "wpml:waypointHeadingMode", "smoothTransition");
    add(h, "wpml:waypointHeadingAngle", p.headingDeg, 2);
    add(h, "wpml:waypointHeadingPathMode", "followBadArc"); // the shorter way round
}

void turnParam(CPLXMLNode* parent) {
    CPLXMLNode* t = node(parent, "wpml:waypointTurnParam");
    // "toPointAndStopWithDiscontinuityCurvature": fly in a straight line, stop at the point.
    // Waypoints are only where the plan turns (a lane's photos between its ends are taken in
    // flight).
    // No wpml:waypointTurnDampingDist: "Common Elements" documents it in (0, the segment's
    // length] and requires it only for the curving modes, so a stop at the point has none.
    add(t, "wpml:waypointTurnMode", "toPointAndStopWithDiscontinuityCurvature");
}

void gimbalRotate(CPLXMLNode* action, const MissionSettings& s) {
    add(action, "wpml:actionActuatorFunc", "gimbalRotate");
    CPLXMLNode* p = node(action, "wpml:actionActuatorFuncParam");
    add(p, "wpml:gimbalHeadingYawBase", "north");
    add(p, "wpml:gimbalRotateMode", "absoluteAngle");
    add(p, "wpml:gimbalPitchRotateEnable", "1");
    add(p, "wpml:gimbalPitchRotateAngle", s.gimbalPitchDeg, 2);
    add(p, "wpml:gimbalRollRotateEnable", "0");
    add(p, "wpml:gimbalRollRotateAngle", "0");
    add(p, "wpml:gimbalYawRotateEnable", "0");
    add(p, "wpml:gimbalYawRotateAngle", "0");
    add(p, "wpml:gimbalRotateTimeEnable", "0");
    add(p, "wpml:gimbalRotateTime", "0");
    add(p, "wpml:payloadPositionIndex", "0");
}

void takePhoto(CPLXMLNode* action, const MissionSettings& s) {
    add(action, "wpml:actionActuatorFunc", "takePhoto");
    CPLXMLNode* p = node(action, "wpml:actionActuatorFuncParam");
    add(p, "wpml:payloadPositionIndex", "0");
    add(p, "wpml:fileSuffix", "");
    add(p, "wpml:payloadLensIndex", s.lens);
    add(p, "wpml:useGlobalPayloadLensIndex", "0");
}

void actionGroup(CPLXMLNode* placemark, const ActionGroup& g, std::size_t id,
                 const MissionSettings& s) {
    CPLXMLNode* a = node(placemark, "wpml:actionGroup");
    add(a, "wpml:actionGroupId", std::to_string(id));
    add(a, "wpml:actionGroupStartIndex", std::to_string(g.start));
    add(a, "wpml:actionGroupEndIndex", std::to_string(g.end));
    add(a, "wpml:actionGroupMode", "sequence");
    CPLXMLNode* trigger = node(a, "wpml:actionTrigger");
    if (g.kind == GroupKind::PhotosByDistance) {
        // "multipleDistance" with takePhoto: a photo every actionTriggerParam metres, from the
        // group's start waypoint to its end waypoint.
        add(trigger, "wpml:actionTriggerType", "multipleDistance");
        add(trigger, "wpml:actionTriggerParam", g.spacingM, 6);
    } else {
        add(trigger, "wpml:actionTriggerType", "reachPoint");
    }
    CPLXMLNode* action = node(a, "wpml:action");
    add(action, "wpml:actionId", "0");
    if (g.kind == GroupKind::Gimbal)
        gimbalRotate(action, s);
    else
        takePhoto(action, s);
}

// A waypoint's position, index and actions; `fill` adds the elements between index and actions.
template <typename Fill>
void placemarks(CPLXMLNode* folder, const MissionSettings& s, const Wayline& w, Fill fill) {
    for (std::size_t i = 0; i < w.points.size(); ++i) {
        const WaylinePoint& p = w.points[i];
        CPLXMLNode* pm = node(folder, "Placemark");
        add(node(pm, "Point"), "coordinates",
            formatNumber(p.position.lon, 9) + "," + formatNumber(p.position.lat, 9));
        add(pm, "wpml:index", std::to_string(i));
        fill(pm, p);
        for (std::size_t g = 0; g < w.groups.size(); ++g)
            if (w.groups[g].start == i)
                actionGroup(pm, w.groups[g], g, s);
    }
}

} // namespace

std::string templateKml(const MissionSettings& s, const Wayline& w) {
    Tree tree;
    CPLXMLNode* doc = startDocument(tree);
    add(doc, "wpml:author", "Photoflight");
    missionConfig(doc, s, true);
    CPLXMLNode* folder = node(doc, "Folder");
    add(folder, "wpml:templateType", "waypoint"); // a waypoint route: DJI Pilot 2 keeps every point
    add(folder, "wpml:templateId", "0");
    CPLXMLNode* sys = node(folder, "wpml:waylineCoordinateSysParam");
    add(sys, "wpml:coordinateMode", "WGS84");
    // "EGM96" (heights above sea level, the terrain model's datum) or "relativeToStartPoint".
    add(sys, "wpml:heightMode", w.absolute ? "EGM96" : "relativeToStartPoint");
    add(sys, "wpml:positioningType", "GPS");
    add(folder, "wpml:autoFlightSpeed", w.speedMps, 2);
    add(folder, "wpml:globalHeight", w.points.empty() ? 0.0 : w.points.front().heightM, 4);
    add(folder, "wpml:gimbalPitchMode", "usePointSetting"); // each point's gimbalPitchAngle
    CPLXMLNode* heading = node(folder, "wpml:globalWaypointHeadingParam");
    add(heading, "wpml:waypointHeadingMode", "followWayline");
    add(heading, "wpml:waypointHeadingPathMode", "followBadArc");
    add(folder, "wpml:globalWaypointTurnMode", "toPointAndStopWithDiscontinuityCurvature");
    CPLXMLNode* payload = node(folder, "wpml:payloadParam");
    add(payload, "wpml:payloadPositionIndex", "0");
    add(payload, "wpml:imageFormat", s.lens);
    placemarks(folder, s, w, [&](CPLXMLNode* pm, const WaylinePoint& p) {
        add(pm, "wpml:ellipsoidHeight", p.ellipsoidHeightM, 4);
        add(pm, "wpml:height", p.heightM, 4);
        add(pm, "wpml:useGlobalHeight", "0");
        add(pm, "wpml:useGlobalSpeed", "0");
        add(pm, "wpml:waypointSpeed", w.speedMps, 2);
        add(pm, "wpml:useGlobalHeadingParam", "0");
        headingParam(pm, p);
        add(pm, "wpml:useGlobalTurnParam", "0");
        turnParam(pm);
        add(pm, "wpml:gimbalPitchAngle", s.gimbalPitchDeg, 2);
    });
    return serialize(tree);
}

std::string waylinesWpml(const MissionSettings& s, const Wayline& w) {
    Tree tree;
    CPLXMLNode* doc = startDocument(tree);
    missionConfig(doc, s, false);
    CPLXMLNode* folder = node(doc, "Folder");
    add(folder, "wpml:templateId", "0");
    // "WGS84": ellipsoidal heights; "relativeToStartPoint": above the take-off point.
    add(folder, "wpml:executeHeightMode", w.absolute ? "WGS84" : "relativeToStartPoint");
    add(folder, "wpml:waylineId", "0");
    add(folder, "wpml:autoFlightSpeed", w.speedMps, 2);
    placemarks(folder, s, w, [&](CPLXMLNode* pm, const WaylinePoint& p) {
        add(pm, "wpml:executeHeight", w.absolute ? p.ellipsoidHeightM : p.heightM, 4);
        add(pm, "wpml:waypointSpeed", w.speedMps, 2);
        headingParam(pm, p);
        turnParam(pm);
    });
    return serialize(tree);
}

} // namespace pf::io::wpml
