#include "lighting/lighting_options.h"

namespace penumbra {
namespace {

using namespace change;

OptionTable makeTable() {
    using S = LightingSettings;
    OptionTableBuilder<S> t("lighting", "Sky light");
    OptionRow& sky = t.text(
        "--sky", "sky", [](S& s) -> auto& { return s.sky.kind; },
        [](const S& s) { return std::vector<std::string>{skyText(s.sky)}; },
        [](S& s, const std::string& text) { parseSky(s.sky, text); }, kFrame,
        "The sky: none; uniform,r,g,b (radiance over the upper hemisphere); analytic[,turbidity] (Preetham's "
        "clear sky driven by the first directional light, its sun's illuminance the light's intensity; "
        "turbidity 2 to 10, default 3); FILE.exr (equirectangular, +Y up, the centre column toward -Z; its "
        "brightest texels are clipped when a directional light gives the sun); auto: analytic with a "
        "directional light, none without");
    sky.placeholder = "none|uniform,R,G,B|analytic[,T]|FILE.exr|auto";
    t.alsoWrites([](S& s) -> auto& { return s.sky.uniformRadiance; });
    t.alsoWrites([](S& s) -> auto& { return s.sky.turbidity; });
    t.alsoWrites([](S& s) -> auto& { return s.sky.mapPath; });
    t.real("--sky-scale", "sky_scale", [](S& s) -> auto& { return s.sky.scale; }, 0.0, 1e6, kFrame,
           "Multiplies the sky's radiance");
    t.real("--sky-rotation", "sky_rotation", [](S& s) -> auto& { return s.sky.rotationDegrees; }, -360.0, 360.0,
           kFrame, "Degrees a sky map turns about +Y, counter-clockwise seen from above");
    return t.build();
}

}  // namespace

const OptionTable& lightingOptions() {
    static const OptionTable table = makeTable();
    return table;
}

void validate(const LightingSettings& s) { checkRanges(lightingOptions(), &s); }

}  // namespace penumbra
