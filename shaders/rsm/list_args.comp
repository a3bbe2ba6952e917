#version 460
// Turns the fallback-pixel count into the workgroup count of the indirect dispatch that gathers them
// (`receiversPerGroup` pixels per 8x8 group, laid out over x and y to stay inside
// maxComputeWorkGroupCount).
layout(local_size_x = 1) in;
layout(set = 0, binding = 0, std430) readonly buffer PixelList { uvec4 header; } list;
layout(set = 0, binding = 1, std430) writeonly buffer Args { uvec4 dispatch; } args;
layout(push_constant) uniform Push { uint receiversPerGroup; };

void main() {
    uint groups = (list.header.x + receiversPerGroup - 1u) / receiversPerGroup;
    uint gx = min(groups, 65535u);
    args.dispatch = uvec4(gx, (groups + gx - 1u) / max(gx, 1u), 1u, 0u);
}
