#include "x_server.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace penumbra::view {

const XServer& XServer::instance() {
    static const XServer server(
        (std::filesystem::temp_directory_path() / ("penumbra_view_test_xvfb_" + std::to_string(getpid()) + ".log"))
            .string());
    return server;
}

// -displayfd: the server picks a free display itself (no race with other test processes, as
// xvfb-run -a has) and writes its number once it accepts connections. -noreset: no reset (and no
// SIGUSR1) when a client disconnects; the tests run several clients one after the other.
XServer::XServer(const std::string& log) : log_(log) {
    int fds[2];
    if (pipe(fds) != 0) {
        error_ = std::string("pipe: ") + std::strerror(errno);
        return;
    }
    // Xvfb's own output (xkbcomp warnings) goes to its log, never into the stderr a test inspects.
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    // scripts/sanitize.sh preloads the sanitizer runtime into the tests: LeakSanitizer would fail Xvfb.
    std::vector<char*> env;
    for (char** e = environ; *e; ++e)
        if (std::strncmp(*e, "LD_PRELOAD=", 11) != 0) env.push_back(*e);
    env.push_back(nullptr);
    const std::string fd = std::to_string(fds[1]);
    const char* argv[] = {"Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1280x720x24", "-nolisten", "tcp",
                          "-noreset", nullptr};
    const int rc = posix_spawnp(&pid_, "Xvfb", &actions, nullptr, const_cast<char* const*>(argv), env.data());
    posix_spawn_file_actions_destroy(&actions);
    close(fds[1]);
    if (rc != 0) {
        pid_ = -1;
        error_ = std::string("cannot run Xvfb: ") + std::strerror(rc);
    } else {
        std::string number;
        pollfd ready{fds[0], POLLIN, 0};
        char c = 0;
        while (poll(&ready, 1, 30000) == 1 && read(fds[0], &c, 1) == 1 && c != '\n') number += c;
        if (number.empty()) error_ = "Xvfb did not start within 30 s (its output: " + log + ")";
        else display_ = ":" + number;
    }
    close(fds[0]);
}

XServer::~XServer() {
    if (pid_ <= 0) return;
    kill(pid_, SIGTERM);
    waitpid(pid_, nullptr, 0);
    if (error_.empty()) std::filesystem::remove(log_);
}

}  // namespace penumbra::view
