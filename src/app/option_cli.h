// The command line generated from option tables (core/options.h): each row
// becomes one CLI11 option whose parser is the row's, with its range and default in the help.
#pragma once
#include <CLI/CLI.hpp>

#include "core/options.h"
#include "renderer/render_options.h"

namespace penumbra {

// Registers every row of `table` on `cmd`, writing into `settings` (a struct of the table's type).
void addOptionRows(CLI::App& cmd, const OptionTable& table, void* settings);
// Every frame-pipeline table (render_options.h), into `settings`.
void addRenderOptionRows(CLI::App& cmd, RenderSettings& settings);

}  // namespace penumbra
