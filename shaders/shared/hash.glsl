// An integer hash's final mix (avalanche: every input bit flips about half the output bits), shared by
// the shaders that seed sample patterns from integers (rsm/gather.glsl, rsm/flux_draw.comp).
uint hashMix(uint h) {
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    return h ^ (h >> 16);
}
