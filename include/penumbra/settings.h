// The settings of a penumbra frame: image size, output and exposure, the shadow maps, the GI technique
// (reflective shadow maps or light propagation volumes) with its own settings and its accumulation
// over frames, and the sky. Default-constructed values are the library's defaults, the same as the
// `penumbra` tool's internal ones but for two that an engine usually owns: the exposure is a fixed
// multiplier and there is no sky (the tool meters its images and lights outdoor scenes with an
// analytic sky). Every option of the tool that sets a technique has its field here.
#pragma once
#include <cstdint>
#include <string>

#include "penumbra/dsm_settings.h"
#include "penumbra/lpv_settings.h"
#include "penumbra/rsm_settings.h"
#include "penumbra/sky_light_settings.h"
#include "penumbra/temporal_gi_settings.h"

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
using penumbra::SkyLightSettings;
using penumbra::SkyVisibility;
using penumbra::TemporalGiSettings;

struct Vec3 {
    float x = 0.0f, y = 0.0f, z = 0.0f;
};

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

// The sky that lights the scene and shows behind it (docs/techniques/lighting.md).
enum class SkyKind : uint32_t { None, Uniform, Analytic, Map };
struct SkySettings {
    SkyKind kind;
    Vec3 uniformRadiance;   // Uniform: radiance over the upper hemisphere
    float turbidity;        // Analytic: Preetham's atmospheric turbidity (2..10), driven by the first directional light
    std::string mapPath;    // Map: an equirectangular OpenEXR file, +Y up
    float scale;            // multiplies every kind's radiance
    float rotationDegrees;  // Map: its turn about +Y
    float sunIlluminance;   // Analytic: the sun's illuminance the sky is scaled to; 0: the first directional light's
    SkySettings();
};

struct Settings {
    uint32_t width;
    uint32_t height;
    Output output;
    float exposure;               // linear multiplier before tone mapping, while autoExposure is off
    bool autoExposure;            // meter the geometry's luminance to middle grey instead
    float exposureCompensation;   // EV added to the metered exposure
    float exposureLowPercentile;  // the luminance percentiles the meter averages between
    float exposureHighPercentile;
    CameraPath cameraPath;
    ShadowSettings shadow;
    GiMode gi;
    bool giTemporal;              // the indirect irradiance accumulated over frames and filtered
    TemporalGiSettings temporalGi;
    RsmSettings rsm;
    LpvSettings lpv;
    DsmSettings dsm;              // deep shadow maps (hair and blended surfaces)
    bool translucency;            // hair and BLEND surfaces composited in depth order
    SkySettings sky;
    SkyLightSettings skyLight;    // how each pixel's view of the sky is found
    bool overlapPasses;           // independent passes run together
    Settings();
};

}  // namespace penumbra::api
