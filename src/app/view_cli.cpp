#include "app/view_cli.h"

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>

#include "app/option_cli.h"

namespace penumbra {
namespace {

std::string nameOf(const CLI::Option& opt) {
    return opt.get_lnames().empty() ? opt.get_name(true) : "--" + opt.get_lnames().front();  // the positional: "scene"
}

// The frame options given on `cmd` (a parsed command that registered them), as the viewer keeps them.
std::vector<FrameArg> givenFrameArgs(const CLI::App& cmd) {
    CLI::App probe;
    FrameOptions o;
    RenderSettings rs;
    addFrameOptions(probe, o, rs);
    const std::vector<CLI::Option*> frameOptions = probe.get_options();  // one vector: begin and end of the same
    std::vector<FrameArg> out;
    for (const CLI::Option* opt : cmd.get_options()) {
        if (opt->count() == 0) continue;
        const std::string name = nameOf(*opt);
        const bool isFrameOption = std::any_of(frameOptions.begin(), frameOptions.end(),
                                               [&](const CLI::Option* p) { return nameOf(*p) == name; });
        if (isFrameOption) out.push_back({name, opt->results()});
    }
    return out;
}

OptionTable makeViewCommandTable() {
    using V = view::ViewOptions;
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
    view::Viewer viewer(view.options, givenFrameArgs(*view.cmd), {std::move(view.frame), view.settings});
    viewer.run();
    return 0;
}

}  // namespace penumbra
