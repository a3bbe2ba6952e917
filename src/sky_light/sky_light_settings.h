// Settings of the sky-light module (src/sky_light): how the sky's visibility at each pixel is found.
#pragma once
#include <cstdint>

namespace penumbra {

enum class SkyVisibility {
    Auto,    // Maps, or Voxels where the maps would cost more than kMaxSkyMapPairs (resolveSkyVisibility)
    Maps,    // depth maps of the scene seen from directions spread over the sky
    Voxels,  // rays through the occupancy volume (its resolution: --rsm-voxel-res)
    None,    // no occlusion: every surface sees its whole hemisphere of sky
};

struct SkyLightSettings {
    SkyVisibility visibility = SkyVisibility::Auto;
    // Maps: directions over the upper hemisphere (equal solid angles), one orthographic depth map of
    // the whole scene each, drawn once and again only when casters move.
    uint32_t mapCount = 64;
    uint32_t mapResolution = 512;
    // Where a receiver looks itself up: this many map texels off its surface, along its normal.
    float mapOffset = 1.5f;
    // Voxels: rays per traced receiver (at most 32, the bits of its clear-ray mask); neighbouring
    // receivers turn their set by different angles, and the filter averages a 4x4 block's 16 sets back
    // together.
    uint32_t rays = 8;
    // Voxels: where the rays start, this many voxels off the surface along its normal, out of the
    // voxels the surface itself occupies (half a voxel leaves many rays inside them; further off
    // misses the occluders near the receiver).
    float startOffset = 1.0f;
    // Camera pixels between traced receivers, per axis: the sky's visibility changes slowly across a
    // surface, so one receiver of each 2x2 block serves them all at a quarter of the work.
    uint32_t traceStep = 2;
    // Traced receivers either side that the filter averages over (on the pixel's own surface); 2
    // covers a 4x4 block of ray sets from every pixel.
    uint32_t filterRadius = 2;
};

// The most triangle-map pairs Auto lets the maps draw: 64 maps of a 300k-triangle scene, about a
// millisecond of the compute rasterizer on an H200. The maps' cost grows with the triangles; the voxel
// rays' does not, so a larger scene takes the rays.
inline constexpr uint64_t kMaxSkyMapPairs = 64ull * 300000ull;

// What Auto stands for in a scene of `drawnTriangles` (other choices: themselves).
inline SkyVisibility resolveSkyVisibility(const SkyLightSettings& s, uint64_t drawnTriangles) {
    if (s.visibility != SkyVisibility::Auto) return s.visibility;
    return uint64_t(s.mapCount) * drawnTriangles <= kMaxSkyMapPairs ? SkyVisibility::Maps : SkyVisibility::Voxels;
}

}  // namespace penumbra
