// The camera surfel of one step x step pixel block (the block's centre pixel): where it lies, the
// normal the camera sees and its area, the block's world footprint over the viewing cosine. The
// includer declares `frame`, gNormal and gDepth and includes core/reconstruct.glsl.
#ifndef PENUMBRA_LPV_CAMERA_SURFEL_GLSL
#define PENUMBRA_LPV_CAMERA_SURFEL_GLSL

struct CameraSurfel {
    bool valid;  // a surface (not the background, not hair) inside the image
    ivec2 pixel;
    vec3 x, n;
    float area;
};

// Hair (SHADING_HAIR, --translucency off) is no surface: its normal target holds a tangent.
CameraSurfel cameraSurfel(uvec2 block, int step) {
    CameraSurfel s;
    s.valid = false;
    s.pixel = ivec2(block) * step + step / 2;
    s.x = s.n = vec3(0.0);
    s.area = 0.0;
    if (any(greaterThanEqual(s.pixel, ivec2(frame.width, frame.height)))) return s;
    const float depth = texelFetch(gDepth, s.pixel, 0).r;
    if (depth >= 1.0) return s;
    const vec4 g = texelFetch(gNormal, s.pixel, 0);
    if (g.w > 1.5) return s;
    s.x = pixelWorldPosition(frame, s.pixel, depth);
    const vec3 toEye = frame.eye - s.x;
    const float dist = length(toEye);
    s.n = normalize(g.xyz);
    if (dot(s.n, toEye) < 0.0) s.n = -s.n;
    const float side = dist * frame.pixelSpread * float(step);
    s.area = side * side / max(dot(s.n, toEye / dist), 0.2);
    s.valid = true;
    return s;
}
#endif
