// The settings of a frame pipeline: image size, output, and each technique's own settings.
// The CLI, `bench`, the viewer and tests fill it; Renderer::apply takes changes of it at run time
// (renderer/settings_change.h says what each change costs).
#pragma once
#include <cstdint>

#include "dsm/dsm_settings.h"
#include "lpv/lpv_settings.h"
#include "rsm/rsm_settings.h"
#include "shadow/shadow_settings.h"
#include "shared/types.h"

namespace penumbra {

enum class Aov {
    Direct = AOV_DIRECT,
    Albedo = AOV_ALBEDO,
    Normal = AOV_NORMAL,
    Depth = AOV_DEPTH,
    Shadow = AOV_SHADOW,
    Final = AOV_FINAL,
    Indirect = AOV_INDIRECT,
    LpvSlice = AOV_LPV_SLICE,
    GvSlice = AOV_GV_SLICE,
    Cascade = AOV_CASCADE,
    Transmittance = AOV_TRANSMITTANCE,
    DsmLists = AOV_DSM_LISTS,
    RsmDepth = AOV_RSM_DEPTH,
    RsmNormal = AOV_RSM_NORMAL,
    RsmFlux = AOV_RSM_FLUX,
    ShadowMap = AOV_SHADOW_MAP,
    Velocity = AOV_VELOCITY,
};

enum class GiMode { None, Rsm, Lpv };

// The camera's G-buffer (lighting/gbuffer_pass.h): visibility buffer + compute resolve, or classic raster.
enum class CameraPath { Visibility, Gbuffer };

struct RenderSettings {
    uint32_t width = 1280;
    uint32_t height = 720;
    Aov aov = Aov::Final;
    uint32_t aovLayer = 0;  // the layer the rsm-* and shadow-map AOVs show (clamped to the layers there are)
    float exposure = 1.0f;  // linear multiplier before the tone mapper
    CameraPath cameraPath = CameraPath::Visibility;  // how the camera's G-buffer is made (lighting/gbuffer_pass.h)
    ShadowSettings shadow;
    GiMode gi = GiMode::None;
    // Temporal accumulation of the indirect irradiance (temporal_gi/gi_history.h): off by default, it trades
    // flicker under moving lights for lag (README "Temporal stability"); alpha = the new frame's weight.
    bool giTemporal = false;
    float giTemporalAlpha = 0.1f;
    RsmSettings rsm;
    LpvSettings lpv;
    DsmSettings dsm;
    // `--translucency`: hair and alphaMode BLEND surfaces composited over the opaque image in depth
    // order (src/dsm/translucency.h); off: both are drawn opaque into the G-buffer.
    bool translucency = true;
    // The frame graph (core/frame_graph.h) runs passes that do not depend on one another together
    // (`bench --overlap`; off: one after another, a barrier before each that needs one).
    bool overlapPasses = true;
};

}  // namespace penumbra
