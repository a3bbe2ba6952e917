// A frame's options given as text, (flag, values) pairs, applied by their option rows without a
// command line parser: the viewer keeps its options this way so that a `set` line, a panel and
// `penumbra render` share one parser and one set of rules.
#pragma once
#include <string>
#include <vector>

#include "frame/frame_options.h"

namespace penumbra {

// One option as given: "--shadow" and its values ("on"/"off" or "true" for a bare flag), or "scene"
// and the scene.
struct FrameArg {
    std::string name;
    std::vector<std::string> values;
};

// The options a frame is made of, typed: what parseFrameArgs returns.
struct ParsedFrame {
    FrameOptions options;
    RenderSettings settings;
};

// One option of a frame in the order the command line registers them (the scene, the inputs' rows,
// every pipeline table's, the motion rows): its row (null for the scene) and the struct it writes.
struct FrameOptionRef {
    std::string name;  // "--shadow", or "scene"
    const OptionRow* row = nullptr;
    const void* settings = nullptr;  // within the ParsedFrame the list was made for
};
std::vector<FrameOptionRef> frameOptionRefs(const ParsedFrame& frame);

// The frame's defaults with `args` applied, each by its row, in the order of frameOptionRefs (as a
// command line parser runs them, whatever order they are given in), then checkFrameSettings. A
// repeatable row takes every value, a bare flag counts its values as CLI11 does (on when the sum of
// on = 1 and off = -1 is positive), any other takes exactly one. Throws std::invalid_argument with one
// line (naming the flag) for an unknown option or a bad value.
ParsedFrame parseFrameArgs(const std::vector<FrameArg>& args);

}  // namespace penumbra
