// Checks attached to the CLI's options when they are registered, so that the command line holds every
// option to its row's rules (the viewer applies the same rows through src/frame/frame_args), and the
// consistency checks over the settings structs.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "io/plural.h"

namespace penumbra {

// A number in [min, max] that is finite: CLI11's Range lets NaN through (every comparison with NaN
// is false) and takes "inf" as a float, which renders black images or vanished shadows.
CLI::Validator finiteRange(double min, double max);

// Adds a finite-number check to every numeric option of `app` and its subcommands (CLI11 type names
// FLOAT, INT, UINT), so that an option registered without a range still refuses NaN, infinity and an
// empty value (which CLI11 takes as "keep the default"). Call it after every option has been added.
void requireFiniteNumbers(CLI::App& app);

// Throws std::invalid_argument naming `option` unless `path` can be created or overwritten as a file
// (`directory` false) or used as a directory (true: an existing writable directory, or one that can
// be created under the nearest existing ancestor). Nothing is created.
void checkWritable(const std::string& path, const std::string& option, bool directory = false);

}  // namespace penumbra
