#include "sky_light/sky_light_options.h"

#include "sky_light/types.h"  // SKY_MAX_RAYS

namespace penumbra {
namespace {

using namespace change;

OptionTable makeTable() {
    using S = SkyLightSettings;
    OptionTableBuilder<S> t("sky_light", "Sky light: the visible sky's irradiance per pixel");
    t.choice("--sky-visibility", "visibility", [](S& s) -> auto& { return s.visibility; },
             std::vector<std::pair<std::string, SkyVisibility>>{{"auto", SkyVisibility::Auto},
                                                                {"maps", SkyVisibility::Maps},
                                                                {"voxels", SkyVisibility::Voxels},
                                                                {"none", SkyVisibility::None}},
             kStructure,
             "What hides the sky from a surface: depth maps of the scene from directions over the sky, rays "
             "through the occupancy volume ({rsm.voxel_resolution}), or nothing (every surface sees its whole "
             "hemisphere); auto: the maps, or the rays where the maps would draw more than 19.2M triangles "
             "in all (64 maps of a 300k-triangle scene)")
        .rebuild({"camera", "gi"});  // the occupancy volume comes and goes with it
    t.integer("--sky-maps", "maps", [](S& s) -> auto& { return s.mapCount; }, 4, SKY_MAX_MAPS, kSizes,
              "Sky visibility maps: directions spread evenly over the upper hemisphere, one depth map each")
        .rebuild({"camera"});
    t.integer("--sky-map-res", "map_resolution", [](S& s) -> auto& { return s.mapResolution; }, 64, 2048, kSizes,
              "Texels per side of each sky visibility map (the whole scene seen from its direction)")
        .rebuild({"camera"});
    t.real("--sky-map-offset", "map_offset", [](S& s) -> auto& { return s.mapOffset; }, 0.0, 8.0, kFrame,
           "Sky visibility map texels off the surface, along its normal, where a receiver looks itself up");
    t.integer("--sky-rays", "rays", [](S& s) -> auto& { return s.rays; }, 1, SKY_MAX_RAYS, kFrame,
              "Voxels: sky visibility rays per traced receiver (a 4x4 block of receivers turns its sets apart; the filter "
              "joins them)");
    t.integer("--sky-trace-step", "trace_step", [](S& s) -> auto& { return s.traceStep; }, 1, 4, kSizes,
              "Camera pixels between the receivers whose sky visibility is traced, per axis (1: every pixel)")
        .rebuild({"camera"});
    t.integer("--sky-filter-radius", "filter_radius", [](S& s) -> auto& { return s.filterRadius; }, 0, 8, kFrame,
              "Traced receivers either side over which the sky visibility is averaged on a pixel's surface (0: "
              "the nearest only)");
    t.real("--sky-ray-offset", "ray_offset", [](S& s) -> auto& { return s.startOffset; }, 0.5, 8.0, kFrame,
           "Voxels: voxels off the surface, along its normal, where the sky visibility rays start");
    return t.build();
}

}  // namespace

const OptionTable& skyLightOptions() {
    static const OptionTable table = makeTable();
    return table;
}

void validate(const SkyLightSettings& s) { checkRanges(skyLightOptions(), &s); }

}  // namespace penumbra
