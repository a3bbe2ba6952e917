// The DSM build's depth buckets (dsm/dsm_insert.glsl, dsm/offsets.comp): a texel's fragments counted
// per bucket, equal slices of the translucent casters' depth range from the light (HairDrawPush.buckets:
// x = nearest depth, y = buckets per unit of depth, z = buckets per texel; outside the range, the end
// slices); only the buckets up to the one whose count reaches the list cap are kept: every fragment
// behind it has at least the cap's number of fragments in front, so none of it could be kept. Exact
// for any range; the range only decides how much is left out.

uint depthBucket(float depth, vec4 buckets) {
    return uint(clamp((depth - buckets.x) * buckets.y, 0.0, buckets.z - 1.0));
}

// How many of the first buckets (counts[0, perTexel)) to keep for a cap of `maxList`; `entries`
// receives the fragments they hold, `count` all the fragments.
uint bucketsKept(uint counts[DSM_MAX_BUCKETS], uint perTexel, uint maxList, out uint entries, out uint count) {
    uint kept = 0u;
    entries = 0u;
    count = 0u;
    for (uint b = 0u; b < perTexel; ++b) {
        count += counts[b];
        if (entries < maxList) {
            entries += counts[b];
            kept = b + 1u;
        }
    }
    return kept;
}
