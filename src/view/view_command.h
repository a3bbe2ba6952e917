// The `view` subcommand: every option of `render` (the same definitions), plus its own table (a
// script to run, the presentation mode).
#pragma once
#include <CLI/CLI.hpp>

#include "app/frame_options.h"
#include "view/viewer.h"

namespace penumbra::view {

struct ViewCommand {
    ViewOptions options;
    FrameOptions frame;        // parsed for validation and help; the session re-parses what was given
    RenderSettings settings;
    CLI::App* cmd = nullptr;
};

// The options of `view` itself (the script, the presentation mode).
const OptionTable& viewCommandOptions();
CLI::App* addViewCommand(CLI::App& app, ViewCommand& view);
int runViewCommand(ViewCommand& view, const vk::ContextOptions& vulkan);

}  // namespace penumbra::view
