// Separable Gaussian blur of moment rows (or columns) through shared memory: each group of
// BLUR_GROUP threads times BLUR_LANES lanes loads its run plus an apron of `radius` texels on
// both sides once, then every thread sums 2 radius + 1 taps from shared memory.
#define BLUR_GROUP 64
#define BLUR_LANES 4
#define BLUR_MAX_RADIUS 32

shared vec4 blurTile[BLUR_LANES][BLUR_GROUP + 2 * BLUR_MAX_RADIUS];

// Tap i of the run sits at blurTile[lane][i]; output texel t of the group at blurTile[lane][t + radius].
vec4 blurTaps(uint lane, int t, int radius) {
    // sigma = radius / 2: the kernel's tails (2 sigma) end at the radius.
    float sigma = max(0.5 * float(radius), 0.5);
    vec4 sum = vec4(0.0);
    float weights = 0.0;
    for (int i = -radius; i <= radius; ++i) {
        float w = exp(-0.5 * float(i * i) / (sigma * sigma));
        sum += w * blurTile[lane][t + radius + i];
        weights += w;
    }
    return sum / weights;
}
