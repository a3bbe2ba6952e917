// The settings of a penumbra frame: image size and output, the shadow maps, and the GI technique
// (reflective shadow maps or light propagation volumes) with its own settings. Default-constructed
// values are the library's defaults (the same as the `penumbra` tool's internal ones; the tool itself
// starts from PCF shadows and RSM GI).
#pragma once
#include <cstdint>

#include "penumbra/dsm_settings.h"
#include "penumbra/lpv_settings.h"
#include "penumbra/rsm_settings.h"

namespace penumbra::api {

using penumbra::DsmLookup;
using penumbra::DsmSettings;
using penumbra::LpvGeometry;
using penumbra::LpvSettings;
using penumbra::RsmFar;
using penumbra::RsmMode;
using penumbra::RsmRadii;
using penumbra::RsmSettings;
using penumbra::RsmVisibility;
using penumbra::RsmWeights;

// Default (per light): the renderer's ShadowSettings::filter.
enum class ShadowFilter : uint32_t { Default, Hard, Pcf, Pcss, Vsm, Evsm, Msm };
enum class PointShadowMode : uint32_t { Cube, Paraboloid };
// Who draws the shadow maps: the raster hardware, the compute rasterizer, or by the device's kind.
enum class RasterMode : uint32_t { Hardware, Compute, Auto };

// Cascaded shadow maps of directional lights.
struct CascadeSettings {
    uint32_t count;    // 1..8
    float lambda;      // 0 = uniform splits, 1 = logarithmic
    float blend;       // blend band at a cascade's far end, a fraction of its depth range
    float distance;    // shadowed view depth; 0 = the camera's far plane
    bool stabilize;    // snap to texels
    CascadeSettings();
};

struct ShadowSettings {
    uint32_t resolution;      // texels per side of each layer (16..16384)
    float depthBiasConstant;
    float depthBiasSlope;
    float normalOffset;       // receiver offset along its normal, in texels
    ShadowFilter filter;      // of every light whose own filter is Default
    float pcfRadius;          // texels
    float pcssLightSize;      // diameter of spot and point lights (world units)
    float pcssSunAngle;       // angular diameter of directional lights (degrees)
    float pcssMaxRadius;      // texels
    uint32_t blurRadius;      // VSM/EVSM/MSM blur radius, texels (0..32)
    float bleedReduction;     // VSM/EVSM/MSM light-bleeding reduction
    float evsmPositive;
    float evsmNegative;
    float msmBias;
    CascadeSettings cascades;
    PointShadowMode pointMode;
    float paraboloidMaxEdgeDegrees;
    RasterMode raster;
    ShadowSettings();
};

enum class GiMode : uint32_t { None, Rsm, Lpv };
// How the camera's G-buffer is made: visibility buffer with a compute resolve, or classic raster.
enum class CameraPath : uint32_t { Visibility, Gbuffer };
// What the image shows: the tone-mapped result, or one of the debug views.
enum class Output : uint32_t { Final, Direct, Indirect, Albedo, Normal, Depth, Shadow };

struct Settings {
    uint32_t width;
    uint32_t height;
    Output output;
    float exposure;           // linear multiplier before tone mapping
    CameraPath cameraPath;
    ShadowSettings shadow;
    GiMode gi;
    bool giTemporal;          // the indirect irradiance accumulated over frames and filtered
    float giTemporalAlpha;    // the least weight of a new frame in that accumulation
    RsmSettings rsm;
    LpvSettings lpv;
    DsmSettings dsm;          // deep shadow maps (hair and blended surfaces)
    bool translucency;        // hair and BLEND surfaces composited in depth order
    Settings();
};

}  // namespace penumbra::api
