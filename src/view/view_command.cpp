#include "view/view_command.h"

#include <fmt/format.h>

namespace penumbra::view {

CLI::App* addViewCommand(CLI::App& app, ViewCommand& view) {
    view.cmd = app.add_subcommand("view", "Interactive viewer: a window with every render option live (README, Viewer)");
    addFrameOptions(*view.cmd, view.frame, view.settings);
    view.cmd->add_option("--script", view.options.script,
                         "Run the commands of FILE (set, camera, light, time, play, pause, frames, screenshot, "
                         "screenshot-ui, quit); the end of the file quits")
        ->check(CLI::ExistingFile);
    view.cmd->add_option("--present", view.options.present, "Presentation: fifo (default, vsync), mailbox, immediate")
        ->check(CLI::IsMember({"fifo", "mailbox", "immediate"}));
    return view.cmd;
}

int runViewCommand(ViewCommand& view, const vk::ContextOptions& vulkan) {
    checkFrameSettings(view.frame, view.settings);  // cross-option rules before a window opens
    view.options.vulkan = vulkan;
    view.options.vulkan.syncValidation = vulkan.validate;  // the viewer's --validate checks synchronization too
    Viewer viewer(view.options, givenFrameArgs(*view.cmd), {view.settings.width, view.settings.height});
    viewer.run();
    return 0;
}

}  // namespace penumbra::view
