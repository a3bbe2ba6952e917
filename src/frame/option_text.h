// Option references in text. Help texts and messages written below the front ends name an option as
// `{module.key}` (its table's module and the row's JSON key), so that a flag is spelled only in its
// row; these functions write the flags in, from the tables a front end knows.
#pragma once
#include <string>
#include <vector>

#include "core/options.h"

namespace penumbra {

// The tables of one frame: the frame pipeline's (renderer/render_options.h), then the frame inputs'
// and motion's (frame/frame_options.h).
std::vector<const OptionTable*> frameOptionTables();

// The long form of a row's flag ("-o,--output" -> "--output").
std::string longFlag(const std::string& flag);
// `text` with each `{module.key}` replaced by the long flag of that row among `tables`. Throws
// std::logic_error for a reference to no row.
std::string expandOptionReferences(const std::string& text, const std::vector<const OptionTable*>& tables);
// The same for a message: references to no row are left as they are (a message is never lost to them).
std::string withFlags(const std::string& message, const std::vector<const OptionTable*>& tables);
// A row's help as the CLI and the viewer show it: references expanded, a number's range appended.
std::string optionHelp(const OptionRow& row, const std::vector<const OptionTable*>& tables);
// "penumbra: warning: MESSAGE" on stderr, with the frame's flags written in.
void printFrameWarning(const std::string& message);

}  // namespace penumbra
