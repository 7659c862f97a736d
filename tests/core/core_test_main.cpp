// Entry point of pf_core_tests. CTest runs every test in its own process, two or more at a time, so
// each process gets its own scratch directory (TMPDIR and TEST_TMPDIR point into it): temporary
// files named by the tests, and by the photoflight-cli runs they start, can never collide.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    const char* base = std::getenv("TMPDIR");
    std::string pattern = std::string(base && *base ? base : "/tmp") + "/pf_core_tests_XXXXXX";
    std::vector<char> buf(pattern.begin(), pattern.end());
    buf.push_back('\0');
    const char* dir = mkdtemp(buf.data());
    if (dir) {
        setenv("TMPDIR", dir, 1);
        setenv("TEST_TMPDIR", dir, 1);
    }
    ::testing::InitGoogleTest(&argc, argv);
    const int rc = RUN_ALL_TESTS();
    if (dir) {
        std::error_code ec;
        std::filesystem::remove_all(dir, ec);
    }
    return rc;
}
