#include "core/io/wpml/kmz_archive.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_string.h>
#include <cpl_vsi.h>
#include <minizip/zip.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <memory>

namespace pf::io::wpml {

namespace {

class QuietErrors {
public:
    QuietErrors() {
        CPLErrorReset();
        CPLPushErrorHandler(CPLQuietErrorHandler);
    }
    ~QuietErrors() { CPLPopErrorHandler(); }
    QuietErrors(const QuietErrors&) = delete;
    QuietErrors& operator=(const QuietErrors&) = delete;
};

// GDAL's name of a file inside a ZIP archive; the braces let the archive's path hold any character.
std::string vsiPath(const std::string& archive, const std::string& inside = {}) {
    return "/vsizip/{" + archive + "}" + (inside.empty() ? "" : "/" + inside);
}

// The DOS date and time of an archive entry (local time, as ZIP stores it): the ZIP format cannot
// say 1979 or earlier.
zip_fileinfo entryInfo(std::time_t modified) {
    zip_fileinfo info{};
    std::tm local{};
    if (!localtime_r(&modified, &local) || local.tm_year < 80)
        local = std::tm{0, 0, 0, 1, 0, 80, 0, 0, 0, 0, nullptr}; // 1980-01-01 00:00
    info.tmz_date.tm_sec = static_cast<uInt>(local.tm_sec);
    info.tmz_date.tm_min = static_cast<uInt>(local.tm_min);
    info.tmz_date.tm_hour = static_cast<uInt>(local.tm_hour);
    info.tmz_date.tm_mday = static_cast<uInt>(local.tm_mday);
    info.tmz_date.tm_mon = static_cast<uInt>(local.tm_mon);
    info.tmz_date.tm_year = static_cast<uInt>(local.tm_year + 1900);
    return info;
}

Status writeEntries(zipFile zip, const std::string& path, const std::vector<ArchiveEntry>& entries,
                    std::time_t modified) {
    const zip_fileinfo info = entryInfo(modified);
    for (const auto& e : entries) {
        if (e.data.size() > static_cast<std::size_t>(UINT_MAX))
            return makeError(ErrorCode::IoError,
                             "cannot write " + path + ": " + e.name + " is too large");
        if (zipOpenNewFileInZip64(zip, e.name.c_str(), &info, nullptr, 0, nullptr, 0, nullptr,
                                  Z_DEFLATED, Z_DEFAULT_COMPRESSION, 0) != ZIP_OK ||
            zipWriteInFileInZip(zip, e.data.data(), static_cast<unsigned>(e.data.size())) !=
                ZIP_OK ||
            zipCloseFileInZip(zip) != ZIP_OK)
            return makeError(ErrorCode::IoError, "cannot write " + path + " (disk full?)");
    }
    return {};
}

} // namespace

Status writeZipArchive(const std::string& path, const std::vector<ArchiveEntry>& entries,
                       std::time_t modified) {
    const std::string tmp = path + ".part";
    zipFile zip = zipOpen64(tmp.c_str(), APPEND_STATUS_CREATE);
    if (!zip)
        return makeError(ErrorCode::IoError,
                         "cannot write " + path + ": " + std::strerror(errno));
    Status written = writeEntries(zip, path, entries, modified);
    if (zipClose(zip, nullptr) != ZIP_OK && written)
        written = makeError(ErrorCode::IoError, "cannot write " + path + " (disk full?)");
    if (!written) {
        std::remove(tmp.c_str());
        return written;
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        const std::string why = std::strerror(errno);
        std::remove(tmp.c_str());
        return makeError(ErrorCode::IoError, "cannot replace " + path + ": " + why);
    }
    return {};
}

Result<std::vector<std::string>> zipArchiveFiles(const std::string& path) {
    VSIStatBufL st;
    if (VSIStatL(path.c_str(), &st) != 0 || VSI_ISDIR(st.st_mode))
        return makeError(ErrorCode::IoError, path + ": cannot read the file (missing or a folder)");
    QuietErrors quiet;
    std::unique_ptr<char*, decltype(&CSLDestroy)> list(VSIReadDirRecursive(vsiPath(path).c_str()),
                                                       &CSLDestroy);
    if (!list)
        return makeError(ErrorCode::ParseError, path + ": not a KMZ file: it is not a ZIP archive");
    std::vector<std::string> files;
    for (char** p = list.get(); *p; ++p) {
        std::string name = *p;
        VSIStatBufL entry;
        if (VSIStatL(vsiPath(path, name).c_str(), &entry) == 0 && !VSI_ISDIR(entry.st_mode))
            files.push_back(name);
    }
    return files;
}

Result<std::string> readZipArchiveFile(const std::string& path, const std::string& name) {
    QuietErrors quiet;
    VSILFILE* f = VSIFOpenL(vsiPath(path, name).c_str(), "rb");
    if (!f)
        return makeError(ErrorCode::NotFound, path + ": the archive holds no " + name);
    std::string data;
    char buf[65536];
    std::size_t n = 0;
    while ((n = VSIFReadL(buf, 1, sizeof buf, f)) > 0)
        data.append(buf, n);
    VSIFCloseL(f);
    return data;
}

} // namespace pf::io::wpml
