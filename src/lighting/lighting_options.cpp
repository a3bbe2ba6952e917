#include "lighting/lighting_options.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace penumbra {
namespace {

using namespace change;

// `--exposure-percentiles LOW,HIGH`: two numbers in [0, 100], LOW below HIGH.
void parseExposurePercentiles(LightingSettings& s, const std::string& text) {
    const size_t comma = text.find(',');
    double v[2] = {0.0, 0.0};
    for (int k = 0; k < 2; ++k) {
        const std::string part = k == 0 ? text.substr(0, comma) : text.substr(comma + 1);
        size_t used = 0;
        try {
            v[k] = std::stod(part, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (comma == std::string::npos || used == 0 || used != part.size() || !std::isfinite(v[k]))
            throw std::invalid_argument("expected LOW,HIGH, two numbers in [0, 100]");
    }
    if (v[0] < 0.0 || v[1] > 100.0 || v[0] >= v[1])
        throw std::invalid_argument("expected 0 <= LOW < HIGH <= 100");
    s.exposureLowPercentile = float(v[0]), s.exposureHighPercentile = float(v[1]);
}

void addExposureRow(OptionTableBuilder<LightingSettings>& t) {
    using S = LightingSettings;
    OptionRow& row = t.text(
        "--exposure-percentiles", "exposure_percentiles", [](S& s) -> auto& { return s.exposureLowPercentile; },
        [](const S& s) {
            return std::vector<std::string>{formatOptionNumber(s.exposureLowPercentile) + "," +
                                            formatOptionNumber(s.exposureHighPercentile)};
        },
        parseExposurePercentiles, kFrame,
        "What {frame.exposure} auto meters: the mean log luminance of the geometry pixels ranked between these "
        "percentiles (0 to 100) maps to middle grey; the darkest (hard shadows) and the brightest (highlights) "
        "do not move the exposure. 0,100: the log-average of all of them");
    row.placeholder = "LOW,HIGH";
    t.alsoWrites([](S& s) -> auto& { return s.exposureHighPercentile; });
}

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
    t.real("--sky-sun-illuminance", "sky_sun_illuminance", [](S& s) -> auto& { return s.sky.sunIlluminance; }, 0.0,
           1e9, kFrame,
           "The sun's illuminance the analytic sky is scaled to, in the units of a directional light's intensity "
           "(its intensity times its colour's luminance); the sky still follows the first directional light's "
           "direction. 0: that light's own. With the light's intensity 0, the sky alone");
    t.real("--sky-rotation", "sky_rotation", [](S& s) -> auto& { return s.sky.rotationDegrees; }, -360.0, 360.0,
           kFrame, "Degrees a sky map turns about +Y, counter-clockwise seen from above");
    addExposureRow(t);
    return t.build();
}

}  // namespace

const OptionTable& lightingOptions() {
    static const OptionTable table = makeTable();
    return table;
}

void validate(const LightingSettings& s) {
    checkRanges(lightingOptions(), &s);
    if (!(s.exposureLowPercentile >= 0.0f && s.exposureLowPercentile < s.exposureHighPercentile &&
          s.exposureHighPercentile <= 100.0f))
        throw std::invalid_argument(
            lightingOptions().flagOf<LightingSettings>([](auto& t) -> auto& { return t.exposureLowPercentile; }) +
            ": expected 0 <= LOW < HIGH <= 100");
}

}  // namespace penumbra
