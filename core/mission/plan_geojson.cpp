#include "core/mission/plan_geojson.h"

#include "core/sensor/footprint.h"

#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <vector>
#include <unistd.h>

namespace pf::mission {

namespace {

// A JSON string literal (quotes included).
std::string quoted(const std::string& s) {
    std::string out = "\"";
    for (const unsigned char c : s) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += static_cast<char>(c);
        } else if (c < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", c);
            out += buf;
        } else {
            out += static_cast<char>(c);
        }
    }
    return out + "\"";
}

// Writes `v` with 7 decimals at `out` (as printf's %.7f, rounded half away from zero), returns the end:
// printf spends most of the export's time on the millions of coordinates.
char* degrees(char* out, double v) {
    if (!std::isfinite(v) || std::fabs(v) >= 1e9)
        return out + std::sprintf(out, "%.7f", std::isfinite(v) ? v : 0.0);
    long long q = std::llround(std::fabs(v) * 1e7);
    if (v < 0 && q != 0)
        *out++ = '-';
    const long long whole = q / 10000000;
    long long frac = q % 10000000;
    char digits[24];
    int n = 0;
    long long w = whole;
    do {
        digits[n++] = static_cast<char>('0' + w % 10);
        w /= 10;
    } while (w > 0);
    while (n > 0)
        *out++ = digits[--n];
    *out++ = '.';
    for (int k = 6; k >= 0; --k) {
        out[k] = static_cast<char>('0' + frac % 10);
        frac /= 10;
    }
    return out + 7;
}

// Writes features one per line, with the separators GeoJSON needs between them.
class FeatureWriter {
public:
    explicit FeatureWriter(std::ostream& out) : m_out(out) {
        m_out << "{\"type\":\"FeatureCollection\",\"features\":[";
    }
    // Starts a feature: `properties` is the inside of the properties object.
    void begin(const std::string& properties, const char* geometryType) {
        m_out << (m_first ? "\n" : ",\n") << "{\"type\":\"Feature\",\"properties\":{" << properties
              << "},\"geometry\":{\"type\":\"" << geometryType << "\",\"coordinates\":";
        m_first = false;
    }
    void end() { m_out << "}}"; }
    void finish() { m_out << "\n]}\n"; }
    void position(const geo::LonLat& p) {
        char buf[64];
        char* e = buf;
        *e++ = '[';
        e = degrees(e, p.lon);
        *e++ = ',';
        e = degrees(e, p.lat);
        *e++ = ']';
        m_out.write(buf, e - buf);
    }
    // A ring, closed as GeoJSON wants it.
    void ring(const geo::GeoRing& r) {
        m_out << '[';
        for (std::size_t i = 0; i <= r.size(); ++i) {
            if (i > 0)
                m_out << ',';
            position(r[i % r.size()]);
        }
        m_out << ']';
    }
    void multiPolygon(const geo::MultiPolygon& mp, const geo::LocalFrame& frame) {
        m_out << '[';
        for (std::size_t k = 0; k < mp.size(); ++k) {
            m_out << (k > 0 ? ",[" : "[");
            ring(frame.toGeo(mp[k].outer));
            for (const auto& h : mp[k].holes) {
                m_out << ',';
                ring(frame.toGeo(h));
            }
            m_out << ']';
        }
        m_out << ']';
    }
    std::ostream& stream() { return m_out; }

private:
    std::ostream& m_out;
    bool m_first = true;
};

std::string num(double v, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

} // namespace

bool writePlanGeoJson(const MissionPlan& plan, std::ostream& out, const PlanGeoJsonOptions& options) {
    FeatureWriter w(out);
    for (const auto& a : plan.aircraft) {
        const std::string who = "\"aircraft\":" + quoted(a.aircraft);
        int photos = 0;
        for (const auto& wp : a.route.waypoints)
            photos += wp.kind == route::WaypointKind::Photo;
        w.begin("\"kind\":\"path\"," + who + ",\"alt_m\":" + num(a.altitudeM, 2) +
                    ",\"footprint_across_m\":" + num(a.footprint.real.longSideM, 3) +
                    ",\"footprint_along_m\":" + num(a.footprint.real.shortSideM, 3) +
                    ",\"photos\":" + std::to_string(photos) + ",\"sorties\":" + std::to_string(a.sorties.size()),
                "LineString");
        out << '[';
        bool firstPoint = true;
        const auto point = [&](const geo::LonLat& p) {
            if (!firstPoint)
                out << ',';
            firstPoint = false;
            w.position(p);
        };
        if (a.route.home)
            point(*a.route.home);
        // Between two sorties the route itself passes through home (a Transit waypoint there).
        for (const auto& wp : a.route.waypoints)
            point(wp.position);
        if (a.route.home)
            point(*a.route.home);
        out << ']';
        w.end();
        int seq = 0;
        for (const auto& wp : a.route.waypoints) {
            if (wp.kind != route::WaypointKind::Photo)
                continue;
            char props[224];
            int len = std::snprintf(props, sizeof props, ",\"seq\":%d,\"alt_m\":%.2f,\"heading_deg\":%.1f", ++seq,
                                    wp.altitudeM, wp.headingDeg);
            if (wp.groundM && a.route.homeElevationM && len > 0 && len < static_cast<int>(sizeof props))
                // terrain following: the ground under the photo and its height above sea level
                std::snprintf(props + len, sizeof props - static_cast<std::size_t>(len),
                              ",\"ground_m\":%.2f,\"alt_amsl_m\":%.2f", *wp.groundM,
                              *a.route.homeElevationM + wp.altitudeM);
            w.begin("\"kind\":\"photo\"," + who + props, "Point");
            w.position(wp.position);
            w.end();
        }
        if (options.footprints && plan.frame && a.localWaypoints.size() == a.route.waypoints.size()) {
            seq = 0;
            for (const auto& lw : a.localWaypoints) {
                if (lw.kind != route::WaypointKind::Photo)
                    continue;
                const geo::Ring r = sensor::footprintRing(
                    sensor::photoTakenFrom(lw.pos, lw.headingDeg, a.footprint.real));
                w.begin("\"kind\":\"footprint\"," + who + ",\"seq\":" + std::to_string(++seq), "Polygon");
                out << '[';
                w.ring(plan.frame->toGeo(r));
                out << ']';
                w.end();
            }
        }
        if (!out)
            return false;
    }
    if (plan.frame) {
        for (const auto& a : plan.aircraft) {
            if (a.subarea.empty())
                continue;
            w.begin("\"kind\":\"subarea\",\"aircraft\":" + quoted(a.aircraft), "MultiPolygon");
            w.multiPolygon(a.subarea, *plan.frame);
            w.end();
        }
        for (const auto& u : plan.uncovered) {
            w.begin("\"kind\":\"uncovered\",\"area_m2\":" + num(u.areaM2, 2), "MultiPolygon");
            w.multiPolygon(u.shape, *plan.frame);
            w.end();
        }
    }
    w.finish();
    out.flush();
    return static_cast<bool>(out);
}

Status writePlanGeoJsonFile(const MissionPlan& plan, const std::string& path, const PlanGeoJsonOptions& options) {
    static std::atomic<int> counter{0};
    const std::string tmp = path + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(++counter);
    bool ok = false;
    {
        std::vector<char> buffer(1 << 20); // few large writes
        std::ofstream f;
        f.rdbuf()->pubsetbuf(buffer.data(), static_cast<std::streamsize>(buffer.size()));
        f.open(tmp, std::ios::binary | std::ios::trunc);
        if (!f)
            return makeError(ErrorCode::IoError, "cannot write " + path + " (cannot create " + tmp + ")");
        ok = writePlanGeoJson(plan, f, options);
        f.close();
        ok = ok && static_cast<bool>(f);
    }
    if (!ok) {
        std::remove(tmp.c_str());
        return makeError(ErrorCode::IoError, "cannot write " + path + " (disk full?)");
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        std::remove(tmp.c_str());
        return makeError(ErrorCode::IoError, "cannot write " + path + " (cannot replace it)");
    }
    return {};
}

std::string planToGeoJson(const MissionPlan& plan) {
    std::ostringstream out;
    writePlanGeoJson(plan, out);
    return out.str();
}

} // namespace pf::mission
