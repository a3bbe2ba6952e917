#version 460
// Turns a list's item count (the RSM's fallback pixels, the camera translucency's kept layers) into the
// workgroup count of the indirect dispatch that works through it (`receiversPerGroup` items per group,
// laid out over x and y to stay inside maxComputeWorkGroupCount).
layout(local_size_x = 1) in;
layout(set = 0, binding = 0, std430) readonly buffer PixelList { uvec4 header; } list;
layout(set = 0, binding = 1, std430) writeonly buffer Args { uvec4 dispatch; } args;
layout(push_constant) uniform Push { uint receiversPerGroup; };

void main() {
    uint groups = (list.header.x + receiversPerGroup - 1u) / receiversPerGroup;
    uint gx = min(groups, 65535u);
    args.dispatch = uvec4(gx, (groups + gx - 1u) / max(gx, 1u), 1u, 0u);
}
