#include "sky_light/sky_light_options.h"

namespace penumbra {
namespace {

using namespace change;

OptionTable makeTable() {
    using S = SkyLightSettings;
    OptionTableBuilder<S> t("sky_light", "Sky light: the visible sky's irradiance per pixel");
    t.choice("--sky-visibility", "visibility", [](S& s) -> auto& { return s.visibility; },
             std::vector<std::pair<std::string, SkyVisibility>>{{"voxels", SkyVisibility::Voxels},
                                                                {"none", SkyVisibility::None}},
             kStructure,
             "What hides the sky from a surface: rays through the occupancy volume ({rsm.voxel_resolution}), or "
             "nothing (every surface sees its whole hemisphere)")
        .rebuild({"camera", "gi"});  // the occupancy volume comes and goes with it
    t.integer("--sky-rays", "rays", [](S& s) -> auto& { return s.rays; }, 1, 64, kFrame,
              "Sky visibility rays per pixel (a 4x4 block of pixels turns its sets apart; the filter joins them)");
    t.integer("--sky-filter-radius", "filter_radius", [](S& s) -> auto& { return s.filterRadius; }, 0, 8, kFrame,
              "Pixels either side over which the sky visibility is averaged on the receiver's surface (0: none)");
    t.real("--sky-ray-offset", "ray_offset", [](S& s) -> auto& { return s.startOffset; }, 0.5, 8.0, kFrame,
           "Voxels off the surface, along its normal, where the sky visibility rays start");
    return t.build();
}

}  // namespace

const OptionTable& skyLightOptions() {
    static const OptionTable table = makeTable();
    return table;
}

void validate(const SkyLightSettings& s) { checkRanges(skyLightOptions(), &s); }

}  // namespace penumbra
