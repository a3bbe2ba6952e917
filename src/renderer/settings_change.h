// What each render option invalidates when it changes at run time (the viewer, `set` in scripts,
// Renderer::apply). One table, in the order of the README's: the CLI flag, its class, the parts of
// the frame pipeline it rebuilds, and how to tell whether two settings differ in it.
#pragma once
#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "renderer/render_settings.h"

namespace penumbra {

// What a settings change invalidates.
enum class SettingsChange {
    None,
    PerFrame,   // values read by the next frame: no allocation, no pipeline creation
    Structure,  // which passes run (shadow filter kind, GI mode, DSM on/off, pass counts)
    Sizes,      // what sizes a resource (resolutions, cascade count, image size)
};
const char* settingsChangeName(SettingsChange c);

// Parts of the frame pipeline a Renderer rebuilds (bit mask).
enum FrameParts : uint32_t {
    kPartNone = 0,
    kPartShadow = 1,  // shadow maps, moments, filter (and what is drawn into them: hair)
    kPartCamera = 2,  // G-buffer, lighting, tone mapping (image size)
    kPartGi = 4,      // RSM, its gather, LPV
    kPartDsm = 8,     // deep shadow maps
    kPartShadowFilters = 16,  // the lights' shadow filters: re-assigned in place (moments sized, passes listed)
};

struct SettingsOption {
    const char* flag;  // CLI flag, e.g. "--shadow-res"
    SettingsChange change;
    uint32_t parts;    // FrameParts rebuilt (Structure and Sizes only)
    std::function<bool(const RenderSettings&, const RenderSettings&)> differs;
};

const std::vector<SettingsOption>& settingsOptionTable();

struct SettingsDiff {
    SettingsChange change = SettingsChange::None;
    uint32_t parts = kPartNone;
    std::vector<std::string> flags;  // the options that differ
};
SettingsDiff diffSettings(const RenderSettings& before, const RenderSettings& after);

}  // namespace penumbra
