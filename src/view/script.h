// `penumbra view --script FILE`: one command per line (docs/viewer.md), for tests and
// reproducible captures. Lines that only change state are applied to the session at once; the
// first that needs frames rendered is handed back to the viewer.
#pragma once
#include <fstream>
#include <stdexcept>
#include <string>

#include "view/session.h"

namespace penumbra::view {

// "FILE:LINE: what" (the CLI prints it after "penumbra: error: ").
struct ScriptError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// What the viewer does next for the script.
struct ScriptStep {
    enum Kind { Frames, Screenshot, ScreenshotUi, PanelsState, Quit } kind = Quit;
    int frames = 0;    // Frames: how many
    std::string path;  // Screenshot(Ui), PanelsState: where
};

class Script {
public:
    explicit Script(const std::string& path);  // throws ScriptError when it cannot be read

    // Applies lines to `session` until one needs frames (or a screenshot, or quits); the end of the
    // file quits. A bad line throws ScriptError and changes nothing.
    ScriptStep run(ViewSession& session);
    const std::string& path() const { return path_; }

private:
    ScriptStep execute(const std::string& command, const std::string& args, ViewSession& session);

    std::string path_;
    std::ifstream in_;
    int line_ = 0;
};

}  // namespace penumbra::view
