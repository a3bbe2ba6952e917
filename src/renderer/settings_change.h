// What each render option invalidates when it changes at run time (the viewer, `set` in scripts,
// Renderer::apply), read from the option tables (renderer/render_options.h): each row's change class
// and the parts of the frame pipeline it rebuilds.
#pragma once
#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "core/options.h"
#include "renderer/render_settings.h"

namespace penumbra {

// Parts of the frame pipeline a Renderer rebuilds (bit mask).
enum FrameParts : uint32_t {
    kPartNone = 0,
    kPartShadow = 1,  // shadow maps, moments, filter (and what is drawn into them: hair)
    kPartCamera = 2,  // G-buffer, lighting, tone mapping (image size)
    kPartGi = 4,      // RSM, its gather, LPV
    kPartDsm = 8,     // deep shadow maps
    kPartShadowFilters = 16,  // the lights' shadow filters: re-assigned in place (moments sized, passes listed)
};

// The parts named by an option row's `rebuilds` ("shadow", "camera", "gi", "rsm", "lpv", "dsm",
// "shadow.filters", "none"); throws std::logic_error for a name no part has.
uint32_t framePartsOf(const std::vector<std::string>& names);

// One row of every table, flattened: its flag, class and parts, and whether two settings differ in it.
struct SettingsOption {
    std::string flag;  // CLI flag, e.g. "--shadow-res"
    SettingsChange change;
    uint32_t parts;    // FrameParts rebuilt (Structure and Sizes only)
    std::function<bool(const RenderSettings&, const RenderSettings&)> differs;
};

// Rebuilt from the tables on each call (a registered table joins it).
std::vector<SettingsOption> settingsOptionTable();

struct SettingsDiff {
    SettingsChange change = SettingsChange::None;
    uint32_t parts = kPartNone;
    std::vector<std::string> flags;  // the options that differ
};
SettingsDiff diffSettings(const RenderSettings& before, const RenderSettings& after);

}  // namespace penumbra
