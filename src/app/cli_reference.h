// `penumbra help`: the command line's help, and with --markdown the full CLI reference (docs/cli.md),
// generated from the live App and the option rows behind its options, so that it cannot drift from
// what the commands accept. The text depends on nothing of the machine it runs on.
#pragma once
#include <string>

#include <CLI/CLI.hpp>

#include "core/options.h"

namespace penumbra {

struct HelpOptions {
    bool markdown = false;
};

const OptionTable& helpCommandOptions();
CLI::App* addHelpCommand(CLI::App& app, HelpOptions& options);

// Every subcommand of `app` with its description, arguments and options (values, default, change
// class, help), in Markdown; the options every command takes are listed once, at the top.
std::string cliReferenceMarkdown(const CLI::App& app);

// What `penumbra help` prints: the reference with --markdown, else the top-level help.
std::string helpText(const HelpOptions& options, const CLI::App& app);

}  // namespace penumbra
