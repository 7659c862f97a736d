// Runs the real photoflight-cli with arguments and captures its exit code, stdout and stderr, for
// the CLI tests.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace pf::test {

struct CliRun {
    int code = -1;
    std::string out;
    std::string err;
};

inline std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

inline CliRun cli(const std::string& args) {
    static int counter = 0;
    const std::string errPath =
        testing::TempDir() + "pf_cli_stderr_" + std::to_string(++counter) + ".txt";
    const std::string cmd = std::string("'") + PF_CLI_PATH + "' " + args + " 2>'" + errPath + "'";
    CliRun r;
    FILE* p = popen(cmd.c_str(), "r");
    if (!p)
        return r;
    char buf[4096];
    std::size_t n;
    while ((n = fread(buf, 1, sizeof buf, p)) > 0)
        r.out.append(buf, n);
    const int status = pclose(p);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.err = slurp(errPath);
    std::remove(errPath.c_str());
    return r;
}

inline bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// A bad input: exit code 2 and the expected message on stderr.
inline void expectBadInput(const std::string& args, const std::string& message) {
    SCOPED_TRACE(args);
    const CliRun r = cli(args);
    EXPECT_EQ(r.code, 2) << r.out << r.err;
    EXPECT_TRUE(has(r.err, "photoflight-cli: error: ")) << "stderr was: " << r.err;
    EXPECT_TRUE(has(r.err, message)) << "stderr was: " << r.err;
}

} // namespace pf::test
