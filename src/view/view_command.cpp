#include "view/view_command.h"

#include <filesystem>

#include <fmt/format.h>

#include "app/option_cli.h"

namespace penumbra::view {
namespace {

OptionTable makeViewCommandTable() {
    using V = ViewOptions;
    using change::kCommand;
    OptionTableBuilder<V> t("view", "View");
    t.text("--script", "script", [](V& v) -> auto& { return v.script; },
           [](const V& v) { return v.script.empty() ? std::vector<std::string>{} : std::vector<std::string>{v.script}; },
           [](V& v, const std::string& file) {
               if (!std::filesystem::is_regular_file(file)) throw std::invalid_argument("no such file");
               v.script = file;
           },
           kCommand,
           "Run the commands of FILE (set, camera, light, time, play, pause, frames, screenshot, screenshot-ui, "
           "quit); the end of the file quits")
        .placeholder = "FILE";
    t.choice("--present", "present", [](V& v) -> auto& { return v.present; },
             std::vector<std::pair<std::string, std::string>>{{"fifo", "fifo"}, {"mailbox", "mailbox"},
                                                              {"immediate", "immediate"}},
             kCommand, "Presentation: fifo (vsync), mailbox, immediate");
    return t.build();
}

}  // namespace

const OptionTable& viewCommandOptions() {
    static const OptionTable table = makeViewCommandTable();
    return table;
}

CLI::App* addViewCommand(CLI::App& app, ViewCommand& view) {
    view.cmd = app.add_subcommand("view", "Interactive viewer: a window with every render option live (docs/viewer.md)");
    addFrameOptions(*view.cmd, view.frame, view.settings);
    addOptionRows(*view.cmd, viewCommandOptions(), &view.options);
    return view.cmd;
}

int runViewCommand(ViewCommand& view, const vk::ContextOptions& vulkan) {
    checkFrameSettings(view.frame, view.settings);  // cross-option rules before a window opens
    view.options.vulkan = vulkan;
    view.options.vulkan.syncValidation = vulkan.validate;  // the viewer's validation checks synchronization too
    Viewer viewer(view.options, givenFrameArgs(*view.cmd), {view.settings.width, view.settings.height});
    viewer.run();
    return 0;
}

}  // namespace penumbra::view
