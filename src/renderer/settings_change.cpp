#include "renderer/settings_change.h"

#include <stdexcept>

#include "renderer/render_options.h"
#include "renderer/technique_registry.h"

namespace penumbra {

uint32_t framePartsOf(const std::vector<std::string>& names) {
    uint32_t parts = kPartNone;
    for (const std::string& n : names) {
        if (n == "shadow") parts |= kPartShadow;
        else if (n == "camera" || n == "frame") parts |= kPartCamera;
        else if (n == "gi" || n == "rsm" || n == "lpv") parts |= kPartGi;
        else if (n == "dsm") parts |= kPartDsm;
        else if (n == "shadow.filters") parts |= kPartShadowFilters;
        else if (const TechniqueEntry* e = TechniqueRegistry::instance().find(n)) parts |= e->parts;
        else if (n != "none") throw std::logic_error("no frame part is named '" + n + "'");
    }
    return parts;
}

namespace {

// The class and parts of one row's change between two settings (None when they agree in it).
std::pair<SettingsChange, uint32_t> classify(const BoundOptionTable& t, const OptionRow& row, const RenderSettings& a,
                                             const RenderSettings& b) {
    if (row.classify) {
        const auto [change, parts] = row.classify(t.at(a), t.at(b));
        return {change, change == SettingsChange::PerFrame ? kPartNone : framePartsOf(parts)};
    }
    if (!row.differs(t.at(a), t.at(b))) return {SettingsChange::None, kPartNone};
    if (row.change == SettingsChange::PerFrame) return {row.change, kPartNone};
    return {row.change, framePartsOf(row.rebuilds.empty() ? std::vector<std::string>{t.table->module} : row.rebuilds)};
}

}  // namespace

std::vector<SettingsOption> settingsOptionTable() {
    std::vector<SettingsOption> out;
    for (const BoundOptionTable& t : renderOptionTables())
        for (const OptionRow& row : t.table->rows) {
            const uint32_t parts = row.change == SettingsChange::PerFrame ? kPartNone
                                   : framePartsOf(row.rebuilds.empty() ? std::vector<std::string>{t.table->module}
                                                                       : row.rebuilds);
            out.push_back({row.flag, row.change, parts, [&t, &row](const RenderSettings& a, const RenderSettings& b) {
                               return classify(t, row, a, b).first != SettingsChange::None;
                           }});
        }
    return out;
}

SettingsDiff diffSettings(const RenderSettings& before, const RenderSettings& after) {
    SettingsDiff d;
    for (const BoundOptionTable& t : renderOptionTables())
        for (const OptionRow& row : t.table->rows) {
            const auto [change, parts] = classify(t, row, before, after);
            if (change == SettingsChange::None) continue;
            d.flags.push_back(row.flag);
            d.change = std::max(d.change, change);
            d.parts |= parts;
        }
    return d;
}

}  // namespace penumbra
