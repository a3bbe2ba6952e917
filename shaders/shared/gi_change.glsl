// A texel of the image a GI technique publishes as "gi.change" (core/names.h GiChange), from the
// luminance a sample point receives now and received last frame: (change, the larger luminance,
// change^2 / larger, 1 for a measured sample). temporal_gi/change_weight.comp sums them over texels.
vec4 giChangeTexel(float now, float before) {
    const float change = now - before, larger = max(now, before);
    return vec4(change, larger, larger > 0.0 ? change * change / larger : 0.0, 1.0);
}
