// Helpers shared by the libFuzzer harnesses: a scratch file for readers that take a path.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <cerrno>
#include <cstdlib>
#include <sys/stat.h>
#include <unistd.h>

namespace pf::fuzz {

// Writes the input to <tmp>/pf-fuzz-<pid>/input<ext> and returns that path. One file per process,
// rewritten for every input, so a long run leaves one small file behind and never fills the disk.
inline std::string writeScratch(const uint8_t* data, std::size_t size, const std::string& ext) {
    const char* tmp = std::getenv("TMPDIR");
    const std::string dir =
        std::string(tmp && *tmp ? tmp : "/tmp") + "/pf-fuzz-" + std::to_string(::getpid());
    static const bool made = [&] { return ::mkdir(dir.c_str(), 0700) == 0 || errno == EEXIST; }();
    (void)made;
    const std::string path = dir + "/input" + ext;
    if (std::FILE* f = std::fopen(path.c_str(), "wb")) {
        if (size > 0) std::fwrite(data, 1, size, f);
        std::fclose(f);
    }
    return path;
}

} // namespace pf::fuzz
