// One Xvfb per test process for the scripted viewer tests, started by the harness instead of
// xvfb-run per command: Debian 12's xvfb-run (under dash 0.5.12) can print "xvfb-run: error:
// problem while cleaning up temporary directory" and exit 5 after a command that failed, which
// breaks every test that checks penumbra's one error line.
#pragma once

#include <string>
#include <sys/types.h>

namespace penumbra::view {

class XServer {
public:
    // The process's server, started on first use; stopped when the process exits.
    static const XServer& instance();

    // ":N" once the server accepts connections; empty when it failed (then error() says why).
    const std::string& display() const { return display_; }
    const std::string& error() const { return error_; }

    XServer(const XServer&) = delete;
    XServer& operator=(const XServer&) = delete;
    ~XServer();

private:
    explicit XServer(const std::string& log);

    pid_t pid_ = -1;
    std::string display_, error_, log_;
};

}  // namespace penumbra::view
