// The nearest entries of a pixel's run of nodes, sorted by depth, for the camera translucency's sort
// (dsm/oit_sort.comp; the DSM resolve sorts its texels' longer runs in a workgroup per texel:
// dsm/resolve.comp). The includer defines SORT_CAPACITY (entries kept), SORT_SHARED_GROUP (the
// workgroup's invocation count), `nodes` (uvec4: x = depth bits),
// `vec2 sortEntry(uint index, uvec4 node)` (x = depth, y = the payload the includer keeps) and
// `uint sortTieKey(vec2 entry)`, which orders entries of equal depth by what they hold, not by where
// the build's atomics happened to put them: the result does not change from run to run (strands'
// consecutive segments meet at a point of equal depth, so ties are common at the cap).
#define SORT_BATCH 4  // nodes read before any is sorted: their reads in flight together

// The heap, entry k read and written as sorted(k) (after sortNearest: ascending depth), in shared
// memory, entry k of invocation i at k * SORT_SHARED_GROUP + i (consecutive invocations in
// consecutive banks). H100: shared cut the camera sort from 3.51 to 2.85 ms (100k strands) against a
// local array, which spilled to L2.
shared vec2 sortHeap[SORT_CAPACITY * SORT_SHARED_GROUP];
#define sorted(k) sortHeap[(k) * SORT_SHARED_GROUP + gl_LocalInvocationIndex]

// Whether a lies farther than b (depth, then the tie key).
bool sortFarther(vec2 a, vec2 b) { return a.x > b.x || (a.x == b.x && sortTieKey(a) > sortTieKey(b)); }

// While the list is walked, `sorted` is a max-heap of the kept entries (the farthest at the root):
// an entry costs O(log maxCount) moves, where an insertion into a sorted array cost O(maxCount).
// Lists run to hundreds of nodes in dense hair (the H100's dsm.resolve spent most of its time
// shifting). This restores the heap below entry i, of `count` entries.
void heapSiftDown(uint i, uint count) {
    vec2 e = sorted(i);
    for (;;) {
        uint c = 2u * i + 1u;
        if (c >= count) break;
        if (c + 1u < count && sortFarther(sorted(c + 1u), sorted(c))) ++c;
        if (!sortFarther(sorted(c), e)) break;
        sorted(i) = sorted(c);
        i = c;
    }
    sorted(i) = e;
}

// Adds entry e to the heap of `count` entries, which keeps the `maxCount` nearest.
void heapPush(vec2 e, uint maxCount, inout uint count) {
    if (count < maxCount) {  // sift the new entry up from the end
        uint i = count++;
        for (; i > 0u && sortFarther(e, sorted((i - 1u) / 2u)); i = (i - 1u) / 2u) sorted(i) = sorted((i - 1u) / 2u);
        sorted(i) = e;
    } else if (sortFarther(sorted(0), e)) {  // nearer than the farthest kept: it takes the root's place
        sorted(0) = e;
        heapSiftDown(0u, count);
    }
}

// Keeps the `maxCount` (<= SORT_CAPACITY) nearest of the `length` nodes at `start`, sorted ascending;
// `count` receives how many were kept.
void sortNearest(uint start, uint length, uint maxCount, out uint count) {
    count = 0;
    for (uint i = 0; i < length; i += SORT_BATCH) {
        uvec4 node[SORT_BATCH];
        [[unroll]] for (uint k = 0; k < SORT_BATCH; ++k)
            if (i + k < length) node[k] = nodes[start + i + k];
        [[unroll]] for (uint k = 0; k < SORT_BATCH; ++k)
            if (i + k < length) heapPush(sortEntry(start + i + k, node[k]), maxCount, count);
    }
    // Heap sort: the farthest to the end, one by one.
    for (uint end = count; end > 1u; --end) {
        vec2 farthest = sorted(0);
        sorted(0) = sorted(end - 1u);
        sorted(end - 1u) = farthest;
        heapSiftDown(0u, end - 1u);
    }
}
