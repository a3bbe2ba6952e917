#include "rsm/rsm_options.h"

#include <stdexcept>

#include <fmt/format.h>

namespace penumbra {
namespace {

using namespace change;

OptionTable makeTable() {
    using S = RsmSettings;
    OptionTableBuilder<S> t("rsm", "Reflective shadow maps");
    t.integer("--rsm-res", "resolution", [](S& s) -> auto& { return s.resolution; }, 8, 8192, kSizes,
              "RSM resolution per light");
    t.integer("--rsm-samples", "samples", [](S& s) -> auto& { return s.samples; }, 1, kMaxRsmSamples, kFrame,
              "RSM gather samples per pixel");
    t.real("--rsm-lag-tolerance", "lag_tolerance", [](S& s) -> auto& { return s.lagTolerance; }, 1e-3, 1e3, kFrame,
           "The RSM's temporal gradients: a relative change of c in a frame beyond their noise weighs the new frame "
           "of the GI history at least c / this (lower: less lag, more flicker)");
    t.integer("--rsm-frame-samples", "frame_samples", [](S& s) -> auto& { return s.frameSamples; }, 1,
              kMaxRsmSamples, kFrame,
              "RSM gather samples per pixel in a frame that adds to the GI history ({frame.gi_temporal}; at most "
              "{rsm.samples}, which a frame that starts the history takes)");
    t.real("--rsm-radius", "radius", [](S& s) -> auto& { return s.radius; }, 1e-4, 2.0, kFrame,
           "RSM sampling radius r_max in RSM uv units");
    t.integer("--rsm-seed", "seed", [](S& s) -> auto& { return s.seed; }, 0, 4294967295.0, kFrame,
              "Seed of the RSM sample pattern");
    t.choice("--rsm-mode", "mode", [](S& s) -> auto& { return s.mode; },
             std::vector<std::pair<std::string, RsmMode>>{
                 {"interpolated", RsmMode::Interpolated}, {"full", RsmMode::Full}, {"all-texels", RsmMode::AllTexels}},
             kStructure, "RSM gather: interpolated low-resolution, full, or all-texels (exact; {rsm.resolution} <= 64)");
    t.choice("--rsm-weights", "weights", [](S& s) -> auto& { return s.weights; },
             std::vector<std::pair<std::string, RsmWeights>>{{"unbiased", RsmWeights::Unbiased},
                                                             {"paper", RsmWeights::Paper}},
             kFrame, "RSM sample weights: unbiased, or the paper's xi1^2");
    t.integer("--rsm-lowres", "lowres_factor", [](S& s) -> auto& { return s.lowResFactor; }, 1, 32, kSizes,
              "Low-resolution gather factor");
    t.real("--rsm-normal-threshold", "normal_threshold", [](S& s) -> auto& { return s.normalThreshold; }, 0.0, 1.0,
           kFrame, "Interpolation: least |cos| between a pixel's normal and a low-resolution sample's");
    t.real("--rsm-distance-threshold", "distance_threshold", [](S& s) -> auto& { return s.distanceThreshold; }, 0.0,
           100.0, kFrame, "Interpolation: largest distance off the tangent plane, in low-resolution cell footprints");
    t.choice("--rsm-vpls", "vpls", [](S& s) -> auto& { return s.bilinearVpls; },
             std::vector<std::pair<std::string, bool>>{{"nearest", false}, {"bilinear", true}}, kFrame,
             "A gather sample's VPL: the texel it falls in, or the four around it weighted bilinearly "
             "(4x the cost; steadier under moving lights)");
    t.choice("--rsm-visibility", "visibility", [](S& s) -> auto& { return s.visibility; },
             std::vector<std::pair<std::string, RsmVisibility>>{{"none", RsmVisibility::None},
                                                                {"depth", RsmVisibility::Depth},
                                                                {"views", RsmVisibility::Views},
                                                                {"voxels", RsmVisibility::Voxels}},
             kStructure,
             "Whether a VPL sees its receiver: not tested, far samples against the RSM's depth, every sample "
             "against the RSM's and the camera's depth, or every sample through the scene's occupancy volume");
    t.integer("--rsm-visibility-points", "visibility_points", [](S& s) -> auto& { return s.visibilityPoints; }, 1,
              16, kFrame, "Views visibility: points of a VPL-receiver segment tested against the two depth maps");
    t.integer("--rsm-voxel-res", "voxel_resolution", [](S& s) -> auto& { return s.voxelResolution; }, 8, 1024,
              kSizes, "Occupancy volume ({rsm.visibility} voxels): voxels along the scene's longest side");
    t.choice("--rsm-radii", "radii", [](S& s) -> auto& { return s.radii; },
             std::vector<std::pair<std::string, RsmRadii>>{{"fixed", RsmRadii::Fixed}, {"shifted", RsmRadii::Shifted}},
             kStructure,
             "The sample pattern's radii: the same for every receiver, or shifted per receiver (unbiased; always "
             "with {rsm.visibility} voxels)");
    t.choice("--rsm-far", "far", [](S& s) -> auto& { return s.far; },
             std::vector<std::pair<std::string, RsmFar>>{{"disc", RsmFar::Disc}, {"flux", RsmFar::Flux}}, kStructure,
             "The far half of the RSM samples: a disc over the whole map, or texels drawn by their flux "
             "(combined with the r_max disc's by the balance heuristic)");
    t.integer("--rsm-visibility-rays", "visibility_rays", [](S& s) -> auto& { return s.visibilityRays; }, 1,
              kMaxRsmSamples, kFrame,
              "Voxel visibility: samples a pixel tests through the occupancy volume (the visible share of their "
              "light scales all samples' light)");
    t.boolean("--rsm-per-cascade", "per_cascade", [](S& s) -> auto& { return s.perCascade; }, kStructure,
              "A sun's RSM per cascade (the seed's way) instead of from its widest cascade only")
        .bareFlag = true;
    return t.build();
}

}  // namespace

const OptionTable& rsmOptions() {
    static const OptionTable table = makeTable();
    return table;
}

void validate(const RsmSettings& s) { checkRanges(rsmOptions(), &s); }

}  // namespace penumbra
