#include "core/data_dir.h"

#include <cstdlib>
#include <sys/stat.h>
#include <unistd.h>

namespace pf {

bool isFile(const std::string& path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

std::vector<std::string> dataDirectoryCandidates() {
    std::vector<std::string> dirs;
    if (const char* env = std::getenv("PHOTOFLIGHT_DATA_DIR"); env && *env)
        dirs.emplace_back(env);
    // A relocated installation: <prefix>/bin/photoflight-cli next to <prefix>/share/photoflight.
    char exe[4096];
    const ssize_t n = ::readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n > 0) {
        std::string p(exe, static_cast<std::size_t>(n));
        const auto slash = p.find_last_of('/');
        if (slash != std::string::npos)
            dirs.push_back(p.substr(0, slash) + "/../share/photoflight");
    }
    if (*PF_INSTALL_DATA_DIR)
        dirs.emplace_back(PF_INSTALL_DATA_DIR);
    if (*PF_SOURCE_DATA_DIR)
        dirs.emplace_back(PF_SOURCE_DATA_DIR);
    return dirs;
}

std::string dataDirectory() {
    for (const auto& dir : dataDirectoryCandidates())
        if (isFile(dir + "/catalog.json"))
            return dir;
    return "";
}

} // namespace pf
