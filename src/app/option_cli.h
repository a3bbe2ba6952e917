// The command line generated from option tables (core/options.h): each row
// becomes one CLI11 option whose parser is the row's, with its range and default in the help.
#pragma once
#include <functional>

#include <CLI/CLI.hpp>

#include "core/options.h"
#include "renderer/render_options.h"

namespace penumbra {

// Registers every row of `table` on `cmd`, writing into `settings` (a struct of the table's type);
// with `only`, the rows it accepts.
void addOptionRows(CLI::App& cmd, const OptionTable& table, void* settings,
                   const std::function<bool(const OptionRow&)>& only = {});
// Every frame-pipeline table (render_options.h), into `settings`.
void addRenderOptionRows(CLI::App& cmd, RenderSettings& settings);
// The row an option of a live App was made from by addOptionRows; nullptr for an option written by
// hand (a positional, the help flag). The CLI reference reads ranges and change classes from it.
const OptionRow* optionRowOf(const CLI::Option* option);

// A help text with each `{module.key}` replaced by the flag of that row (a help that refers to
// another option names it through its row). Throws std::logic_error for a reference to no row.
std::string expandOptionReferences(const std::string& help);
// A message from below the app (an error, a renderer or scene warning) with its option references
// written as flags; references to no row are left as they are (a message is never lost to them).
std::string withFlags(const std::string& message);
// "penumbra: warning: MESSAGE" on stderr, with the flags written in.
void printWarning(const std::string& message);

// The flag of the row bound to `access` in `table`, for a command's row of an option that another
// table spells (`reference --width` is `render --width`).
template <class S, class Access>
const char* sharedFlag(const OptionTable& table, Access access) {
    return table.flagOf<S>(access).c_str();  // tables are static: the text outlives every row
}

}  // namespace penumbra
