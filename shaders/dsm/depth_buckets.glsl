// Depth buckets of the translucent casters' builds, the DSM's (texels: dsm/dsm_insert.glsl,
// dsm/offsets.comp) and the camera's (pixels: dsm/oit_insert.glsl, dsm/oit_offsets.comp): a cell's
// fragments counted per bucket, equal slices of the casters' depth range (GpuDepthBuckets; outside the
// range, the end slices); only the buckets up to the one whose count reaches the list cap are kept: every fragment
// behind it has at least the cap's number of fragments in front, so none of it could be kept. Exact
// for any range; the range only decides how much is left out. The includer declares `buckets` (a
// uint per bucket of every cell: counts, then each kept bucket's place in its cell's run) and
// CELL_BUCKETS, the most buckets a cell has (DSM_BUCKETS or OIT_BUCKETS: the arrays' size; the
// builds, which take no arrays, leave it at the larger).
#ifndef CELL_BUCKETS
#define CELL_BUCKETS OIT_BUCKETS
#endif


uint depthBucket(float depth, GpuDepthBuckets buckets) {
    return uint(clamp((depth - buckets.nearest) * buckets.perDepth, 0.0, float(buckets.perCell) - 1.0));
}

// The same slices over the cell's own part of the range, in front of `far` (the camera's pixel: its
// opaque surface, behind which no fragment is kept): over a pixel whose surface lies within the
// casters' depths the buckets are finer, and fewer fragments beyond the cap's bucket are stored.
uint depthBucketBefore(float depth, GpuDepthBuckets buckets, float far) {
    float cells = float(buckets.perCell);
    float span = min(cells / buckets.perDepth, far - buckets.nearest);
    return span > 0.0 ? uint(clamp((depth - buckets.nearest) / span * cells, 0.0, cells - 1.0))
                      : depthBucket(depth, buckets);
}

// How many of the first buckets (counts[0, perTexel)) to keep for a cap of `maxList`; `entries`
// receives the fragments they hold, `count` all the fragments.
uint bucketsKept(uint counts[CELL_BUCKETS], uint perTexel, uint maxList, out uint entries, out uint count) {
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

// Cell `cell`'s counts (zeros for a cell outside the map or image).
void readBucketCounts(uint cell, uint perCell, bool inside, out uint counts[CELL_BUCKETS]) {
    for (uint b = 0u; b < perCell; ++b) counts[b] = 0u;
    if (inside)
        for (uint b = 0u; b < perCell; ++b) counts[b] = buckets[cell * perCell + b];
}

// Replaces cell `cell`'s counts by its buckets' places in its run from `start` on (the first `kept`,
// when `listed`); the rest get DSM_CULLED, so that the build's second step stores nothing of them.
void writeBucketPlaces(uint cell, uint perCell, uint counts[CELL_BUCKETS], uint kept, uint start, bool listed) {
    for (uint b = 0u, at = start; b < perCell; at += counts[b], ++b)
        buckets[cell * perCell + b] = listed && b < kept ? at : DSM_CULLED;
}
