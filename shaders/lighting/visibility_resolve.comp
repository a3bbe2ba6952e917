#version 460
// The camera's G-buffer from the visibility buffer (src/render/gbuffer_pass.h): per pixel, the
// triangle of its ID seen along the pixel's centre ray: albedo (base colour with the texture's level
// of detail from the quad's neighbouring rays, as the raster path's implicit derivatives) and the
// interpolated world normal (w = SHADING_SURFACE). No ID: zeros, as the raster path clears.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "lighting/gbuffer_bindings.h"
#include "core/material.glsl"
#include "core/visibility.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = VISIBILITY_RESOLVE_FRAME) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = VISIBILITY_RESOLVE_IDS) uniform usampler2D ids;
layout(set = 0, binding = VISIBILITY_RESOLVE_ALBEDO, rgba16f) uniform writeonly image2D outAlbedo;
layout(set = 0, binding = VISIBILITY_RESOLVE_NORMAL, rgba16f) uniform writeonly image2D outNormal;
layout(push_constant) uniform Push { VisibilityResolvePush pc; };

void main() {
    const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, ivec2(pc.width, pc.height)))) return;
    const uint id = texelFetch(ids, pixel, 0).r;
    if (id == 0u) {
        imageStore(outAlbedo, pixel, vec4(0.0));
        imageStore(outNormal, pixel, vec4(0.0));
        return;
    }
    VisRay centre, dx0, dx1, dy0, dy1;
    quadRays(frame.invViewProj, pixel, vec2(pc.width, pc.height), centre, dx0, dx1, dy0, dy1);
    const VisSurface s = resolveSurface(fetchTriangle(id), centre, dx0, dx1, dy0, dy1);
    imageStore(outAlbedo, pixel, vec4(surfaceBaseColor(s).rgb, 1.0));
    imageStore(outNormal, pixel, vec4(s.normal, SHADING_SURFACE));
}
