// The whole command line as one object: every subcommand and option registered on one CLI11 App
// (main.cpp parses and runs it; the option fuzzer in tests/option_fuzz_test.cpp walks its options).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/bench.h"
#include "app/cli_reference.h"
#include "app/frame_cli.h"
#include "app/ground_truth_cli.h"
#include "app/stability.h"
#include "vk/context.h"

namespace penumbra {

struct RenderCliOptions {
    FrameOptions frame;
    std::string output = "penumbra.png";
    bool printPasses = false;
    int frames = 1;
    bool quiet = false;
    int sequence = 0;   // --sequence N: N frames from --time at --fps (0: one image)
    double fps = 30.0;
};

// The options of `render` itself (output, frames, sequence).
const OptionTable& renderCommandOptions();

// The options of every command: the Vulkan device and validation, and the hidden `--dry-run`
// (also PENUMBRA_DRY_RUN=1): check every option and output path and load the scene, then stop
// before any GPU or path-tracing work (exit 0). Tests and scripts use it.
struct GlobalOptions {
    vk::ContextOptions vk;
    bool dryRun = false;
};
const OptionTable& globalOptions();
// Registers the global options on `cmd`, writing into `options`.
void addGlobalOptions(CLI::App& cmd, GlobalOptions& options);

struct Cli {
    CLI::App app{"penumbra: real-time shadows and diffuse global illumination (Vulkan 1.3)"};
    GlobalOptions global;
    vk::ContextOptions& vk = global.vk;
    bool& dryRun = global.dryRun;
    RenderCliOptions render;
    RenderSettings renderSettings;
    BenchOptions bench;
    RenderSettings benchSettings;
    ReferenceCliOptions reference;
    CompareCliOptions compare;
    EvalCliOptions eval;
    StabilityOptions stability;
    RenderSettings stabilitySettings;
    HelpOptions help;
    CLI::App *renderCmd = nullptr, *benchCmd = nullptr, *infoCmd = nullptr, *referenceCmd = nullptr,
             *compareCmd = nullptr, *evalCmd = nullptr, *stabilityCmd = nullptr,
             *helpCmd = nullptr;

    // Registers every subcommand and option; `commandLine` is recorded in bench and eval JSON.
    explicit Cli(const std::string& commandLine = "");
    Cli(const Cli&) = delete;
    Cli& operator=(const Cli&) = delete;

    // "unknown command 'x' (one of: render, ...)" when the first word that is neither an option nor the
    // value of a global option is not a subcommand; "" when the line names one (or asks for help).
    std::string unknownCommand(const std::vector<std::string>& args) const;
    // Runs the parsed subcommand; throws std::exception with one line for bad input.
    int run();
};

}  // namespace penumbra
