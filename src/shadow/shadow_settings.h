// Shadow-map settings: resolution and bias (seed 004), the filter family and its parameters,
// cascades for directional lights, cube or dual-paraboloid maps for point lights.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/raster_mode.h"
#include "scene/scene.h"
#include "shadow/cascades.h"

namespace penumbra {

enum class PointShadowMode { Cube, Paraboloid };

struct ShadowSettings {
    uint32_t resolution = 2048;
    // Rasterizer depth bias. D32_SFLOAT's constant unit is 2^(e-23) of the primitive's largest depth
    // exponent, so the constant term is small; the slope term does the work on slanted receivers.
    float depthBiasConstant = 4.0f;
    float depthBiasSlope = 1.5f;
    // Receiver offset along its normal, in shadow texels (texel world size at the receiver).
    float normalOffset = 1.0f;

    // Filter of every light whose own Light::shadowFilter is Default.
    ShadowFilter filter = ShadowFilter::Hard;
    float pcfRadius = 1.5f;          // PCF kernel radius, texels
    float pcssLightSize = 0.1f;      // PCSS: diameter of spot and point lights (world units)
    float pcssSunAngle = 1.0f;       // PCSS: angular diameter of directional lights (degrees)
    float pcssMaxRadius = 24.0f;     // PCSS: largest blocker search and filter radius, texels
    uint32_t blurRadius = 3;         // VSM/EVSM/MSM: Gaussian blur radius, texels (0..32)
    float bleedReduction = 0.25f;    // VSM/EVSM/MSM: light-bleeding reduction, linstep(amount, 1, p)
    float evsmPositive = 40.0f;      // EVSM exponents (fp32 moments overflow above ~42)
    float evsmNegative = 5.0f;
    float msmBias = 3e-5f;           // MSM moment bias (Peters & Klein 2015)

    CascadeSettings cascades;        // directional lights
    PointShadowMode pointMode = PointShadowMode::Cube;
    float paraboloidMaxEdgeDegrees = 2.0f;  // tessellation: largest angle an edge may span
    // Who draws the layers (and the camera's visibility buffer): the raster hardware, or the compute
    // rasterizer (src/raster) for every light but paraboloid point lights (their bent edges stay with
    // the tessellated hardware pass). Auto: by the device's kind (computeRasterFor): the compute
    // rasterizer where the raster path is narrow (H100, H200: faster over the whole rasterizer sweep,
    // docs/techniques/shadows.md), the hardware elsewhere, lavapipe included.
    RasterMode raster = RasterMode::Auto;
};

// "hard", "pcf", "pcss", "vsm", "evsm", "msm" (throws std::invalid_argument naming `option`).
ShadowFilter parseShadowFilter(const std::string& name, const std::string& option);
std::string shadowFilterName(ShadowFilter filter);
std::vector<std::string> shadowFilterNames();

// Holds settings built in code to the ranges of the option table (shadow_options.h); throws
// std::invalid_argument naming the option.
void validate(const ShadowSettings& settings);

}  // namespace penumbra
