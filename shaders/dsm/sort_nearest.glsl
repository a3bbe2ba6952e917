// The nearest entries of a linked list, sorted by depth: shared by the DSM resolve (light-space
// lists) and the camera translucency resolve (per-pixel lists). The includer defines
// SORT_CAPACITY (size of the local array), `nodes` (uvec4: x = depth bits, z = next) and
// `vec2 sortEntry(uint node)` (x = depth, y = the payload the includer keeps).

vec2 sorted[SORT_CAPACITY];  // ascending x

// Insertion into `sorted` while walking the list from `head`: O(length x maxCount), the lists being
// short. Keeps the `maxCount` (<= SORT_CAPACITY) nearest; `guard` bounds a corrupt list. Returns the
// list's full length; `count` receives how many entries were kept.
uint sortNearest(uint head, uint maxCount, uint guard, out uint count) {
    count = 0;
    uint length = 0;
    for (uint n = head; n != DSM_NONE && length < guard; n = nodes[n].z, ++length) {
        vec2 e = sortEntry(n);
        if (count == maxCount && e.x >= sorted[count - 1].x) continue;  // behind every kept entry
        uint i = min(count, maxCount - 1);  // when full, the farthest kept entry gives way
        count = min(count + 1, maxCount);
        for (; i > 0 && sorted[i - 1].x > e.x; --i) sorted[i] = sorted[i - 1];
        sorted[i] = e;
    }
    return length;
}
