#include "tests/core/io/wpml_checker.h"

#include "core/geo/geodesic.h"

#include <cpl_conv.h>
#include <cpl_minixml.h>
#include <cpl_string.h>
#include <cpl_vsi.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <set>

namespace pf::test {

namespace {

// The documented enumerations (DJI WPML pages).
const std::set<std::string> kFlyTo{"safely", "pointToPoint"};
const std::set<std::string> kFinish{"goHome", "noAction", "autoLand", "gotoFirstWaypoint"};
const std::set<std::string> kExitOnRcLost{"goContinue", "executeLostAction"};
const std::set<std::string> kRcLostAction{"goBack", "landing", "hover"};
const std::set<std::string> kTemplateTypes{"waypoint", "mapping2d", "mapping3d", "mappingStrip"};
const std::set<std::string> kTemplateHeightModes{"EGM96", "relativeToStartPoint",
                                                 "aboveGroundLevel", "realTimeFollowSurface"};
const std::set<std::string> kExecuteHeightModes{"WGS84", "relativeToStartPoint",
                                                "realTimeFollowSurface"};
const std::set<std::string> kHeadingModes{"followWayline", "manually", "fixed", "smoothTransition",
                                          "towardPOI"};
const std::set<std::string> kHeadingPathModes{"clockwise", "counterClockwise", "followBadArc"};
const std::set<std::string> kTurnModes{"coordinateTurn", "toPointAndStopWithDiscontinuityCurvature",
                                       "toPointAndStopWithContinuityCurvature",
                                       "toPointAndPassWithContinuityCurvature"};
const std::set<std::string> kGimbalPitchModes{"manual", "usePointSetting"};
const std::set<std::string> kTriggers{"reachPoint", "betweenAdjacentPoints", "multipleTiming",
                                      "multipleDistance"};
const std::set<std::string> kActions{
    "takePhoto",     "startRecord",   "stopRecord", "focus",           "zoom",
    "customDirName", "gimbalRotate",  "rotateYaw",  "hover",           "gimbalEvenlyRotate",
    "accurateShoot", "orientedShoot", "panoShot",   "recordPointCloud"};
// droneEnumValue/droneSubEnumValue: M350 89, M300 60, M30/M30T 67 (0, 1), M3E/M3T/M3M 77 (0, 1, 2),
// M3D/M3TD 91 (0, 1); Matrice 4E/4T 99 (0, 1) on the Product Support page.
const std::set<std::pair<int, int>> kDrones{{89, 0}, {60, 0}, {67, 0}, {67, 1}, {77, 0}, {77, 1},
                                            {77, 2}, {91, 0}, {91, 1}, {99, 0}, {99, 1}};
// payloadEnumValue: the list of Common Elements, the Matrice 4E/4T cameras (88, 89) and the P1
// (50).
const std::set<int> kPayloads{42, 43, 50, 52, 53, 61, 66, 67, 68, 80, 81, 82, 83, 88, 89, 65534};

struct Doc {
    std::unique_ptr<CPLXMLNode, void (*)(CPLXMLNode*)> tree{nullptr, CPLDestroyXMLNode};
    const CPLXMLNode* document = nullptr;
};

const CPLXMLNode* child(const CPLXMLNode* n, const std::string& name) {
    for (const CPLXMLNode* c = n ? n->psChild : nullptr; c; c = c->psNext)
        if (c->eType == CXT_Element && name == c->pszValue)
            return c;
    return nullptr;
}
std::vector<const CPLXMLNode*> all(const CPLXMLNode* n, const std::string& name) {
    std::vector<const CPLXMLNode*> out;
    for (const CPLXMLNode* c = n ? n->psChild : nullptr; c; c = c->psNext)
        if (c->eType == CXT_Element && name == c->pszValue)
            out.push_back(c);
    return out;
}
std::string text(const CPLXMLNode* n) {
    return n ? CPLGetXMLValue(n, nullptr, "") : "";
}

class Checker {
public:
    WpmlCheck out;

    void fail(const std::string& s) { out.problems.push_back(s); }

    // A required element with one of the documented values.
    std::string oneOf(const CPLXMLNode* parent, const std::string& name,
                      const std::set<std::string>& allowed, const std::string& where) {
        const CPLXMLNode* e = child(parent, name);
        if (!e) {
            fail(where + ": " + name + " is missing");
            return {};
        }
        const std::string v = text(e);
        if (!allowed.count(v))
            fail(where + ": " + name + " \"" + v + "\" is not a documented value");
        return v;
    }
    // A required number in [lo, hi].
    double number(const CPLXMLNode* parent, const std::string& name, double lo, double hi,
                  const std::string& where) {
        const CPLXMLNode* e = child(parent, name);
        if (!e) {
            fail(where + ": " + name + " is missing");
            return NAN;
        }
        char* end = nullptr;
        const std::string t = text(e);
        const double v = std::strtod(t.c_str(), &end);
        if (t.empty() || *end || !std::isfinite(v) || v < lo || v > hi)
            fail(where + ": " + name + " \"" + t + "\" is not a number in [" + std::to_string(lo) +
                 ", " + std::to_string(hi) + "]");
        return v;
    }

    Doc parse(const std::string& archive, const std::string& name) {
        Doc d;
        const std::string p = "/vsizip/{" + archive + "}/" + name;
        VSILFILE* f = VSIFOpenL(p.c_str(), "rb");
        if (!f) {
            fail(name + " cannot be read");
            return d;
        }
        std::string xml;
        char buf[65536];
        std::size_t n;
        while ((n = VSIFReadL(buf, 1, sizeof buf, f)) > 0)
            xml.append(buf, n);
        VSIFCloseL(f);
        if (xml.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>", 0) != 0)
            fail(name + ": does not start with the XML declaration of the documentation's samples");
        d.tree.reset(CPLParseXMLString(xml.c_str()));
        const CPLXMLNode* kml = nullptr;
        for (const CPLXMLNode* c = d.tree.get(); c; c = c->psNext)
            if (c->eType == CXT_Element && std::string(c->pszValue) == "kml")
                kml = c;
        if (!kml) {
            fail(name + ": not well-formed XML with a <kml> root");
            return d;
        }
        if (std::string(CPLGetXMLValue(kml, "xmlns", "")) != "http://www.opengis.net/kml/2.2")
            fail(name + ": the default namespace is not KML 2.2");
        if (std::string(CPLGetXMLValue(kml, "xmlns:wpml", ""))
                .rfind("http://www.dji.com/wpmz/1.0.", 0) != 0)
            fail(name + ": the wpml prefix is not bound to http://www.dji.com/wpmz/1.0.x");
        d.document = child(kml, "Document");
        if (!d.document)
            fail(name + ": no <Document>");
        return d;
    }

    void missionConfig(const CPLXMLNode* doc, const std::string& where) {
        const CPLXMLNode* c = child(doc, "wpml:missionConfig");
        if (!c)
            return fail(where + ": wpml:missionConfig is missing");
        oneOf(c, "wpml:flyToWaylineMode", kFlyTo, where);
        oneOf(c, "wpml:finishAction", kFinish, where);
        if (oneOf(c, "wpml:exitOnRCLost", kExitOnRcLost, where) == "executeLostAction")
            oneOf(c, "wpml:executeRCLostAction", kRcLostAction, where);
        number(c, "wpml:takeOffSecurityHeight", 8.0, 1500.0, where); // [8, 1500] fits a dock too
        number(c, "wpml:globalTransitionalSpeed", 1e-9, 15.0, where);
        const CPLXMLNode* drone = child(c, "wpml:droneInfo");
        const CPLXMLNode* payload = child(c, "wpml:payloadInfo");
        out.droneEnum = static_cast<int>(number(drone, "wpml:droneEnumValue", 0, 65535, where));
        out.droneSubEnum =
            static_cast<int>(number(drone, "wpml:droneSubEnumValue", 0, 65535, where));
        if (!kDrones.count({out.droneEnum, out.droneSubEnum}))
            fail(where + ": drone type " + std::to_string(out.droneEnum) + "/" +
                 std::to_string(out.droneSubEnum) + " is not documented");
        out.payloadEnum =
            static_cast<int>(number(payload, "wpml:payloadEnumValue", 0, 65535, where));
        if (!kPayloads.count(out.payloadEnum))
            fail(where + ": payload type " + std::to_string(out.payloadEnum) +
                 " is not documented");
        number(payload, "wpml:payloadPositionIndex", 0, 2, where);
    }

    void headingAndTurn(const CPLXMLNode* pm, const std::string& where) {
        const CPLXMLNode* h = child(pm, "wpml:waypointHeadingParam");
        if (oneOf(h, "wpml:waypointHeadingMode", kHeadingModes, where) == "smoothTransition")
            number(h, "wpml:waypointHeadingAngle", -180.0, 180.0, where);
        oneOf(h, "wpml:waypointHeadingPathMode", kHeadingPathModes, where);
        const CPLXMLNode* t = child(pm, "wpml:waypointTurnParam");
        // "Common Elements", wpml:waypointTurnParam: the damping distance is in (0, the segment's
        // length] and required for a coordinated turn; when given it must be in that range.
        if (oneOf(t, "wpml:waypointTurnMode", kTurnModes, where) == "coordinateTurn" ||
            child(t, "wpml:waypointTurnDampingDist"))
            number(t, "wpml:waypointTurnDampingDist", 1e-9, 1e9, where);
    }

    // Action groups; returns (start, end, trigger, interval) of each group that takes photos.
    struct PhotoGroup {
        std::size_t start, end;
        std::string trigger;
        double interval;
    };
    void actionGroups(const CPLXMLNode* pm, std::size_t count, std::set<long>& ids,
                      std::vector<PhotoGroup>& photos, const std::string& where) {
        for (const CPLXMLNode* g : all(pm, "wpml:actionGroup")) {
            const double id = number(g, "wpml:actionGroupId", 0, 65535, where);
            if (!ids.insert(static_cast<long>(id)).second)
                fail(where + ": actionGroupId " + text(child(g, "wpml:actionGroupId")) +
                     " is used twice");
            const double s =
                number(g, "wpml:actionGroupStartIndex", 0, static_cast<double>(count) - 1, where);
            const double e =
                number(g, "wpml:actionGroupEndIndex", s, static_cast<double>(count) - 1, where);
            oneOf(g, "wpml:actionGroupMode", {"sequence"}, where);
            const CPLXMLNode* t = child(g, "wpml:actionTrigger");
            const std::string type = oneOf(t, "wpml:actionTriggerType", kTriggers, where);
            double interval = 0.0;
            if (type == "multipleTiming" || type == "multipleDistance")
                interval = number(t, "wpml:actionTriggerParam", 1e-9, 1e9, where);
            std::set<long> actionIds;
            bool photo = false;
            for (const CPLXMLNode* a : all(g, "wpml:action")) {
                if (!actionIds.insert(std::lround(number(a, "wpml:actionId", 0, 65535, where)))
                         .second)
                    fail(where + ": an actionId is used twice in one group");
                const std::string f = oneOf(a, "wpml:actionActuatorFunc", kActions, where);
                const CPLXMLNode* p = child(a, "wpml:actionActuatorFuncParam");
                number(p, "wpml:payloadPositionIndex", 0, 2, where);
                if (f == "takePhoto")
                    photo = true;
                if (f == "gimbalRotate") {
                    oneOf(p, "wpml:gimbalRotateMode", {"absoluteAngle"}, where);
                    if (text(child(p, "wpml:gimbalPitchRotateEnable")) == "1")
                        number(p, "wpml:gimbalPitchRotateAngle", -120.0, 45.0, where);
                }
            }
            if (photo && std::isfinite(s) && std::isfinite(e))
                photos.push_back(
                    {static_cast<std::size_t>(s), static_cast<std::size_t>(e), type, interval});
        }
    }

    void templateFolder(const Doc& d) {
        const std::string w = "template.kml";
        const CPLXMLNode* f = child(d.document, "Folder");
        if (!f)
            return fail(w + ": no Folder");
        oneOf(f, "wpml:templateType", kTemplateTypes, w);
        number(f, "wpml:templateId", 0, 65535, w);
        const CPLXMLNode* sys = child(f, "wpml:waylineCoordinateSysParam");
        oneOf(sys, "wpml:coordinateMode", {"WGS84"}, w);
        out.templateHeightMode = oneOf(sys, "wpml:heightMode", kTemplateHeightModes, w);
        number(f, "wpml:autoFlightSpeed", 1e-9, 15.0, w);
        const bool pointPitch =
            oneOf(f, "wpml:gimbalPitchMode", kGimbalPitchModes, w) == "usePointSetting";
        oneOf(f, "wpml:globalWaypointTurnMode", kTurnModes, w);
        if (!child(child(f, "wpml:payloadParam"), "wpml:imageFormat"))
            fail(w + ": wpml:payloadParam/wpml:imageFormat is missing");
        const auto pms = all(f, "Placemark");
        std::set<long> ids;
        std::vector<PhotoGroup> photos;
        for (std::size_t i = 0; i < pms.size(); ++i) {
            const std::string where = w + ": Placemark " + std::to_string(i);
            if (number(pms[i], "wpml:index", 0, 65535, where) != static_cast<double>(i))
                fail(where + ": wpml:index is not " + std::to_string(i) + " (contiguous from 0)");
            if (text(child(pms[i], "wpml:useGlobalHeight")) == "0") {
                out.templateHeights.push_back(number(pms[i], "wpml:height", -1000, 10000, where));
                out.templateEllipsoidHeights.push_back(
                    number(pms[i], "wpml:ellipsoidHeight", -1000, 10000, where));
            }
            if (text(child(pms[i], "wpml:useGlobalSpeed")) == "0")
                number(pms[i], "wpml:waypointSpeed", 1e-9, 15.0, where);
            if (text(child(pms[i], "wpml:useGlobalHeadingParam")) == "0" &&
                text(child(pms[i], "wpml:useGlobalTurnParam")) == "0")
                headingAndTurn(pms[i], where);
            if (pointPitch)
                number(pms[i], "wpml:gimbalPitchAngle", -90.0, 90.0, where);
            actionGroups(pms[i], pms.size(), ids, photos, where);
        }
    }

    void waylinesFolder(const Doc& d) {
        const std::string w = "waylines.wpml";
        const CPLXMLNode* f = child(d.document, "Folder");
        if (!f)
            return fail(w + ": no Folder");
        number(f, "wpml:templateId", 0, 65535, w);
        number(f, "wpml:waylineId", 0, 65535, w);
        out.executeHeightMode = oneOf(f, "wpml:executeHeightMode", kExecuteHeightModes, w);
        number(f, "wpml:autoFlightSpeed", 1e-9, 15.0, w);
        const bool relative = out.executeHeightMode == "relativeToStartPoint";
        const auto pms = all(f, "Placemark");
        std::set<long> ids;
        std::vector<PhotoGroup> photos;
        for (std::size_t i = 0; i < pms.size(); ++i) {
            const std::string where = w + ": Placemark " + std::to_string(i);
            if (number(pms[i], "wpml:index", 0, 65535, where) != static_cast<double>(i))
                fail(where + ": wpml:index is not " + std::to_string(i) + " (contiguous from 0)");
            WpmlFlownPoint p;
            const char* coords = CPLGetXMLValue(pms[i], "Point.coordinates", nullptr);
            const CPLStringList xy(CSLTokenizeString2(coords ? coords : "", ",",
                                                      CSLT_STRIPLEADSPACES | CSLT_STRIPENDSPACES));
            if (xy.size() < 2)
                fail(where + ": Point/coordinates is not longitude,latitude");
            else
                p.position = {CPLAtof(xy[0]), CPLAtof(xy[1])};
            if (std::abs(p.position.lon) > 180 || std::abs(p.position.lat) > 90)
                fail(where + ": coordinates out of range");
            // Heights: above take-off within the documented safe take-off height range, else a
            // plausible height above the ellipsoid.
            p.executeHeightM = number(pms[i], "wpml:executeHeight", relative ? 1.2 : -500.0,
                                      relative ? 1500.0 : 9000.0, where);
            number(pms[i], "wpml:waypointSpeed", 1e-9, 15.0, where);
            headingAndTurn(pms[i], where);
            actionGroups(pms[i], pms.size(), ids, photos, where);
            out.waypoints.push_back(p);
        }
        drawRoute(photos);
    }

    // The flown route: every waypoint, and the photos of interval triggers between them.
    void drawRoute(const std::vector<PhotoGroup>& groups) {
        auto& w = out.waypoints;
        std::vector<std::vector<WpmlFlownPoint>> between(w.size());
        for (const auto& g : groups) {
            if (g.trigger == "reachPoint") {
                w[g.start].photo = true;
                ++out.photos;
                continue;
            }
            if (g.trigger != "multipleDistance") {
                fail("waylines.wpml: a photo trigger the checker cannot place: " + g.trigger);
                continue;
            }
            double done = 0.0; // distance flown since the group's start
            double next = 0.0; // where the next photo is due
            for (std::size_t j = g.start; j <= g.end; ++j) {
                const double seg =
                    j < g.end ? geo::geodesicDistance(w[j].position, w[j + 1].position) : 0.0;
                while (next <= done + seg + 1e-6) {
                    ++out.photos;
                    const double along = next - done;
                    if (along < 1e-3)
                        w[j].photo = true;
                    else if (seg - along < 1e-3 && j + 1 <= g.end)
                        w[j + 1].photo = true;
                    else {
                        WpmlFlownPoint p;
                        p.position = geo::geodesicDirect(
                            w[j].position, geo::initialBearingDeg(w[j].position, w[j + 1].position),
                            along);
                        p.executeHeightM =
                            w[j].executeHeightM +
                            along / seg * (w[j + 1].executeHeightM - w[j].executeHeightM);
                        p.photo = true;
                        between[j].push_back(p);
                    }
                    next += g.interval;
                    if (j == g.end)
                        break;
                }
                done += seg;
            }
        }
        for (std::size_t i = 0; i < w.size(); ++i) {
            out.flown.push_back(w[i]);
            out.flown.insert(out.flown.end(), between[i].begin(), between[i].end());
        }
    }
};

} // namespace

WpmlCheck checkWpmlKmz(const std::string& path) {
    Checker c;
    std::unique_ptr<char*, void (*)(char**)> list(
        VSIReadDirRecursive(("/vsizip/{" + path + "}").c_str()), CSLDestroy);
    if (!list) {
        c.fail("not a ZIP archive");
        return c.out;
    }
    std::set<std::string> files;
    for (char** p = list.get(); *p; ++p)
        if (std::string(*p).back() != '/')
            files.insert(*p);
    const std::set<std::string> expected{"wpmz/template.kml", "wpmz/waylines.wpml"};
    if (files != expected)
        c.fail("the archive does not hold exactly wpmz/template.kml and wpmz/waylines.wpml");
    const Doc t = c.parse(path, "wpmz/template.kml");
    const Doc w = c.parse(path, "wpmz/waylines.wpml");
    if (!t.document || !w.document)
        return c.out;
    c.missionConfig(t.document, "template.kml");
    c.missionConfig(w.document, "waylines.wpml");
    c.templateFolder(t);
    c.waylinesFolder(w);
    return c.out;
}

} // namespace pf::test
