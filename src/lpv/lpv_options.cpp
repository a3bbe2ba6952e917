#include "lpv/lpv_options.h"

#include <stdexcept>

#include <fmt/format.h>

namespace penumbra {
namespace {

using namespace change;

OptionTable makeTable() {
    using S = LpvSettings;
    OptionTableBuilder<S> t("lpv", "Light propagation volumes");
    t.integer("--lpv-res", "resolution", [](S& s) -> auto& { return s.resolution; }, 4, 256, kSizes,
              "LPV cells per side");
    // Pass counts: the next frame lists its passes from the new value; nothing is re-created.
    t.integer("--lpv-iterations", "iterations", [](S& s) -> auto& { return s.iterations; }, 1, 256, kStructure,
              "LPV propagation steps")
        .rebuild({"none"});
    t.integer("--lpv-cascades", "cascades", [](S& s) -> auto& { return s.cascades; }, 1, 4, kSizes, "LPV cascades")
        .orSpecial(0, "1 for small scenes, 3 for large");
    t.integer("--lpv-rsm-res", "rsm_resolution", [](S& s) -> auto& { return s.rsmResolution; }, 16, 8192, kSizes,
              "RSM resolution for LPV injection");
    t.integer("--lpv-vpl-res", "vpl_resolution", [](S& s) -> auto& { return s.vplResolution; }, 1, 8192, kSizes,
              "Down-sampled VPLs per side (divides {lpv.rsm_resolution})");
    t.boolean("--lpv-occlusion", "occlusion", [](S& s) -> auto& { return s.occlusion; }, kFrame,
              "Geometry-volume occlusion");
    t.choice("--lpv-geometry", "geometry", [](S& s) -> auto& { return s.geometry; },
             std::vector<std::pair<std::string, LpvGeometry>>{{"surfels", LpvGeometry::Surfels},
                                                             {"voxels", LpvGeometry::Voxels}},
             kStructure,
             "What blocks propagation: surfels (geometry volume) or voxels (the occupancy volume, {rsm.voxel_resolution})");
    t.boolean("--lpv-camera-geometry", "camera_geometry", [](S& s) -> auto& { return s.cameraGeometry; },
              kStructure, "Inject camera G-buffer occluders")
        .rebuild({"none"});
    t.integer("--lpv-camera-geometry-step", "camera_geometry_step", [](S& s) -> auto& { return s.cameraGeometryStep; },
              1, 64, kFrame, "Camera occluders: one surfel per step x step pixels");
    t.real("--lpv-lag-tolerance", "lag_tolerance", [](S& s) -> auto& { return s.lagTolerance; }, 1e-3, 1e3, kFrame,
           "The LPV's temporal gradients: a relative change of c in a frame weighs the new frame of the GI history "
           "at least c / this (lower: less lag, more flicker)");
    t.real("--lpv-blend-cells", "blend_cells", [](S& s) -> auto& { return s.blendCells; }, 0.0, 16.0, kFrame,
           "Cascade border blend band, in cells");
    t.integer("--lpv-slice-axis", "slice_axis", [](S& s) -> auto& { return s.sliceAxis; }, 0, 2, kFrame,
              "Axis of the lpv-slice/gv-slice AOV: 0=x 1=y 2=z");
    t.integer("--lpv-slice", "slice", [](S& s) -> auto& { return s.sliceIndex; }, 0, 255, kFrame,
              "Cell index of the lpv-slice/gv-slice AOV (< {lpv.resolution})");
    return t.build();
}

}  // namespace

const OptionTable& lpvOptions() {
    static const OptionTable table = makeTable();
    return table;
}

void validate(const LpvSettings& s) {
    const OptionTable& t = lpvOptions();
    checkRanges(t, &s);
    if (s.rsmResolution % s.vplResolution)
        throw std::invalid_argument(fmt::format("{} {} must be a multiple of {} {}",
                                                t.flagOf<LpvSettings>([](LpvSettings& x) -> auto& { return x.rsmResolution; }),
                                                s.rsmResolution,
                                                t.flagOf<LpvSettings>([](LpvSettings& x) -> auto& { return x.vplResolution; }),
                                                s.vplResolution));
}

}  // namespace penumbra
