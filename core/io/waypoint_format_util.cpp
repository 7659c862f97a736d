#include "core/io/waypoint_format_util.h"

#include "core/io/json_reader.h"

#include <cpl_error.h>
#include <cpl_vsi.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace pf::io::detail {

namespace {

// Keeps GDAL quiet while we turn its errors into messages of our own.
class QuietGdal {
public:
    QuietGdal() {
        CPLErrorReset();
        CPLPushErrorHandler(CPLQuietErrorHandler);
    }
    ~QuietGdal() { CPLPopErrorHandler(); }
    QuietGdal(const QuietGdal&) = delete;
    QuietGdal& operator=(const QuietGdal&) = delete;
};

} // namespace

std::string formatNumber(double v, int decimals) {
    if (!std::isfinite(v))
        return "0";
    char buf[64];
    auto res = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
    std::string s(buf, res.ptr);
    if (s.find('.') != std::string::npos) {
        while (!s.empty() && s.back() == '0')
            s.pop_back();
        if (!s.empty() && s.back() == '.')
            s.pop_back();
    }
    if (s == "-0")
        s = "0";
    return s;
}

std::optional<double> parseNumber(std::string_view text) {
    text = trim(text);
    if (!text.empty() && text.front() == '+')
        text.remove_prefix(1);
    if (text.empty())
        return std::nullopt;
    double v = 0.0;
    auto res = std::from_chars(text.data(), text.data() + text.size(), v);
    if (res.ec != std::errc() || res.ptr != text.data() + text.size() || !std::isfinite(v))
        return std::nullopt;
    return v;
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front())))
        s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back())))
        s.remove_suffix(1);
    return s;
}

std::vector<std::string_view> splitLines(std::string_view text) {
    if (text.size() >= 3 && text.compare(0, 3, "\xEF\xBB\xBF") == 0)
        text.remove_prefix(3);
    std::vector<std::string_view> lines;
    while (!text.empty()) {
        const auto nl = text.find('\n');
        std::string_view line = text.substr(0, nl);
        if (!line.empty() && line.back() == '\r')
            line.remove_suffix(1);
        lines.push_back(line);
        if (nl == std::string_view::npos)
            break;
        text.remove_prefix(nl + 1);
    }
    return lines;
}

std::vector<std::string_view> splitChar(std::string_view line, char sep) {
    std::vector<std::string_view> out;
    for (;;) {
        const auto p = line.find(sep);
        out.push_back(line.substr(0, p));
        if (p == std::string_view::npos)
            break;
        line.remove_prefix(p + 1);
    }
    return out;
}

std::vector<std::string_view> splitFields(std::string_view line) {
    line = trim(line);
    if (line.find('\t') != std::string_view::npos) {
        auto f = splitChar(line, '\t');
        for (auto& x : f)
            x = trim(x);
        return f;
    }
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && line[i] == ' ')
            ++i;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ')
            ++i;
        if (i > start)
            out.push_back(line.substr(start, i - start));
    }
    return out;
}

Result<std::string> readTextFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return makeError(ErrorCode::IoError, "cannot open " + path + ": " + std::strerror(errno));
    std::ostringstream ss;
    ss << in.rdbuf();
    if (in.bad())
        return makeError(ErrorCode::IoError, "cannot read " + path);
    return ss.str();
}

Status writeTextFile(const std::string& path, const std::string& text) {
    const std::string tmp = path + ".part";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out)
            return makeError(ErrorCode::IoError,
                             "cannot write " + path + ": " + std::strerror(errno));
        out << text;
        out.flush();
        if (!out) {
            std::remove(tmp.c_str());
            return makeError(ErrorCode::IoError, "cannot write " + path + " (disk full?)");
        }
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        const std::string why = std::strerror(errno);
        std::remove(tmp.c_str());
        return makeError(ErrorCode::IoError, "cannot replace " + path + ": " + why);
    }
    return {};
}

Error lineError(const std::string& source, std::size_t line, const std::string& what) {
    return makeError(ErrorCode::ParseError,
                     source + ": line " + std::to_string(line) + ": " + what);
}

Result<CPLJSONObject> parseJson(const std::string& rawText, const std::string& source) {
    const bool bom = rawText.size() >= 3 && rawText.compare(0, 3, "\xEF\xBB\xBF") == 0;
    const std::string text = bom ? rawText.substr(3) : rawText;
    if (trim(text).empty())
        return makeError(ErrorCode::ParseError, source + ": the file is empty");
    CPLJSONDocument doc;
    std::string msg;
    bool ok = false;
    {
        QuietGdal quiet;
        ok = doc.LoadMemory(text);
        msg = CPLGetLastErrorMsg();
    }
    if (!ok) {
        // json-c reports a byte offset; people edit files by line.
        std::size_t offset = text.size();
        if (auto p = msg.find("at offset "); p != std::string::npos)
            offset =
                std::min<std::size_t>(std::strtoul(msg.c_str() + p + 10, nullptr, 10), text.size());
        const TextPosition at = textPositionAt(text, offset);
        std::string why = msg;
        if (auto p = why.find("JSON parsing error: "); p != std::string::npos)
            why = why.substr(p + 20);
        if (auto p = why.find(" (at offset"); p != std::string::npos)
            why = why.substr(0, p);
        if (why.empty())
            why = "not valid JSON";
        else if (why == "continue") // json-c's word for input that stops mid-document
            why = "the file ends before the JSON is complete";
        return makeError(ErrorCode::ParseError, source + ": line " + std::to_string(at.line) +
                                                    ", column " + std::to_string(at.column) +
                                                    ": invalid JSON (" + why + ")");
    }
    CPLJSONObject root = doc.GetRoot();
    if (root.GetType() != CPLJSONObject::Type::Object)
        return makeError(ErrorCode::ParseError,
                         source + ": expected a JSON object at the top level");
    return root;
}

const char* kindName(route::WaypointKind kind) {
    switch (kind) {
    case route::WaypointKind::Photo:
        return "photo";
    case route::WaypointKind::Turn:
        return "turn";
    case route::WaypointKind::Transit:
        return "transit";
    }
    return "photo";
}

std::optional<route::WaypointKind> kindFromName(std::string_view name) {
    std::string n(trim(name));
    std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return std::tolower(c); });
    if (n == "photo")
        return route::WaypointKind::Photo;
    if (n == "turn")
        return route::WaypointKind::Turn;
    if (n == "transit")
        return route::WaypointKind::Transit;
    return std::nullopt;
}

void inferNonPhotoKinds(std::vector<route::Waypoint>& waypoints, const std::vector<bool>& isPhoto) {
    const auto first = std::find(isPhoto.begin(), isPhoto.end(), true);
    const auto last = std::find(isPhoto.rbegin(), isPhoto.rend(), true);
    const std::size_t firstPhoto = static_cast<std::size_t>(first - isPhoto.begin());
    const std::size_t lastPhoto =
        isPhoto.size() - 1 - static_cast<std::size_t>(last - isPhoto.rbegin());
    for (std::size_t i = 0; i < waypoints.size(); ++i) {
        if (isPhoto[i])
            waypoints[i].kind = route::WaypointKind::Photo;
        else if (first == isPhoto.end() || i < firstPhoto || i > lastPhoto)
            waypoints[i].kind = route::WaypointKind::Transit;
        else
            waypoints[i].kind = route::WaypointKind::Turn;
    }
}

std::string waypointPositionProblem(double lon, double lat, double alt) {
    if (!std::isfinite(lat))
        return "the latitude is not a number";
    if (!std::isfinite(lon))
        return "the longitude is not a number";
    if (std::abs(lat) > 90)
        return "latitude " + formatNumber(lat, 7) + " is out of range (-90 to 90)";
    if (std::abs(lon) > 180)
        return "longitude " + formatNumber(lon, 7) + " is out of range (-180 to 180)";
    if (!std::isfinite(alt))
        return "the altitude is not a number";
    return {};
}

double normaliseHeading(double deg) {
    double d = std::fmod(deg, 360.0);
    if (d < 0)
        d += 360.0;
    return d >= 360.0 ? 0.0 : d;
}

std::string extensionOf(const std::string& path) {
    const auto slash = path.find_last_of("/\\");
    const auto dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
        return "";
    std::string ext = path.substr(dot);
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    return ext;
}

std::string baseName(const std::string& path) {
    const auto slash = path.find_last_of("/\\");
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string lastGdalError(const std::string& fallback) {
    const char* msg = CPLGetLastErrorMsg();
    return msg && *msg ? std::string(msg) : fallback;
}

Status closeDataset(DatasetPtr& ds, const std::string& path) {
    QuietGdal quiet;
    GDALClose(ds.release());
    if (CPLGetLastErrorType() >= CE_Failure)
        return makeError(ErrorCode::IoError,
                         "cannot finish " + path + ": " + lastGdalError("the write failed"));
    return {};
}

Result<DatasetPtr> createVectorDataset(const char* driverName, const std::string& path,
                                       const std::vector<std::string>& options) {
    GDALAllRegister();
    GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(driverName);
    if (!driver)
        return makeError(ErrorCode::Unsupported, std::string("cannot write ") + path +
                                                     ": this GDAL has no " + driverName +
                                                     " driver");
    QuietGdal quiet;
    VSIStatBufL st;
    if (VSIStatL(path.c_str(), &st) == 0 && VSIUnlink(path.c_str()) != 0)
        return makeError(ErrorCode::IoError,
                         "cannot replace " + path + ": " + std::strerror(errno));
    std::vector<char*> opts;
    for (const auto& o : options)
        opts.push_back(const_cast<char*>(o.c_str()));
    opts.push_back(nullptr);
    GDALDataset* ds = driver->Create(path.c_str(), 0, 0, 0, GDT_Unknown, opts.data());
    if (!ds)
        return makeError(ErrorCode::IoError,
                         "cannot write " + path + ": " + lastGdalError("GDAL could not create it"));
    return DatasetPtr(ds);
}

Result<DatasetPtr> openVectorDataset(const std::string& path, const char* driverName) {
    GDALAllRegister();
    VSIStatBufL st;
    if (VSIStatL(path.c_str(), &st) != 0)
        return makeError(ErrorCode::IoError, "cannot open " + path + ": no such file");
    if (st.st_size == 0)
        return makeError(ErrorCode::ParseError, path + ": the file is empty");
    QuietGdal quiet;
    const char* drivers[] = {driverName, nullptr};
    auto* ds = static_cast<GDALDataset*>(
        GDALOpenEx(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, drivers, nullptr, nullptr));
    if (!ds)
        return makeError(ErrorCode::ParseError,
                         path + ": not a readable " + driverName + " file (" +
                             lastGdalError("GDAL did not recognise its content") + ")");
    return DatasetPtr(ds);
}

std::unique_ptr<OGRPolygon> toOgrPolygon(const geo::GeoPolygon& p) {
    auto poly = std::make_unique<OGRPolygon>();
    auto ring = [](const geo::GeoRing& r) {
        auto* lr = new OGRLinearRing();
        for (const auto& v : r)
            lr->addPoint(v.lon, v.lat);
        if (!r.empty())
            lr->addPoint(r.front().lon, r.front().lat);
        return lr;
    };
    poly->addRingDirectly(ring(p.outer));
    for (const auto& h : p.holes)
        poly->addRingDirectly(ring(h));
    return poly;
}

} // namespace pf::io::detail
