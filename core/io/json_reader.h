// Checked reading of a JSON document (GDAL's CPLJSON) for the mission file and the catalog: typed
// fields with defaults, required fields, unknown-field detection, positions, polygons and cameras; the
// first problem becomes "<source>: <field path>: <what>". Internal to io: include from .cpp files only.
#pragma once

#include "core/fleet/aircraft.h"
#include "core/geo/types.h"
#include "core/result.h"
#include "core/sensor/camera.h"

#include <cpl_json.h>

#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>

namespace pf::io::detail {

// Parses JSON text into `doc` (a UTF-8 byte-order mark, as Windows editors write, is skipped). Errors:
// "<source>: not valid JSON: <what> at line L, column C".
Status loadJsonText(CPLJSONDocument& doc, const std::string& text, const std::string& source);

// Turns GDAL's JSON parser message ("... (at offset 11)") into words with a line and column.
std::string describeJsonError(const std::string& text, const std::string& gdalMessage);

// The line and column (both from 1) of byte `offset` of `text`, as people who edit the file count.
struct TextPosition {
    std::size_t line = 1;
    std::size_t column = 1;
};
TextPosition textPositionAt(const std::string& text, std::size_t offset);

// Reads fields of one document; readers of a format derive from it and add their own objects.
class JsonReader {
public:
    // `separator` joins a path and a member's key in messages: "." for "aircraft[0].camera" (the
    // mission file), ": " for "cameras[1] (\"Cam\"): sensor_width_mm" (the catalog).
    explicit JsonReader(std::string source, std::string separator = ".")
        : m_source(std::move(source)), m_separator(std::move(separator)) {}

    bool failed() const { return m_error.has_value(); }
    Error error() const { return *m_error; }

    // Remembers the first problem only: later ones are usually its consequences.
    void fail(const std::string& path, const std::string& what);

    static const char* typeName(const CPLJSONObject& o);

    static bool isNumber(const CPLJSONObject& o);

    // "path<separator>key", or the key alone at the top level.
    std::string join(const std::string& path, const std::string& key) const;

    // The member `key` of `parent`, or an invalid object when absent (JSON null counts as absent).
    static CPLJSONObject member(const CPLJSONObject& parent, const std::string& key);

    // A misspelt optional field would otherwise be ignored and its default used without a word, which
    // for a safety margin or an overlap is worse than refusing the file. "note" is allowed anywhere
    // for the user's own remarks.
    void checkKeys(const CPLJSONObject& o, const std::string& path, std::initializer_list<const char*> known,
                   const char* separator = nullptr);

    bool expectType(const CPLJSONObject& o, const std::string& path, bool ok, const char* expected);

    double number(const CPLJSONObject& o, const std::string& path);

    double number(const CPLJSONObject& parent, const std::string& path, const std::string& key, double def,
                  bool required = false);

    std::optional<double> optionalNumber(const CPLJSONObject& parent, const std::string& path,
                                         const std::string& key);

    long long integer(const CPLJSONObject& parent, const std::string& path, const std::string& key,
                      long long def, bool required, long long minValue, long long maxValue);

    std::string string(const CPLJSONObject& parent, const std::string& path, const std::string& key,
                       const std::string& def, bool required = false);

    bool boolean(const CPLJSONObject& parent, const std::string& path, const std::string& key, bool def);

    CPLJSONObject object(const CPLJSONObject& parent, const std::string& path, const std::string& key,
                         bool required);

    // The value as an array, or an empty array (and the error) when it is something else.
    CPLJSONArray array(const CPLJSONObject& o, const std::string& path);

    geo::LonLat position(const CPLJSONObject& o, const std::string& path);

    std::optional<geo::LonLat> optionalPosition(const CPLJSONObject& parent, const std::string& path,
                                                const std::string& key);

    geo::GeoRing ring(const CPLJSONObject& o, const std::string& path);

    // {"outer": ring, "holes": [ring, ...]}: rings of [longitude, latitude] positions, stored open.
    geo::GeoPolygon polygon(const CPLJSONObject& parent, const std::string& path, const std::string& key);

    // A camera object as the mission file and the catalog store it: optics or field of view, image
    // size in pixels, checked by sensor::validate. `named`: the name is required and not empty, and
    // the messages after it name the camera: "cameras[3] ("Sony RX1R II"): focal_length_mm: ...".
    sensor::Camera camera(const CPLJSONObject& o, const std::string& path, bool named = false);

    // The "plane" object of an aircraft (detail::planeToJson): absent values keep their defaults.
    fleet::PlanePerformance plane(const CPLJSONObject& o, const std::string& path);

private:
    std::string m_source;
    std::string m_separator;
    std::optional<Error> m_error;
};

} // namespace pf::io::detail
