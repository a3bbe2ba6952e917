#include "shadow/shadow_options.h"

namespace penumbra {
namespace {

using namespace change;

// Shadow-map sizes also size the RSM (its layers follow the shadow layers) and the DSM (whose
// resolution defaults to the shadow map's).
const std::vector<std::string> kShadowSized{"shadow", "gi", "dsm"};

void addMapRows(OptionTableBuilder<ShadowSettings>& t) {
    using S = ShadowSettings;
    t.integer("--shadow-res", "resolution", [](S& s) -> auto& { return s.resolution; }, 16, 16384, kSizes,
              "Shadow map resolution")
        .rebuild(kShadowSized);
    t.real("--shadow-bias-constant", "bias_constant", [](S& s) -> auto& { return s.depthBiasConstant; }, 0.0, 1e6,
           kFrame, "Rasterizer constant depth bias");
    t.real("--shadow-bias-slope", "bias_slope", [](S& s) -> auto& { return s.depthBiasSlope; }, 0.0, 100.0, kFrame,
           "Rasterizer slope-scaled depth bias");
    t.real("--shadow-normal-offset", "normal_offset", [](S& s) -> auto& { return s.normalOffset; }, 0.0, 100.0,
           kFrame, "Receiver normal offset in shadow texels");
    t.choice("--raster", "raster", [](S& s) -> auto& { return s.raster; },
             std::vector<std::pair<std::string, RasterMode>>{
                 {"hardware", RasterMode::Hardware}, {"compute", RasterMode::Compute}, {"auto", RasterMode::Auto}},
             kStructure,
             "Who draws the shadow maps and the camera's visibility buffer: the raster hardware, the compute "
             "rasterizer (paraboloid point lights stay on the hardware), or auto (by the device's kind: compute on "
             "NVIDIA H100/H200, the hardware elsewhere)")
        .rebuild({"shadow", "camera"});
    t.choice("--point-shadow", "point_shadow", [](S& s) -> auto& { return s.pointMode; },
             std::vector<std::pair<std::string, PointShadowMode>>{{"cube", PointShadowMode::Cube},
                                                                  {"paraboloid", PointShadowMode::Paraboloid}},
             kStructure, "Point-light shadow maps: 6 cube faces or 2 paraboloids")
        .rebuild(kShadowSized);
    t.real("--paraboloid-max-edge", "paraboloid_max_edge", [](S& s) -> auto& { return s.paraboloidMaxEdgeDegrees; },
           0.2, 90.0, kStructure, "Paraboloid maps: the largest angle a tessellated edge may span, degrees")
        .rebuild(kShadowSized);
}

void addFilterRows(OptionTableBuilder<ShadowSettings>& t) {
    using S = ShadowSettings;
    t.real("--pcf-radius", "pcf_radius", [](S& s) -> auto& { return s.pcfRadius; }, 0.0, 64.0, kFrame,
           "PCF kernel radius in shadow texels");
    t.real("--pcss-light-size", "pcss_light_size", [](S& s) -> auto& { return s.pcssLightSize; }, 1e-6, 1e6, kFrame,
           "PCSS: spot/point light diameter, world units");
    t.real("--pcss-sun-angle", "pcss_sun_angle", [](S& s) -> auto& { return s.pcssSunAngle; }, 1e-4, 89.0, kFrame,
           "PCSS: directional light angular diameter, degrees");
    t.real("--pcss-max-radius", "pcss_max_radius", [](S& s) -> auto& { return s.pcssMaxRadius; }, 1.0, 128.0,
           kFrame, "PCSS: largest search/filter radius, texels");
    t.integer("--vsm-blur", "moment_blur", [](S& s) -> auto& { return s.blurRadius; }, 0, 32, kFrame,
              "VSM/EVSM/MSM blur radius, texels");
    t.real("--vsm-bleed", "moment_bleed", [](S& s) -> auto& { return s.bleedReduction; }, 0.0, 0.99, kFrame,
           "VSM/EVSM/MSM light-bleeding reduction");
    t.real("--evsm-positive", "evsm_positive", [](S& s) -> auto& { return s.evsmPositive; }, 0.1, 42.0, kFrame,
           "EVSM positive exponent (32-bit float moments overflow above 42)");
    t.real("--evsm-negative", "evsm_negative", [](S& s) -> auto& { return s.evsmNegative; }, 0.1, 42.0, kFrame,
           "EVSM negative exponent");
    t.real("--msm-bias", "msm_bias", [](S& s) -> auto& { return s.msmBias; }, 0.0, 0.1, kFrame,
           "MSM moment bias (Peters and Klein 2015)");
}

void addCascadeRows(OptionTableBuilder<ShadowSettings>& t) {
    using S = ShadowSettings;
    t.integer("--cascades", "cascades", [](S& s) -> auto& { return s.cascades.count; }, 1, 8, kSizes,
              "Directional lights: cascade count")
        .rebuild(kShadowSized);
    t.real("--csm-lambda", "csm_lambda", [](S& s) -> auto& { return s.cascades.lambda; }, 0.0, 1.0, kFrame,
           "Cascade split: 0 uniform .. 1 logarithmic");
    t.real("--csm-blend", "csm_blend", [](S& s) -> auto& { return s.cascades.blend; }, 0.0, 0.5, kFrame,
           "Blend band between cascades, fraction");
    t.real("--csm-distance", "csm_distance", [](S& s) -> auto& { return s.cascades.distance; }, 0.0, 1e9, kFrame,
           "Shadowed view distance (0: the far plane)");
    t.boolean("--csm-stabilize", "csm_stabilize", [](S& s) -> auto& { return s.cascades.stabilize; }, kFrame,
              "Snap cascades to whole texels (off shows the shimmering it prevents)");
}

OptionTable makeTable() {
    OptionTableBuilder<ShadowSettings> t("shadow", "Shadow maps");
    addMapRows(t);
    addFilterRows(t);
    addCascadeRows(t);
    return t.build();
}

}  // namespace

const OptionTable& shadowOptions() {
    static const OptionTable table = makeTable();
    return table;
}

}  // namespace penumbra
