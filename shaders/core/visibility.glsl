// Visibility IDs and what they resolve to, shared by every resolve (the camera's visibility buffer,
// the RSM from the shadow pass). An ID is a drawn triangle's index + 1 (0: nothing drawn): the
// drawn triangles are every instance's triangles, (instance, triangle in the index buffer), and a
// raster computes the index as the instance's base + the draw's first triangle in its mesh +
// gl_PrimitiveID (visibilityIdBase). fetchTriangle applies the instance's transform.
// The includer includes shared/types.h and core/material.glsl first.
#include "core/triangles.glsl"

struct VisRay {
    vec3 origin, direction;
};

// The ray through normalized device coordinates `ndc` of a view (its near point towards its far one).
VisRay viewRay(mat4 invViewProj, vec2 ndc) {
    const vec4 a = invViewProj * vec4(ndc, 0.0, 1.0);
    const vec4 b = invViewProj * vec4(ndc, 1.0, 1.0);
    const vec3 o = a.xyz / a.w;
    return VisRay(o, b.xyz / b.w - o);
}

// Barycentrics (xyz) and ray parameter (w) where the ray meets the triangle's plane, inside the
// triangle or not (neighbouring pixels' rays give the derivatives, as a raster's helper lanes do).
vec4 planeHit(VisTriangle tri, VisRay r) {
    const vec3 e1 = tri.p[1] - tri.p[0], e2 = tri.p[2] - tri.p[0];
    const vec3 pv = cross(r.direction, e2);
    const float inv = 1.0 / dot(e1, pv);
    const vec3 tv = r.origin - tri.p[0];
    const vec3 qv = cross(tv, e1);
    const float u = dot(tv, pv) * inv, v = dot(r.direction, qv) * inv;
    return vec4(1.0 - u - v, u, v, dot(e2, qv) * inv);
}

vec2 interpolateUv(VisTriangle tri, vec3 b) { return b.x * tri.uv[0] + b.y * tri.uv[1] + b.z * tri.uv[2]; }

struct VisSurface {
    vec3 position;
    vec3 normal;     // interpolated and normalized (not turned to any side)
    vec2 uv;
    vec2 uvDx, uvDy; // uv differences to the next pixel in x and y: the gradients for textureGrad
    uint material;
};

// The surface of `tri` seen along `centre`; `dx` and `dy` are the rays of the pixels whose
// differences a raster takes as derivatives.
VisSurface resolveSurface(VisTriangle tri, VisRay centre, VisRay dx0, VisRay dx1, VisRay dy0, VisRay dy1) {
    const vec4 h = planeHit(tri, centre);
    VisSurface s;
    s.position = centre.origin + h.w * centre.direction;
    s.normal = normalize(h.x * tri.n[0] + h.y * tri.n[1] + h.z * tri.n[2]);
    s.uv = interpolateUv(tri, h.xyz);
    s.uvDx = interpolateUv(tri, planeHit(tri, dx1).xyz) - interpolateUv(tri, planeHit(tri, dx0).xyz);
    s.uvDy = interpolateUv(tri, planeHit(tri, dy1).xyz) - interpolateUv(tri, planeHit(tri, dy0).xyz);
    s.material = tri.material;
    return s;
}

// Rays for resolveSurface at pixel `p` of a `size` image: derivatives as a raster's 2x2 quads take
// them (coarse: the quad's first row and column), so textures get the same level of detail.
void quadRays(mat4 invViewProj, ivec2 p, vec2 size, out VisRay centre, out VisRay dx0, out VisRay dx1,
              out VisRay dy0, out VisRay dy1) {
    const vec2 scale = 2.0 / size;
    const ivec2 q = p & ~1;
    centre = viewRay(invViewProj, (vec2(p) + 0.5) * scale - 1.0);
    dx0 = viewRay(invViewProj, (vec2(q) + 0.5) * scale - 1.0);
    dx1 = viewRay(invViewProj, (vec2(q) + vec2(1.5, 0.5)) * scale - 1.0);
    dy0 = dx0;
    dy1 = viewRay(invViewProj, (vec2(q) + vec2(0.5, 1.5)) * scale - 1.0);
}

vec4 surfaceBaseColor(VisSurface s) { return baseColorGrad(s.material, s.uv, s.uvDx, s.uvDy); }
