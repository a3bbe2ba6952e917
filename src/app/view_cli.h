// The `view` subcommand on the command line: every option of `render` (the same rows), plus its own
// table (a script to run, the presentation mode). Built into the executable beside main: the
// commands' library (penumbra_app) links no window system.
#pragma once
#include <CLI/CLI.hpp>

#include "app/frame_cli.h"
#include "view/viewer.h"

namespace penumbra {

struct ViewCommand {
    view::ViewOptions options;
    FrameOptions frame;  // the frame options as CLI11 parsed them, handed to the viewer with what was given
    RenderSettings settings;
    CLI::App* cmd = nullptr;
};

// The options of `view` itself (the script, the presentation mode).
const OptionTable& viewCommandOptions();
CLI::App* addViewCommand(CLI::App& app, ViewCommand& view);
int runViewCommand(ViewCommand& view, const vk::ContextOptions& vulkan);

}  // namespace penumbra
