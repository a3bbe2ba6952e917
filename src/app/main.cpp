// penumbra command line: `render` (headless, PNG/EXR), `view` (interactive), `bench` (per-pass GPU timings),
// `info`, and the ground truth: `reference` (CPU path tracer), `compare` (image metrics), `eval` (techniques
// vs reference). The viewer is registered here, on top: the library's Cli knows no window system.
// The commands and options live in app/cli_app.h; every bad input ends in one `penumbra: error:` line.
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/cli_app.h"
#include "app/option_cli.h"
#include "app/view_cli.h"

int main(int argc, char** argv) {
    std::string commandLine;
    std::vector<std::string> args;
    for (int i = 0; i < argc; ++i) {
        commandLine += (i ? " " : "") + std::string(argv[i]);
        if (i > 0) args.push_back(argv[i]);
    }
    penumbra::Cli cli(commandLine);
    penumbra::ViewCommand viewCommand;
    CLI::App* viewer = penumbra::addViewCommand(cli.app, viewCommand);
    if (const std::string unknown = cli.unknownCommand(args); !unknown.empty()) {
        fmt::print(stderr, "penumbra: error: {} (see {})\n", unknown, cli.app.get_help_ptr()->get_name());
        return 2;
    }
    try {
        cli.app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return cli.app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return cli.app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::string msg = e.what();
        if (msg.empty()) msg = e.get_name();
        fmt::print(stderr, "penumbra: error: {} (see {})\n", msg, cli.app.get_help_ptr()->get_name());
        return 2;
    }
    cli.vk.syncValidation = cli.vk.validate;  // validation checks synchronization too
    try {
        if (*viewer) return penumbra::runViewCommand(viewCommand, cli.vk);
        return cli.run();
    } catch (const std::exception& e) {
        fmt::print(stderr, "penumbra: error: {}\n", penumbra::withFlags(e.what()));
        return 1;
    }
}
