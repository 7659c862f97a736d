#include "core/mosaic/photo_metadata.h"

#include "core/geo/gdal_util.h"

#include <cpl_string.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <vector>

namespace pf::mosaic {

namespace {

std::string trim(std::string s) {
    auto notSpace = [](unsigned char c) { return !std::isspace(c) && c != '\0'; };
    s.erase(s.begin(), std::find_if(s.begin(), s.end(), notSpace));
    s.erase(std::find_if(s.rbegin(), s.rend(), notSpace).base(), s.end());
    return s;
}

// Every number in the text, in order: "(49) (0) (43.2)" -> 49, 0, 43.2; "0x01" -> 1.
std::vector<double> numbers(const std::string& text) {
    std::vector<double> out;
    const char* p = text.c_str();
    while (*p) {
        if (std::isdigit(static_cast<unsigned char>(*p)) ||
            ((*p == '-' || *p == '+' || *p == '.') && p[1] &&
             (std::isdigit(static_cast<unsigned char>(p[1])) || p[1] == '.'))) {
            char* end = nullptr;
            const bool hex = p[0] == '0' && (p[1] == 'x' || p[1] == 'X');
            const double v =
                hex ? static_cast<double>(std::strtol(p, &end, 16)) : std::strtod(p, &end);
            if (end == p) {
                ++p;
                continue;
            }
            out.push_back(v);
            p = end;
        } else {
            ++p;
        }
    }
    return out;
}

} // namespace

namespace detail {

std::optional<double> exifNumber(const std::string& text, int index) {
    const auto v = numbers(text);
    if (index < 0 || index >= static_cast<int>(v.size()) || !std::isfinite(v[index]))
        return std::nullopt;
    return v[index];
}

std::optional<double> exifDegrees(const std::string& triple, const std::string& ref) {
    const auto v = numbers(triple);
    if (v.empty())
        return std::nullopt;
    double deg = v[0] + (v.size() > 1 ? v[1] / 60.0 : 0.0) + (v.size() > 2 ? v[2] / 3600.0 : 0.0);
    const std::string r = trim(ref);
    if (!r.empty() && (r[0] == 'S' || r[0] == 's' || r[0] == 'W' || r[0] == 'w'))
        deg = -deg;
    if (!std::isfinite(deg))
        return std::nullopt;
    return deg;
}

std::optional<std::string> xmpProperty(const std::string& xmp, const std::string& localName) {
    // Attribute form: prefix:Name="value" (or single quotes).
    const std::string key = ":" + localName;
    for (std::size_t at = xmp.find(key); at != std::string::npos; at = xmp.find(key, at + 1)) {
        std::size_t p = at + key.size();
        // The local name must end here (GimbalYawDegree must not match GimbalYawDegreeX).
        while (p < xmp.size() && std::isspace(static_cast<unsigned char>(xmp[p])))
            ++p;
        if (p < xmp.size() && xmp[p] == '=') {
            ++p;
            while (p < xmp.size() && std::isspace(static_cast<unsigned char>(xmp[p])))
                ++p;
            if (p < xmp.size() && (xmp[p] == '"' || xmp[p] == '\'')) {
                const char quote = xmp[p];
                const std::size_t end = xmp.find(quote, p + 1);
                if (end != std::string::npos)
                    return trim(xmp.substr(p + 1, end - p - 1));
            }
        } else if (p < xmp.size() && xmp[p] == '>' && at > 0) {
            // Element form: <prefix:Name>value</prefix:Name>; the '<' and prefix precede `at`.
            const std::size_t open = xmp.rfind('<', at);
            if (open == std::string::npos || xmp.find_first_of(" \t\r\n>", open) < at)
                continue;
            const std::size_t end = xmp.find('<', p + 1);
            if (end != std::string::npos)
                return trim(xmp.substr(p + 1, end - p - 1));
        }
    }
    return std::nullopt;
}

std::optional<double> xmpNumber(const std::string& xmp, const std::string& localName) {
    const auto text = xmpProperty(xmp, localName);
    if (!text || text->empty())
        return std::nullopt;
    char* end = nullptr;
    const double v = std::strtod(text->c_str(), &end);
    if (end == text->c_str() || !std::isfinite(v))
        return std::nullopt;
    return v;
}

} // namespace detail

namespace {

std::string item(GDALDataset& ds, const char* key) {
    const char* v = ds.GetMetadataItem(key);
    return v ? trim(v) : std::string();
}

std::optional<double> itemNumber(GDALDataset& ds, const char* key) {
    const std::string v = item(ds, key);
    return v.empty() ? std::nullopt : detail::exifNumber(v);
}

} // namespace

Result<PhotoMetadata> readPhotoMetadata(const std::string& path) {
    const std::string name = geo::detail::fileName(path);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        return makeError(ErrorCode::IoError, name + ": no such file");
    geo::detail::GdalErrorCapture errors;
    auto ds = geo::detail::openRaster(path);
    if (!ds)
        return makeError(
            ErrorCode::ParseError,
            name + ": not an image GDAL can read" +
                (errors.message().empty() ? std::string() : " (" + errors.message() + ")"));
    PhotoMetadata m;
    m.path = path;
    m.widthPx = ds->GetRasterXSize();
    m.heightPx = ds->GetRasterYSize();
    const int bands = ds->GetRasterCount();
    if (m.widthPx < 2 || m.heightPx < 2 || (bands != 1 && bands != 3 && bands != 4))
        return makeError(ErrorCode::Unsupported,
                         name + ": expected an RGB or grey photo but found " +
                             std::to_string(bands) + " band(s) of " + std::to_string(m.widthPx) +
                             " x " + std::to_string(m.heightPx) + " px");
    if (ds->GetRasterBand(1)->GetRasterDataType() != GDT_Byte)
        return makeError(ErrorCode::Unsupported, name + ": expected 8-bit samples (a JPEG photo)");

    if (auto o = itemNumber(*ds, "EXIF_Orientation"); o && *o >= 1 && *o <= 8)
        m.orientation = static_cast<int>(*o);
    const auto lat =
        detail::exifDegrees(item(*ds, "EXIF_GPSLatitude"), item(*ds, "EXIF_GPSLatitudeRef"));
    const auto lon =
        detail::exifDegrees(item(*ds, "EXIF_GPSLongitude"), item(*ds, "EXIF_GPSLongitudeRef"));
    // Cameras without a fix write zeros; (0, 0) is in the Gulf of Guinea, not a survey site.
    if (lat && lon && std::abs(*lat) <= 90 && std::abs(*lon) <= 180 &&
        !(*lat == 0.0 && *lon == 0.0))
        m.position = geo::LonLat{*lon, *lat};
    if (auto alt = itemNumber(*ds, "EXIF_GPSAltitude")) {
        const auto ref = itemNumber(*ds, "EXIF_GPSAltitudeRef");
        m.gpsAltitudeM = (ref && *ref == 1.0) ? -*alt : *alt;
    }
    if (auto dir = itemNumber(*ds, "EXIF_GPSImgDirection")) {
        m.imageDirectionDeg = *dir;
        const std::string ref = item(*ds, "EXIF_GPSImgDirectionRef");
        m.imageDirectionMagnetic = !ref.empty() && (ref[0] == 'M' || ref[0] == 'm');
    }
    m.make = item(*ds, "EXIF_Make");
    m.model = item(*ds, "EXIF_Model");
    m.focalLengthMm = itemNumber(*ds, "EXIF_FocalLength");
    if (auto f35 = itemNumber(*ds, "EXIF_FocalLengthIn35mmFilm"); f35 && *f35 > 0)
        m.focalLength35mmMm = *f35;
    m.dateTime = item(*ds, "EXIF_DateTimeOriginal");
    if (m.dateTime.empty())
        m.dateTime = item(*ds, "EXIF_DateTime");
    if (!m.dateTime.empty()) {
        const std::string sub = item(*ds, "EXIF_SubSecTimeOriginal");
        if (!sub.empty())
            m.dateTime += "." + sub;
    }

    if (char** xmpList = ds->GetMetadata("xml:XMP"); xmpList && xmpList[0]) {
        const std::string xmp = xmpList[0];
        m.hasXmp = true;
        m.relativeAltitudeM = detail::xmpNumber(xmp, "RelativeAltitude");
        m.absoluteAltitudeM = detail::xmpNumber(xmp, "AbsoluteAltitude");
        m.gimbalPitchDeg = detail::xmpNumber(xmp, "GimbalPitchDegree");
        m.gimbalYawDeg = detail::xmpNumber(xmp, "GimbalYawDegree");
        m.gimbalRollDeg = detail::xmpNumber(xmp, "GimbalRollDegree");
        m.flightYawDeg = detail::xmpNumber(xmp, "FlightYawDegree");
        if (!m.position) {
            const auto xlat = detail::xmpNumber(xmp, "GpsLatitude");
            // Some firmware spells it "GpsLongtitude".
            auto xlon = detail::xmpNumber(xmp, "GpsLongitude");
            if (!xlon)
                xlon = detail::xmpNumber(xmp, "GpsLongtitude");
            if (xlat && xlon && std::abs(*xlat) <= 90 && std::abs(*xlon) <= 180 &&
                !(*xlat == 0.0 && *xlon == 0.0))
                m.position = geo::LonLat{*xlon, *xlat};
        }
    }
    return m;
}

Status checkPhotoDecodes(const std::string& path) {
    const std::string name = geo::detail::fileName(path);
    // libjpeg's complaints about damaged data are warnings by default; here they are failures.
    CPLConfigOptionSetter strict("GDAL_ERROR_ON_LIBJPEG_WARNING", "TRUE", true);
    geo::detail::GdalErrorCapture errors;
    auto ds = geo::detail::openRaster(path);
    if (!ds)
        return makeError(ErrorCode::ParseError, name + ": not an image GDAL can read");
    GDALRasterBand* band = ds->GetRasterBand(1);
    const int nOvr = band->GetOverviewCount();
    GDALRasterBand* smallest = nOvr > 0 ? band->GetOverview(nOvr - 1) : band;
    const int w = smallest->GetXSize(), h = smallest->GetYSize();
    std::vector<GByte> buf(static_cast<std::size_t>(w) * h);
    const CPLErr err =
        smallest->RasterIO(GF_Read, 0, 0, w, h, buf.data(), w, h, GDT_Byte, 0, 0, nullptr);
    if (err != CE_None || errors.failed() || errors.warned()) {
        std::string why = errors.message();
        if (why.empty())
            why = "the image data cannot be decoded";
        return makeError(ErrorCode::ParseError, name + ": the image data is damaged (" + why + ")");
    }
    return {};
}

} // namespace pf::mosaic
