// The settings of a frame pipeline: the core's (image size, output, camera path) and each
// technique's own, named members for the built-in modules and an extension store for techniques
// registered from outside (renderer/technique_registry.h).
// The CLI, `bench`, the viewer and tests fill it; Renderer::apply takes changes of it at run time
// (renderer/settings_change.h says what each change costs).
#pragma once
#include <any>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>

#include "core/core_settings.h"
#include "dsm/dsm_settings.h"
#include "lighting/lighting_settings.h"
#include "lpv/lpv_settings.h"
#include "rsm/rsm_settings.h"
#include "shadow/shadow_settings.h"
#include "sky_light/sky_light_settings.h"
#include "temporal_gi/temporal_gi_settings.h"
#include "shared/types.h"

namespace penumbra {

enum class GiMode { None, Rsm, Lpv };

struct RenderSettings {
    uint32_t width = 1280;
    uint32_t height = 720;
    Aov aov = Aov::Final;
    uint32_t aovLayer = 0;  // the layer the rsm-* and shadow-map AOVs show (clamped to the layers there are)
    float exposure = 1.0f;  // linear multiplier before the tone mapper, when autoExposure is off
    // `--exposure auto`: the geometry's log-average luminance maps to 0.18 (the default of render and
    // the viewer; tests, references, stability and eval read the linear HDR image, which it leaves alone).
    bool autoExposure = true;
    float exposureCompensation = 0.0f;  // EV: the exposure times 2^EV
    CameraPath cameraPath = CameraPath::Visibility;  // how the camera's G-buffer is made (lighting/gbuffer_pass.h)
    ShadowSettings shadow;
    GiMode gi = GiMode::None;
    // The indirect irradiance accumulated over frames and filtered (src/temporal_gi); off: each frame's
    // estimate alone (the references and the single-frame tests).
    bool giTemporal = true;
    TemporalGiSettings temporalGi;
    RsmSettings rsm;
    LpvSettings lpv;
    DsmSettings dsm;
    LightingSettings lighting;  // the sky
    // How the sky's visibility is found per pixel (src/sky_light), while the sky is on.
    SkyLightSettings skyLight;
    // `--translucency`: hair and alphaMode BLEND surfaces composited over the opaque image in depth
    // order (src/dsm/translucency.h); off: both are drawn opaque into the G-buffer.
    bool translucency = true;
    // The frame graph (core/frame_graph.h) runs passes that do not depend on one another together
    // (`bench --overlap`; off: one after another, a barrier before each that needs one).
    bool overlapPasses = true;
    // Settings of registered techniques outside src/, by their registry name.
    // Mutable: an extension's settings are default-made on first read, also through a const path
    // (its option rows read them for the JSON and the settings diff).
    mutable std::map<std::string, std::any> extensions;

    // The extension's settings of type T (default-made on first use).
    template <class T>
    T& extension(const std::string& name) {
        std::any& a = extensions[name];
        if (!a.has_value()) a = T{};
        return std::any_cast<T&>(a);
    }
    // Null when never set.
    template <class T>
    const T* extension(const std::string& name) const {
        const auto it = extensions.find(name);
        return it == extensions.end() ? nullptr : std::any_cast<T>(&it->second);
    }
    // The part that every technique shares; `computeRaster` resolved for the device.
    CoreSettings core(bool computeRaster) const {
        return {width,        height,         aov,           aovLayer, exposure, cameraPath, translucency, computeRaster,
                autoExposure, exposureCompensation};
    }
};

}  // namespace penumbra
