// Order-independent injection sums (lpv/inject*.comp, lpv/resolve.comp). Every contribution is turned
// into a 64-bit fixed-point integer before it is added, so that the integer atomics give the same sum
// in whatever order the invocations run: float atomics rounded differently in each order, and the
// volume changed from run to run under a still light.
//
// Light: one colour's coefficients in one cell are scaled by 2^(K - e), where e is the exponent of
// the largest |coefficient| any VPL adds there (below 2^e; lpv/inject_range.comp finds it first) and
// K = 62 - ceil(log2(VPL count)): no VPL adds 2^K or more, and all of them together stay below 2^62.
// A contribution keeps its bits down to 2^-K of the cell's largest one, and the sum is exact (a float
// sum keeps 2^-24 of the running total at every add). e is taken no lower than -64: what lies below
// 2^-64 is kept down to 2^(-64 - K).
// Geometry: a surfel's blocking coefficient lies within +-LOBE_C1 / LOBE_PEAK (1.36), so a fixed
// scale of 2^28 holds the sum of 2^34 surfels in one cell, each to within 2^-29.
// Needs GL_EXT_shader_explicit_arithmetic_types_int64.
const int LPV_LIGHT_SUM_BITS = 62;
const int LPV_LOWEST_EXPONENT = -64;
const int LPV_GEOMETRY_FRACTION_BITS = 28;

// Exactly 2^e, -126 <= e <= 127 (exp2 need not be exact).
float powerOfTwo(int e) { return uintBitsToFloat(uint(e + 127) << 23); }

// K above for `count` contributions at most.
int lightFractionBits(uint count) {
    const int ceilLog2 = count <= 1u ? 0 : findMSB(count - 1u) + 1;
    return LPV_LIGHT_SUM_BITS - ceilLog2;
}

// e above from the float bits of a cell's largest |coefficient| (0 where no VPL landed).
int lightExponent(uint largestBits) {
    int e;
    frexp(uintBitsToFloat(largestBits), e);
    return max(e, LPV_LOWEST_EXPONENT);
}

i64vec4 toFixed(vec4 v, int fractionBits) { return i64vec4(roundEven(v * powerOfTwo(fractionBits))); }
vec4 fromFixed(i64vec4 q, int fractionBits) { return vec4(q) * powerOfTwo(-fractionBits); }
