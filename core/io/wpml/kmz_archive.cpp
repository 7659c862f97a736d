#include "core/io/wpml/kmz_archive.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_string.h>
#include <cpl_vsi.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
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

std::string gdalMessage() {
    const char* m = CPLGetLastErrorMsg();
    return m && *m ? std::string(": ") + m : std::string();
}

// GDAL's name of a file inside a ZIP archive; the braces let the archive's path hold any character.
std::string vsiPath(const std::string& archive, const std::string& inside = {}) {
    return "/vsizip/{" + archive + "}" + (inside.empty() ? "" : "/" + inside);
}

Status writeEntries(void* zip, const std::string& path, const std::vector<ArchiveEntry>& entries) {
    for (const auto& e : entries) {
        if (e.data.size() > static_cast<std::size_t>(INT_MAX))
            return makeError(ErrorCode::IoError,
                             "cannot write " + path + ": " + e.name + " is too large");
        if (CPLCreateFileInZip(zip, e.name.c_str(), nullptr) != CE_None ||
            CPLWriteFileInZip(zip, e.data.data(), static_cast<int>(e.data.size())) != CE_None ||
            CPLCloseFileInZip(zip) != CE_None)
            return makeError(ErrorCode::IoError, "cannot write " + path + gdalMessage());
    }
    return {};
}

} // namespace

Status writeZipArchive(const std::string& path, const std::vector<ArchiveEntry>& entries) {
    const std::string tmp = path + ".part";
    std::remove(tmp.c_str()); // CPLCreateZip would append to an archive left by a crash
    QuietErrors quiet;
    void* zip = CPLCreateZip(tmp.c_str(), nullptr);
    if (!zip)
        return makeError(ErrorCode::IoError, "cannot write " + path + gdalMessage());
    Status written = writeEntries(zip, path, entries);
    if (CPLCloseZip(zip) != CE_None && written)
        written =
            makeError(ErrorCode::IoError, "cannot write " + path + " (disk full?)" + gdalMessage());
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
