// The frame's options (frame/frame_options.h) on the command line: `render`, `bench`, `view` and the
// commands that take a scene register them here.
#pragma once
#include <CLI/CLI.hpp>

#include "frame/frame_options.h"

namespace penumbra {

void addFrameOptions(CLI::App& cmd, FrameOptions& o, RenderSettings& rs);
// The time and motion options alone (also on `reference` and `eval`).
void addMotionOptions(CLI::App& cmd, FrameOptions& o);

}  // namespace penumbra
