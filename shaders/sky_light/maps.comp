#version 460
// Sky visibility from depth maps: the scene drawn once from each of a set of directions spread
// evenly over the upper hemisphere (an orthographic shadow map per direction, by the compute
// rasterizer). A traced receiver looks itself up in every map that its hemisphere holds and weighs
// each lit one by the sky's radiance from that direction and the cosine: the share of the sky's
// radiance it sees, per channel, as weigh.comp gives it for the voxel rays (upsample.comp multiplies
// it by the open sky's irradiance). The maps hold the triangles themselves (alpha-masked ones tested,
// one-sided ones by the light's rule), so thin walls neither leak nor grow.
#extension GL_GOOGLE_include_directive : require
#include "sky_light/types.h"
#include "core/reconstruct.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = SKY_MAPS_FRAME) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = SKY_MAPS_GBUFFER_NORMAL) uniform sampler2D gNormal;
layout(set = 0, binding = SKY_MAPS_GBUFFER_DEPTH) uniform sampler2D gDepth;
layout(set = 0, binding = SKY_MAPS_DEPTH) uniform sampler2DArray skyMaps;
layout(set = 0, binding = SKY_MAPS_OUT, rgba16f) uniform writeonly image2D outShare;
layout(set = 0, binding = SKY_MAPS_DIRECTIONS, std430) readonly buffer Directions { SkyMapDirection directions[]; };
layout(push_constant) uniform Push { SkyLightPush pc; };
#include "sky/radiance.glsl"
layout(set = 0, binding = SKY_MAPS_SKY_RADIANCE) uniform sampler2D skyRadianceMap;
#include "sky_light/surface.glsl"
#include "sky_light/rays.glsl"

// Whether q is lit in map k: the texel it falls in. (A bilinear compare would read texels a texel
// away, where a sloped occluder a centimetre above the receiver, a ceiling over the top of a wall,
// stands deeper than the receiver: a lit seam.)
float litInMap(uint k, vec3 q) {
    const vec3 clip = (directions[k].viewProj * vec4(q, 1.0)).xyz;  // orthographic: w = 1
    const int res = int(pc.mapResolution);
    const ivec2 t = clamp(ivec2(floor((clip.xy * 0.5 + 0.5) * float(res))), ivec2(0), ivec2(res - 1));
    return texelFetch(skyMaps, ivec3(t, int(k)), 0).r >= min(clip.z, 1.0) ? 1.0 : 0.0;
}

// Each direction's radiance, the same for every receiver: fetched once per workgroup.
shared vec3 directionRadiance[SKY_MAX_MAPS];

void main() {
    for (uint k = gl_LocalInvocationIndex; k < pc.mapCount; k += gl_WorkGroupSize.x * gl_WorkGroupSize.y)
        directionRadiance[k] = skyTextureRadiance(skyRadianceMap, directions[k].direction);
    barrier();
    const ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, imageSize(outShare)))) return;
    const SkyReceiver r = skyReceiver(min(tracedPixel(texel, pc.traceStep), ivec2(frame.width, frame.height) - 1));
    if (!r.surface || pc.mapCount == 0u) {
        imageStore(outShare, texel, vec4(1.0));
        return;
    }
    // Off the surface along its normal, and as far towards the eye: a point on a seam reconstructed a
    // hair beyond the wall it meets (outside a room) comes back into the space the camera sees.
    const vec3 q = r.p + (r.n + normalize(frame.eye - r.p)) * pc.mapOffset;
    vec3 seen = vec3(0.0), total = vec3(0.0);
    float lit = 0.0, facing = 0.0;
    for (uint k = 0u; k < pc.mapCount; ++k) {
        const vec3 d = directions[k].direction;
        const float c = dot(r.n, d);
        if (c <= 0.0) continue;
        // The sky's own radiance, not its SH: the series' smoothing moves weight from the horizon to
        // the zenith, which a street's walls see through their slot of sky.
        const vec3 l = directionRadiance[k] * c;
        const float v = litInMap(k, q);
        total += l;
        seen += l * v;
        lit += c * v;
        facing += c;
    }
    // A direction set that sees no radiance at all (a black sky's side) counts lit directions instead;
    // a surface that faces none of them (a ceiling) sees none (so an upsampled edge mixes in nothing).
    const vec3 byCount = vec3(facing > 0.0 ? lit / facing : 0.0);
    const vec3 share = mix(seen / max(total, vec3(1e-20)), byCount, vec3(lessThanEqual(total, vec3(0.0))));
    imageStore(outShare, texel, vec4(share, 1.0));
}
