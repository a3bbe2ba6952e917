// `penumbra help --markdown` (app/cli_reference): the generated CLI reference lists every command and
// every option the live App accepts, each table row with the row's range, default and change class,
// and nothing that depends on the machine it was generated on.
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "app/cli_app.h"
#include "app/cli_reference.h"
#include "app/option_cli.h"

using namespace penumbra;

namespace {

// The text of the section "## penumbra NAME" up to the next command's section.
std::string commandSection(const std::string& doc, const std::string& name) {
    const std::string heading = "\n## penumbra " + name + "\n";
    const size_t begin = doc.find(heading);
    if (begin == std::string::npos) return "";
    const size_t end = doc.find("\n## penumbra ", begin + heading.size());
    return doc.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
}

}  // namespace

TEST(CliReference, ListsEveryCommandAndOptionWithItsRow) {
    const Cli cli;
    const std::string doc = cliReferenceMarkdown(cli.app);
    int rows = 0;
    for (const CLI::App* sub : cli.app.get_subcommands({})) {
        const std::string section = commandSection(doc, sub->get_name());
        ASSERT_FALSE(section.empty()) << sub->get_name() << " has no section";
        for (const CLI::Option* opt : sub->get_options()) {
            if (opt == sub->get_help_ptr() || opt->get_positional() || opt->get_lnames().empty()) continue;
            const OptionRow* row = optionRowOf(opt);
            ASSERT_NE(row, nullptr) << sub->get_name() << " --" << opt->get_lnames().front() << " has no option row";
            const bool global = &globalOptions().rows.front() <= row && row <= &globalOptions().rows.back();
            std::string where = global ? doc : section;
            const std::string flag = "--" + opt->get_lnames().front();
            // A group an earlier command printed is referred to: its table is in that command's section.
            const std::string same = "**" + opt->get_group() + "**: the same options as [`penumbra ";
            if (const size_t ref = where.find(same); ref != std::string::npos && where.find(flag + "` |") == std::string::npos) {
                const size_t name = ref + same.size();
                where = commandSection(doc, where.substr(name, where.find('`', name) - name));
            }
            std::string names;  // the option column: "-o, --output"
            for (const std::string& n : opt->get_snames()) names += "-" + n + ", ";
            const size_t at = where.find("| `" + names + flag + "` |");
            ASSERT_NE(at, std::string::npos) << sub->get_name() << " " << flag << " missing";
            const std::string line = where.substr(at, where.find('\n', at) - at);
            if (row->kind == OptionKind::Integer || row->kind == OptionKind::Real) {
                std::string range = row->rangeText();
                for (size_t p = range.find('|'); p != std::string::npos; p = range.find('|', p + 2)) range.insert(p, "\\");
                EXPECT_NE(line.find(range), std::string::npos) << flag << ": " << line;
            }
            if (row->change == SettingsChange::Sizes && !row->classify) {
                EXPECT_NE(line.find("| sizes"), std::string::npos) << flag << ": " << line;
            }
            ++rows;
        }
    }
    EXPECT_GT(rows, 150);  // every command's options, the frame pipeline's in each rendering command
}

TEST(CliReference, DependsOnNothingOfTheMachine) {
    const Cli cli;
    const std::string doc = cliReferenceMarkdown(cli.app);
    EXPECT_EQ(doc, cliReferenceMarkdown(Cli().app)) << "two Apps give two texts";
    EXPECT_FALSE(std::regex_search(doc, std::regex("(^|[ `(=])/(usr|home|work|tmp|root)/"))) << "an absolute path";
    for (const char* device : {"llvmpipe", "Mesa", "driver version"})
        EXPECT_EQ(doc.find(device), std::string::npos) << device;
    EXPECT_EQ(doc.find(PENUMBRA_SOURCE_DIR), std::string::npos);
}

TEST(CliReference, HelpWithoutMarkdownIsTheUsualHelp) {
    const Cli cli;
    EXPECT_EQ(helpText(HelpOptions{}, cli.app), cli.app.help());
    EXPECT_EQ(helpText(HelpOptions{true}, cli.app), cliReferenceMarkdown(cli.app));
}
