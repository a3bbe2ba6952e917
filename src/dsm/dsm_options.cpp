#include "dsm/dsm_options.h"

#include <stdexcept>
#include <string>

#include "shared/types.h"

namespace penumbra {
namespace {

constexpr SettingsChange kStructure = SettingsChange::Structure;
constexpr SettingsChange kSizes = SettingsChange::Sizes;

// "0,2": light indices (the flag may also be repeated).
void addLights(DsmSettings& s, const std::string& text) {
    size_t start = 0;
    while (start <= text.size()) {
        const size_t comma = std::min(text.find(',', start), text.size());
        const std::string item = text.substr(start, comma - start);
        if (item.empty() || item.size() > 9 || item.find_first_not_of("0123456789") != std::string::npos)
            throw std::invalid_argument("expected light indices, e.g. 0,2");
        s.lights.push_back(uint32_t(std::stoul(item)));
        start = comma + 1;
    }
}

OptionTable makeTable() {
    using S = DsmSettings;
    OptionTableBuilder<S> t("dsm", "Deep shadow maps and hair");
    OptionRow& lights = t.text(
        "--dsm-lights", "lights", [](S& s) -> auto& { return s.lights; },
        [](const S& s) {
            std::vector<std::string> out;
            for (uint32_t l : s.lights) out.push_back(std::to_string(l));
            return out;
        },
        addLights, kStructure, "Lights that get a deep shadow map, e.g. 0,2 (default: all shadowed)");
    lights.repeatable = true;
    lights.placeholder = "N[,N...]";
    lights.clear = [](void* s) { static_cast<S*>(s)->lights.clear(); };
    lights.rebuild({"shadow", "dsm"});
    t.integer("--dsm-res", "resolution", [](S& s) -> auto& { return s.resolution; }, 16, 16384, kSizes,
              "Deep shadow map resolution")
        .orSpecial(0, "the shadow map's resolution");
    t.integer("--dsm-nodes", "pool_nodes", [](S& s) -> auto& { return s.poolNodes; }, 1,
              double(DsmSettings::kMaxPoolNodes - 1), kSizes, "Node pool capacity")
        .orSpecial(0, "16 nodes per DSM texel, at most what the device addresses");
    // The DSM's lookup table is written once when its buffers are made: these rebuild it.
    t.integer("--dsm-max-list", "max_list", [](S& s) -> auto& { return s.maxList; }, 1, DSM_MAX_LIST_CAP, kStructure,
              "Nodes kept per texel, nearest first");
    t.real("--dsm-filter", "filter", [](S& s) -> auto& { return s.filterWidth; }, 0.0, 8.0, kStructure,
           "DSM PCF box width in texels (0 = bilinear)");
    t.real("--dsm-bias", "depth_bias", [](S& s) -> auto& { return s.depthBias; }, 0.0, 64.0, kStructure,
           "DSM receiver depth bias in texels");
    t.real("--dsm-normal-offset", "normal_offset", [](S& s) -> auto& { return s.normalOffset; }, 0.0, 64.0,
           kStructure, "DSM receiver offset along its normal in texels");
    t.boolean("--dsm-depth-test", "depth_test", [](S& s) -> auto& { return s.depthTest; }, kStructure,
              "Skip DSM fragments hidden behind opaque casters");
    t.choice("--dsm-lookup", "lookup", [](S& s) -> auto& { return s.lookup; },
             std::vector<std::pair<std::string, DsmLookup>>{{"search", DsmLookup::Search}, {"links", DsmLookup::Links}},
             kStructure,
             "How a DSM lookup finds its place in each filter tap's list: binary search in the packed list, or a "
             "walk through the neighbour links from the previous tap");
    return t.build();
}

}  // namespace

const OptionTable& dsmOptions() {
    static const OptionTable table = makeTable();
    return table;
}

}  // namespace penumbra
