// Where a world point lands in a light's shadow layers. Needs `shadowLayers` (GpuShadowLayer[]) and
// `params` (GpuShadowParams) declared by the including shader.
#include "shadow/paraboloid.glsl"

struct ShadowCoord {
    vec3 uvLayer;  // texture coordinates and array layer
    float depth;   // the value the map stores for this point (compare reference)
};

#include "shadow/cube_face.glsl"

// The layer of light `s` that holds world point q: `chosen` for a spot light or the cascade chosen
// for the pixel, the face or hemisphere in q's direction for a point light (so that filter taps
// cross faces and the paraboloid seam seamlessly).
uint shadowLayerFor(GpuShadowLight s, GpuLight light, uint chosen, vec3 q) {
    vec3 d = q - light.position;
    if (s.kind == SHADOW_KIND_CUBE) return s.firstLayer + cubeFace(d);
    if (s.kind == SHADOW_KIND_PARABOLOID) return s.firstLayer + (dot(d, light.direction) >= 0.0 ? 0u : 1u);
    return chosen;
}

ShadowCoord shadowProject(uint layerIndex, vec3 q) {
    GpuShadowLayer layer = shadowLayers[layerIndex];
    if (layer.projection == SHADOW_PROJ_PARABOLOID) {
        vec3 v = (layer.viewProj * vec4(q, 1.0)).xyz;
        vec3 m = paraboloidProject(v, layer.zNear, layer.zFar, layer.discScale);
        return ShadowCoord(vec3(m.xy * 0.5 + 0.5, float(layerIndex)), m.z);
    }
    vec4 clip = layer.viewProj * vec4(q, 1.0);
    // Behind a perspective light: outside the map (the border reads as lit; no light goes there).
    if (clip.w <= 0.0) return ShadowCoord(vec3(-1.0, -1.0, float(layerIndex)), 0.0);
    vec3 ndc = clip.xyz / clip.w;
    return ShadowCoord(vec3(ndc.xy * 0.5 + 0.5, float(layerIndex)), ndc.z);
}

// World size of one texel of the layer at q (normal offset, filter radii).
float shadowTexelAt(uint layerIndex, vec3 q, vec3 lightPosition) {
    GpuShadowLayer layer = shadowLayers[layerIndex];
    if (layer.projection == SHADOW_PROJ_ORTHO) return layer.texelSize;
    if (layer.projection == SHADOW_PROJ_PARABOLOID) return layer.texelSize * distance(q, lightPosition);
    return layer.texelSize * (layer.viewProj * vec4(q, 1.0)).w;  // w = depth along the face's axis
}

// Distance from the light of a stored depth on the ray through q (PCSS): along the light direction
// from the near plane for orthographic layers, from the light's position otherwise.
float shadowDistance(uint layerIndex, float depth, vec3 q, vec3 lightPosition) {
    GpuShadowLayer layer = shadowLayers[layerIndex];
    float n = layer.zNear, f = layer.zFar;
    if (layer.projection != SHADOW_PROJ_PERSPECTIVE) return n + depth * (f - n);  // stored linear
    // Perspective: depth -> view depth, then to the distance along q's ray.
    float z = n * f / (f - depth * (f - n));
    return z * distance(q, lightPosition) / max((layer.viewProj * vec4(q, 1.0)).w, 1e-20);
}
