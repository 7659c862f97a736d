// Checked reading of JSON documents: field types, ranges, paths in messages, cameras.
#include "core/io/json_reader.h"

#include "core/io/area_import.h"

#include <cmath>
#include <cstdlib>

namespace pf::io::detail {

Status loadJsonText(CPLJSONDocument& doc, const std::string& rawText, const std::string& source) {
    const bool bom = rawText.size() >= 3 && rawText.compare(0, 3, "\xEF\xBB\xBF") == 0;
    const std::string text = bom ? rawText.substr(3) : rawText;
    GdalErrorScope errors;
    if (!doc.LoadMemory(text))
        return makeError(ErrorCode::ParseError,
                         source + ": not valid JSON: " + describeJsonError(text, errors.firstError()));
    return {};
}

// "JSON parsing error: unexpected character (at offset 11)" -> "... at line 1, column 12".
std::string describeJsonError(const std::string& text, const std::string& gdalMessage) {
    std::string msg = gdalMessage.empty() ? std::string("the text is not valid JSON") : gdalMessage;
    // json-c reports a document that stops in the middle as "continue".
    if (const auto c = msg.find("error: continue"); c != std::string::npos)
        msg = msg.substr(0, c) + "error: the text ends before the JSON is complete" + msg.substr(c + 15);
    const std::string marker = "(at offset ";
    const auto pos = msg.find(marker);
    if (pos == std::string::npos)
        return msg;
    const std::size_t offset = std::strtoul(msg.c_str() + pos + marker.size(), nullptr, 10);
    const TextPosition at = textPositionAt(text, offset);
    return msg.substr(0, pos) + "at line " + std::to_string(at.line) + ", column " + std::to_string(at.column);
}

TextPosition textPositionAt(const std::string& text, std::size_t offset) {
    TextPosition at;
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++at.line;
            at.column = 1;
        } else {
            ++at.column;
        }
    }
    return at;
}

void JsonReader::fail(const std::string& path, const std::string& what) {
    if (!m_error)
        m_error = makeError(ErrorCode::ParseError, m_source + ": " + (path.empty() ? "" : path + ": ") + what);
}

const char* JsonReader::typeName(const CPLJSONObject& o) {
    switch (o.GetType()) {
    case CPLJSONObject::Type::Null: return "null";
    case CPLJSONObject::Type::Object: return "an object";
    case CPLJSONObject::Type::Array: return "an array";
    case CPLJSONObject::Type::Boolean: return "true/false";
    case CPLJSONObject::Type::String: return "a string";
    case CPLJSONObject::Type::Integer:
    case CPLJSONObject::Type::Long:
    case CPLJSONObject::Type::Double: return "a number";
    case CPLJSONObject::Type::Unknown: break;
    }
    return "an unreadable value";
}

bool JsonReader::isNumber(const CPLJSONObject& o) {
    const auto t = o.GetType();
    return t == CPLJSONObject::Type::Integer || t == CPLJSONObject::Type::Long ||
           t == CPLJSONObject::Type::Double;
}

std::string JsonReader::join(const std::string& path, const std::string& key) const {
    return path.empty() ? key : path + m_separator + key;
}

CPLJSONObject JsonReader::member(const CPLJSONObject& parent, const std::string& key) {
    CPLJSONObject o = parent.GetObj(key);
    if (o.IsValid() && o.GetType() == CPLJSONObject::Type::Null)
        return CPLJSONObject(); // invalid
    return o;
}

void JsonReader::checkKeys(const CPLJSONObject& o, const std::string& path, std::initializer_list<const char*> known,
               const char* separator) {
    if (failed() || o.GetType() != CPLJSONObject::Type::Object)
        return;
    for (const auto& child : o.GetChildren()) {
        const std::string key = child.GetName();
        bool ok = key == "note";
        for (const char* k : known)
            ok = ok || key == k;
        if (!ok) {
            std::string list;
            for (const char* k : known)
                list += (list.empty() ? "" : ", ") + std::string(k);
            fail(path.empty() ? key : path + (separator ? separator : m_separator.c_str()) + key,
                 "unknown field (known here: " + list + ")");
            return;
        }
    }
}

bool JsonReader::expectType(const CPLJSONObject& o, const std::string& path, bool ok, const char* expected) {
    if (!ok)
        fail(path, std::string("expected ") + expected + " but found " + typeName(o));
    return ok;
}

double JsonReader::number(const CPLJSONObject& o, const std::string& path) {
    if (!expectType(o, path, isNumber(o), "a number"))
        return 0.0;
    const double v = o.ToDouble();
    if (!std::isfinite(v)) {
        fail(path, "expected a finite number but found " + std::string(std::isnan(v) ? "NaN" : "infinity"));
        return 0.0;
    }
    return v;
}

double JsonReader::number(const CPLJSONObject& parent, const std::string& path, const std::string& key, double def,
              bool required) {
    CPLJSONObject o = member(parent, key);
    if (!o.IsValid()) {
        if (required)
            fail(join(path, key), "missing required field");
        return def;
    }
    return number(o, join(path, key));
}

std::optional<double> JsonReader::optionalNumber(const CPLJSONObject& parent, const std::string& path,
                                     const std::string& key) {
    CPLJSONObject o = member(parent, key);
    if (!o.IsValid())
        return std::nullopt;
    return number(o, join(path, key));
}

long long JsonReader::integer(const CPLJSONObject& parent, const std::string& path, const std::string& key,
                  long long def, bool required, long long minValue, long long maxValue) {
    const std::string p = join(path, key);
    CPLJSONObject o = member(parent, key);
    if (!o.IsValid()) {
        if (required)
            fail(p, "missing required field");
        return def;
    }
    const double v = number(o, p);
    if (failed())
        return def;
    if (v != std::floor(v)) {
        fail(p, "expected a whole number but found " + o.ToString());
        return def;
    }
    if (v < static_cast<double>(minValue) || v > static_cast<double>(maxValue)) {
        fail(p, "value " + o.ToString() + " is out of range (" + std::to_string(minValue) + " to " +
                    std::to_string(maxValue) + ")");
        return def;
    }
    return o.GetType() == CPLJSONObject::Type::Double ? static_cast<long long>(v) : o.ToLong();
}

std::string JsonReader::string(const CPLJSONObject& parent, const std::string& path, const std::string& key,
                   const std::string& def, bool required) {
    CPLJSONObject o = member(parent, key);
    if (!o.IsValid()) {
        if (required)
            fail(join(path, key), "missing required field");
        return def;
    }
    if (!expectType(o, join(path, key), o.GetType() == CPLJSONObject::Type::String, "a string"))
        return def;
    return o.ToString();
}

bool JsonReader::boolean(const CPLJSONObject& parent, const std::string& path, const std::string& key, bool def) {
    CPLJSONObject o = member(parent, key);
    if (!o.IsValid())
        return def;
    if (!expectType(o, join(path, key), o.GetType() == CPLJSONObject::Type::Boolean, "true or false"))
        return def;
    return o.ToBool();
}

CPLJSONObject JsonReader::object(const CPLJSONObject& parent, const std::string& path, const std::string& key,
                     bool required) {
    CPLJSONObject o = member(parent, key);
    if (!o.IsValid()) {
        if (required)
            fail(join(path, key), "missing required field");
        return CPLJSONObject();
    }
    if (!expectType(o, join(path, key), o.GetType() == CPLJSONObject::Type::Object, "an object"))
        return CPLJSONObject();
    return o;
}

CPLJSONArray JsonReader::array(const CPLJSONObject& o, const std::string& path) {
    if (!expectType(o, path, o.GetType() == CPLJSONObject::Type::Array, "an array"))
        return CPLJSONArray();
    return o.ToArray();
}

geo::LonLat JsonReader::position(const CPLJSONObject& o, const std::string& path) {
    if (!expectType(o, path, o.GetType() == CPLJSONObject::Type::Array, "a [longitude, latitude] array"))
        return {};
    CPLJSONArray a = o.ToArray();
    if (a.Size() != 2) {
        fail(path, "expected a [longitude, latitude] array but found " + std::to_string(a.Size()) + " values");
        return {};
    }
    geo::LonLat p{number(a[0], path + "[0]"), number(a[1], path + "[1]")};
    if (failed())
        return {};
    if (std::abs(p.lon) > 180.0)
        fail(path + "[0]", "longitude " + a[0].ToString() + " is out of range (-180 to 180)");
    else if (std::abs(p.lat) > 90.0)
        fail(path + "[1]", "latitude " + a[1].ToString() + " is out of range (-90 to 90)");
    return p;
}

std::optional<geo::LonLat> JsonReader::optionalPosition(const CPLJSONObject& parent, const std::string& path,
                                            const std::string& key) {
    CPLJSONObject o = member(parent, key);
    if (!o.IsValid())
        return std::nullopt;
    return position(o, join(path, key));
}

geo::GeoRing JsonReader::ring(const CPLJSONObject& o, const std::string& path) {
    geo::GeoRing out;
    CPLJSONArray a = array(o, path);
    for (int i = 0; i < a.Size() && !failed(); ++i)
        out.push_back(position(a[i], path + "[" + std::to_string(i) + "]"));
    // Rings are stored open; accept a closed ring as GeoJSON writes it.
    if (out.size() > 1 && out.front() == out.back())
        out.pop_back();
    return out;
}

geo::GeoPolygon JsonReader::polygon(const CPLJSONObject& parent, const std::string& path, const std::string& key) {
    geo::GeoPolygon poly;
    CPLJSONObject o = object(parent, path, key, true);
    if (failed())
        return poly;
    const std::string p = join(path, key);
    CPLJSONObject outer = member(o, "outer");
    if (!outer.IsValid()) {
        fail(join(p, "outer"), "missing required field");
        return poly;
    }
    poly.outer = ring(outer, join(p, "outer"));
    CPLJSONObject holes = member(o, "holes");
    if (holes.IsValid()) {
        CPLJSONArray h = array(holes, join(p, "holes"));
        for (int i = 0; i < h.Size() && !failed(); ++i)
            poly.holes.push_back(ring(h[i], join(p, "holes") + "[" + std::to_string(i) + "]"));
    }
    checkKeys(o, p, {"outer", "holes"});
    return poly;
}

sensor::Camera JsonReader::camera(const CPLJSONObject& o, const std::string& path, bool named) {
    sensor::Camera c;
    if (!expectType(o, path, o.GetType() == CPLJSONObject::Type::Object, "an object"))
        return c;
    c.name = string(o, path, "name", "", named);
    const std::string p = named && !c.name.empty() ? path + " (\"" + c.name + "\")" : path;
    c.sensorWidthMm = number(o, p, "sensor_width_mm", 0.0);
    c.sensorHeightMm = number(o, p, "sensor_height_mm", 0.0);
    c.focalLengthMm = number(o, p, "focal_length_mm", 0.0);
    c.hfovDeg = number(o, p, "hfov_deg", 0.0);
    c.vfovDeg = number(o, p, "vfov_deg", 0.0);
    c.imageWidthPx = static_cast<int>(integer(o, p, "image_width_px", 0, true, 1, 1'000'000));
    c.imageHeightPx = static_cast<int>(integer(o, p, "image_height_px", 0, true, 1, 1'000'000));
    checkKeys(o, p, {"name", "sensor_width_mm", "sensor_height_mm", "focal_length_mm", "hfov_deg", "vfov_deg",
                     "image_width_px", "image_height_px"});
    if (failed())
        return c;
    if (named && c.name.empty())
        fail(join(p, "name"), "must not be empty");
    else if (auto s = sensor::validate(c); !s)
        fail(p, s.error().message);
    return c;
}

fleet::PlanePerformance JsonReader::plane(const CPLJSONObject& o, const std::string& path) {
    fleet::PlanePerformance p;
    if (!expectType(o, path, o.GetType() == CPLJSONObject::Type::Object, "an object"))
        return p;
    p.minTurnRadiusM = optionalNumber(o, path, "turn_radius_m");
    p.maxBankDeg = optionalNumber(o, path, "bank_deg");
    p.climbRateMps = number(o, path, "climb_rate_mps", p.climbRateMps);
    p.sinkRateMps = number(o, path, "sink_rate_mps", p.sinkRateMps);
    p.runInM = number(o, path, "run_in_m", p.runInM);
    p.stallSpeedMps = optionalNumber(o, path, "stall_speed_mps");
    checkKeys(o, path,
              {"turn_radius_m", "bank_deg", "climb_rate_mps", "sink_rate_mps", "run_in_m",
               "stall_speed_mps"});
    return p;
}

} // namespace pf::io::detail
