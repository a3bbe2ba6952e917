// L1 spherical harmonics (4 coefficients), the basis and clamped-cosine-lobe projection of
// TECHNIQUES.md section 4: Y = (0.282095, -0.488603 y, 0.488603 z, -0.488603 x).
const float SH_C0 = 0.282094792;
const float SH_C1 = 0.488602512;
const float LOBE_C0 = 0.886226925;  // sqrt(pi) / 2
const float LOBE_C1 = 1.02332671;   // sqrt(pi / 3)

vec4 shBasis(vec3 d) { return vec4(SH_C0, -SH_C1 * d.y, SH_C1 * d.z, -SH_C1 * d.x); }

// Projection of max(0, dot(n, w)): integrates to pi over the sphere.
vec4 cosineLobe(vec3 n) { return vec4(LOBE_C0, -LOBE_C1 * n.y, LOBE_C1 * n.z, -LOBE_C1 * n.x); }

// Projection of sin(t, w), a hair strand's Kajiya-Kay diffuse kernel around its tangent t: zonal and
// even, so its L1 band vanishes and only pi^2 Y00 remains (the same for every tangent).
const float HAIR_LOBE_C0 = 2.78416400;  // pi^2 * SH_C0
vec4 hairLobe() { return vec4(HAIR_LOBE_C0, 0.0, 0.0, 0.0); }

// Value of the L1 cosine lobe in its own direction (0.75): dividing by it makes a lobe peak at 1.
const float LOBE_PEAK = LOBE_C0 * SH_C0 + LOBE_C1 * SH_C1;
