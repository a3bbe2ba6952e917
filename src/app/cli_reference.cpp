#include "app/cli_reference.h"

#include <algorithm>
#include <map>
#include <vector>

#include <fmt/format.h>

#include "app/cli_app.h"
#include "app/option_cli.h"

namespace penumbra {
namespace {

OptionTable makeHelpCommandTable() {
    OptionTableBuilder<HelpOptions> t("help", "Help");
    t.boolean("--markdown", "markdown", [](HelpOptions& h) -> auto& { return h.markdown; }, SettingsChange::None,
              "Print the full reference of every command and option in Markdown (docs/cli.md)")
        .bareFlag = true;
    return t.build();
}

// A table cell: pipes would end the cell, line breaks the row.
std::string cell(std::string text) {
    std::string out;
    for (char c : text) {
        if (c == '|') out += "\\|";
        else if (c == '\n') out += ' ';
        else out += c;
    }
    return out;
}

std::string code(const std::string& text) { return text.empty() ? "" : "`" + cell(text) + "`"; }

// "-o, --output" from CLI11's names.
std::string flagNames(const CLI::Option& opt) {
    std::vector<std::string> names;
    for (const std::string& s : opt.get_snames()) names.push_back("-" + s);
    for (const std::string& l : opt.get_lnames()) names.push_back("--" + l);
    return fmt::format("{}", fmt::join(names, ", "));
}

std::string changeText(const OptionRow& row) {
    if (row.classify) return "by value";  // a compound row: each part costs what its own member costs
    if (row.change == SettingsChange::None) return "command";
    std::string text = settingsChangeName(row.change);
    if (!row.rebuilds.empty() && row.change != SettingsChange::PerFrame)
        text += fmt::format(" ({})", fmt::join(row.rebuilds, ", "));
    return text;
}

std::string valuesText(const CLI::Option& opt, const OptionRow* row) {
    if (!row) return opt.get_type_name();
    if (row->bareFlag) return "flag";
    return row->rangeText() + (row->repeatable ? " (repeatable)" : "");
}

std::string defaultText(const CLI::Option& opt, const OptionRow* row) {
    if (row && row->bareFlag) return "off";
    return opt.get_default_str();
}

bool isGlobal(const CLI::Option& opt) {
    const OptionRow* row = optionRowOf(&opt);
    if (!row) return false;
    const auto& rows = globalOptions().rows;
    return std::any_of(rows.begin(), rows.end(), [row](const OptionRow& r) { return &r == row; });
}

// The options of `cmd` that the reference lists (not the help flags; the global ones only on top).
std::vector<const CLI::Option*> listedOptions(const CLI::App& cmd, bool top) {
    std::vector<const CLI::Option*> out;
    for (const CLI::Option* opt : cmd.get_options()) {
        if (opt == cmd.get_help_ptr() || opt == cmd.get_help_all_ptr()) continue;
        if (opt->get_positional() || top != isGlobal(*opt)) continue;
        out.push_back(opt);
    }
    return out;
}

std::string groupTitle(const std::string& group) { return group.empty() ? "Hidden (for tests and scripts)" : group; }

// One option group's table.
std::string groupTable(const std::string& group, const std::vector<const CLI::Option*>& options) {
    std::string out = "| option | values | default | change | description |\n| --- | --- | --- | --- | --- |\n";
    for (const CLI::Option* opt : options) {
        if (opt->get_group() != group) continue;
        const OptionRow* row = optionRowOf(opt);
        // The row's own help: the values column already gives the range that --help appends.
        std::string description = row ? expandOptionReferences(row->help) : opt->get_description();
        if (!opt->get_envname().empty()) description += fmt::format(" (also {}=1)", opt->get_envname());
        out += fmt::format("| {} | {} | {} | {} | {} |\n", code(flagNames(*opt)), code(valuesText(*opt, row)),
                           code(defaultText(*opt, row)), row ? changeText(*row) : "command", cell(description));
    }
    return out;
}

// The tables a command's reference has already printed, to the command that printed them: the frame
// options of render, bench, stability and view are written out once.
using PrintedTables = std::map<std::string, std::string>;

// One table per option group, in the order the groups first appear (the order of `--help`); a group
// whose table an earlier command printed refers to it.
std::string optionTables(const std::vector<const CLI::Option*>& options, const std::string& command,
                         PrintedTables& printed) {
    std::vector<std::string> groups;
    for (const CLI::Option* opt : options)
        if (std::find(groups.begin(), groups.end(), opt->get_group()) == groups.end()) groups.push_back(opt->get_group());
    std::string out;
    for (const std::string& group : groups) {
        const std::string table = groupTable(group, options);
        const auto [first, added] = printed.emplace(groupTitle(group) + "\n" + table, command);
        if (added) out += fmt::format("\n**{}**\n\n{}", groupTitle(group), table);
        else
            out += fmt::format("\n**{}**: the same options as [`penumbra {}`](#penumbra-{}).\n", groupTitle(group),
                               first->second, first->second);
    }
    return out;
}

std::string commandSection(const CLI::App& cmd, PrintedTables& printed) {
    std::string usage = "penumbra " + cmd.get_name() + " [OPTIONS]";
    std::string arguments;
    for (const CLI::Option* opt : cmd.get_options()) {
        if (!opt->get_positional()) continue;
        const std::string name = opt->get_name();
        usage += opt->get_required() ? " " + name : " [" + name + "]";
        arguments += fmt::format("| `{}` | {} | {} |\n", name, code(opt->get_type_name()), cell(opt->get_description()));
    }
    std::string out = fmt::format("\n## penumbra {}\n\n{}\n\n```\n{}\n```\n", cmd.get_name(),
                                  cmd.get_description(), usage);
    if (!arguments.empty()) out += "\n| argument | values | description |\n| --- | --- | --- |\n" + arguments;
    const std::vector<const CLI::Option*> options = listedOptions(cmd, false);
    if (!options.empty()) out += optionTables(options, cmd.get_name(), printed);
    return out;
}

}  // namespace

const OptionTable& helpCommandOptions() {
    static const OptionTable table = makeHelpCommandTable();
    return table;
}

CLI::App* addHelpCommand(CLI::App& app, HelpOptions& options) {
    const std::string& markdown = helpCommandOptions().flagOf<HelpOptions>([](HelpOptions& h) -> auto& { return h.markdown; });
    CLI::App* cmd = app.add_subcommand("help", fmt::format("Print this help, or with {} the full CLI reference", markdown));
    addOptionRows(*cmd, helpCommandOptions(), &options);
    return cmd;
}

std::string cliReferenceMarkdown(const CLI::App& app) {
    const std::string command =
        "penumbra help " + helpCommandOptions().flagOf<HelpOptions>([](HelpOptions& h) -> auto& { return h.markdown; });
    std::string out = fmt::format(
        "# penumbra command line\n\n"
        "<!-- Generated by `{0}` from the option tables; a test compares this file with\n"
        "     its output. After changing an option, regenerate it: {0} > docs/cli.md -->\n\n"
        "{1}\n\n"
        "Commands: {2}.\n\n"
        "The **change** column says what changing an option costs in the viewer (`penumbra view`) or between\n"
        "frames of an embedding application: `per-frame` (read by the next frame; no allocation, no pipeline),\n"
        "`structure` (which passes run: the named parts are rebuilt), `sizes` (resources are reallocated),\n"
        "`by value` (a compound option: each part costs what its own setting costs), `command` (read once by\n"
        "the command).\n",
        command, app.get_description(), [&] {
            std::vector<std::string> names;
            for (const CLI::App* sub : app.get_subcommands({})) names.push_back(fmt::format("`{}`", sub->get_name()));
            return fmt::format("{}", fmt::join(names, ", "));
        }());
    out += "\n## Options of every command\n\nThey may stand before or after the command.\n";
    PrintedTables printed;
    out += optionTables(listedOptions(app, true), "", printed);
    for (const CLI::App* sub : app.get_subcommands({})) out += commandSection(*sub, printed);
    return out;
}

std::string helpText(const HelpOptions& options, const CLI::App& app) {
    return options.markdown ? cliReferenceMarkdown(app) : app.help();
}

}  // namespace penumbra
