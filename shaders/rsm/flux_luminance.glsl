// --rsm-far flux: what texels are drawn by, and in what order. Included by rsm/flux_*.comp (which
// declare rsmVpls) and rsm/gather.glsl.

// The luminance of a packed VPL's flux (rsm/resolve.comp's layout), 0 where the texel holds no
// surface. The draws and the gather's weights read the same half floats, so they agree exactly.
float packedFluxLuminance(uvec4 vpl) {
    if (uintBitsToFloat(vpl.x) >= 1.0) return 0.0;
    const vec3 phi = vec3(unpackHalf2x16(vpl.z), unpackHalf2x16(vpl.w).x);
    return max(dot(phi, vec3(0.2126, 0.7152, 0.0722)), 0.0);
}

// Texel `d` along a Hilbert curve over an n x n map (n a power of two). The CDF runs in this order
// so that a draw whose target moves a little (a moving light) moves to a texel nearby: in row order
// it could jump to the next row's start, and the far light would flicker.
uvec2 hilbertTexel(uint n, uint d) {
    uvec2 p = uvec2(0u);
    for (uint s = 1u; s < n; s *= 2u) {
        const uint rx = 1u & (d / 2u), ry = 1u & (d ^ rx);
        if (ry == 0u) {
            if (rx == 1u) p = uvec2(s - 1u) - p;
            p = p.yx;
        }
        p += s * uvec2(rx, ry);
        d /= 4u;
    }
    return p;
}
