// A simulated vehicle (sim_vehicle.mjs) as a child process of a test, on loopback; stopped when
// the object goes.
#pragma once

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <vector>

namespace pf::test {

class Peer {
public:
    explicit Peer(const std::vector<std::string>& args) {
        int out[2];
        if (pipe(out) != 0)
            return;
        m_pid = fork();
        if (m_pid == 0) {
            dup2(out[1], 1);
            close(out[0]);
            close(out[1]);
            std::vector<std::string> all = {PF_NODE_PATH, PF_PEER_SCRIPT};
            all.insert(all.end(), args.begin(), args.end());
            std::vector<char*> argv;
            for (auto& a : all)
                argv.push_back(a.data());
            argv.push_back(nullptr);
            execv(argv[0], argv.data());
            _exit(127);
        }
        close(out[1]);
        m_out = out[0];
        // Wait (at most 20 s: node starts slowly on a loaded machine) for "READY <port>".
        std::string line;
        pollfd p{m_out, POLLIN, 0};
        const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
        while (std::chrono::steady_clock::now() < until && line.find('\n') == std::string::npos) {
            if (poll(&p, 1, 200) > 0) {
                char buf[128];
                const ssize_t n = read(m_out, buf, sizeof buf);
                if (n <= 0)
                    break;
                line.append(buf, std::size_t(n));
            }
        }
        if (line.rfind("READY ", 0) == 0)
            m_port = std::stoi(line.substr(6));
    }
    ~Peer() {
        if (m_pid > 0) {
            kill(m_pid, SIGTERM);
            int st = 0;
            waitpid(m_pid, &st, 0);
        }
        if (m_out >= 0)
            close(m_out);
    }
    Peer(const Peer&) = delete;
    Peer& operator=(const Peer&) = delete;
    int port() const { return m_port; }

private:
    pid_t m_pid = -1;
    int m_out = -1;
    int m_port = 0;
};

} // namespace pf::test
