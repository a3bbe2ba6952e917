// The option tables of a frame pipeline, bound to where their settings live in RenderSettings: the
// frame's own table (size, output, GI mode, temporal GI, translucency, `--shadow`) and each module's.
// The CLI, `--help`, the JSON `settings` of bench/eval/stability, the viewer's panels and
// Renderer::apply's classification are generated from this list.
#pragma once
#include <deque>
#include <functional>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/options.h"
#include "renderer/render_settings.h"

namespace penumbra {

struct BoundOptionTable {
    const OptionTable* table;
    std::function<const void*(const RenderSettings&)> of;  // the struct the table's rows are written for
    void* at(RenderSettings& s) const { return const_cast<void*>(of(s)); }
    const void* at(const RenderSettings& s) const { return of(s); }
};

// Every table: the frame's first, then the modules' in the order of the frame (shadow, dsm, rsm,
// lpv), then those of techniques registered with an option table (renderer/technique_registry.h).
const std::deque<BoundOptionTable>& renderOptionTables();

// The row of `flag` in any table, with its table; null when no table has it.
struct FoundOption {
    const OptionRow* row = nullptr;
    const BoundOptionTable* table = nullptr;
};
FoundOption findRenderOption(const std::string& flag);

// The table's values: {"key": value, ...} (numbers as numbers, on/off as booleans, lists as arrays).
nlohmann::json optionsJson(const OptionTable& table, const void* settings);
// Every frame-pipeline table: the frame's keys at the top, each module's under its name (the JSON
// `settings` of bench, eval and stability).
nlohmann::json renderSettingsJson(const RenderSettings& settings);

// The frame's own table (RenderSettings' members that belong to no module).
const OptionTable& frameOptionTable();

// The flag of a RenderSettings member of the frame's table, e.g. frameFlag([](auto& s) -> auto& { return s.gi; }).
template <class Access>
const std::string& frameFlag(Access access) {
    return frameOptionTable().flagOf<RenderSettings>(access);
}

// Ranges of every module and the rules between modules (one place). Throws std::invalid_argument.
void validateSettings(const RenderSettings& settings);

}  // namespace penumbra
