// `penumbra bench`: frames after warm-up, GPU time per pass (median, p5, p95), bandwidth of the
// memory-bound passes against the device's measured copy bandwidth, JSON for bench/results.
#pragma once
#include <CLI/CLI.hpp>

#include "app/frame_cli.h"
#include "vk/context.h"

namespace penumbra {

struct BenchOptions {
    FrameOptions frame;
    int frames = 100;
    int warmup = 10;
    int framesInFlight = 2;  // 1: the old loop, each frame waited for before the next is recorded
    std::string json;     // output file, "" = none
    std::string command;  // the command line, recorded in the JSON
};

// The options of `bench` itself (frames, warm-up, JSON).
const OptionTable& benchCommandOptions();
CLI::App* addBenchCommand(CLI::App& app, BenchOptions& options, RenderSettings& settings);
int runBench(const BenchOptions& options, const vk::ContextOptions& vkOptions, RenderSettings settings,
             bool dryRun = false);

}  // namespace penumbra
