#include "dsm/hair_gpu.h"

#include <algorithm>

#include <fmt/format.h>

#include "dsm/bindings.h"

namespace penumbra {
namespace {

// Unit tangent at point i of a polyline: the mean of its segments' directions, so that the ribbons
// of neighbouring segments share their edge at the joint (no cracks, no overlap).
glm::vec3 tangentAt(const glm::vec3* p, uint32_t count, uint32_t i) {
    const glm::vec3 in = i > 0 ? p[i] - p[i - 1] : glm::vec3(0.0f);
    const glm::vec3 out = i + 1 < count ? p[i + 1] - p[i] : glm::vec3(0.0f);
    auto unit = [](const glm::vec3& v) { const float l = glm::length(v); return l > 0.0f ? v / l : v; };
    const glm::vec3 t = unit(in) + unit(out);
    return glm::length(t) > 1e-6f ? glm::normalize(t) : glm::vec3(0, 1, 0);
}

// The 10 bits of v spread to every third bit (a Morton code's one axis).
uint32_t spreadBits(uint32_t v) {
    v = (v | (v << 16)) & 0x030000FFu;
    v = (v | (v << 8)) & 0x0300F00Fu;
    v = (v | (v << 4)) & 0x030C30C3u;
    return (v | (v << 2)) & 0x09249249u;
}

// The indices of `positions` in the order of a Morton curve over their bounds: neighbours in the
// order are neighbours in space.
std::vector<uint32_t> mortonOrder(const std::vector<glm::vec3>& positions) {
    Bounds b;
    for (const glm::vec3& p : positions) b.extend(p);
    const glm::vec3 extent = glm::max(b.max - b.min, glm::vec3(1e-30f));
    std::vector<std::pair<uint32_t, uint32_t>> keys;
    keys.reserve(positions.size());
    for (uint32_t i = 0; i < positions.size(); ++i) {
        const glm::uvec3 q(glm::clamp((positions[i] - b.min) / extent, 0.0f, 1.0f) * 1023.0f);
        keys.push_back({spreadBits(q.x) | spreadBits(q.y) << 1 | spreadBits(q.z) << 2, i});
    }
    std::sort(keys.begin(), keys.end());
    std::vector<uint32_t> order;
    order.reserve(keys.size());
    for (const auto& k : keys) order.push_back(k.second);
    return order;
}

// The ribbon points of the strands in `order` (GPU strand k is scene strand order[k]; their point
// ranges checked).
std::vector<gpu::GpuHairPoint> ribbonPoints(const Scene& scene, const std::vector<uint32_t>& order) {
    std::vector<gpu::GpuHairPoint> out;
    out.reserve(scene.strandPoints.size() + 2 * scene.strands.size());
    for (size_t k = 0; k < order.size(); ++k) {
        const Strand& strand = scene.strands[order[k]];
        const glm::vec3* p = &scene.strandPoints[strand.firstPoint];
        const uint32_t index = uint32_t(k);
        const uint32_t n = strand.pointCount;
        // Zero-width copies of the end points bracket the strand (degenerate strip joins).
        out.push_back({p[0], 0.0f, tangentAt(p, n, 0), index});
        for (uint32_t i = 0; i < n; ++i) out.push_back({p[i], strand.width, tangentAt(p, n, i), index});
        out.push_back({p[n - 1], 0.0f, tangentAt(p, n, n - 1), index});
    }
    return out;
}

}  // namespace

gpu::GpuDepthBuckets depthBuckets(glm::vec2 range, uint32_t count, BuildStep step) {
    const float buckets = float(count);
    return {range.x, range.y > range.x ? buckets / (range.y - range.x) : 0.0f, count,
            step == BuildStep::Count ? 0u : 1u};
}

uint32_t depthBucketCount(vk::Context& ctx, uint64_t cells, uint32_t wanted) {
    uint32_t count = wanted;
    while (count > 1 && cells * 4 * count > ctx.limits().storageBufferRange) count /= 2;
    return count;
}

RibbonView cameraRibbonView(const glm::vec3& eye, float pixelPerDistance) {
    return {eye, 1u, pixelPerDistance, 1u, 1.0f, 0u};
}

RibbonView lightRibbonView(const Light& light, const LightProjection& projection) {
    const bool directional = light.type == LightType::Directional;
    return {directional ? -glm::normalize(light.direction) : light.position, directional ? 0u : 1u,
            projection.texelSize, projection.perspective ? 1u : 0u, 1.0f, 0u};
}

HairGpu::HairGpu(vk::CommandContext& cmd, const Scene& scene) : strandCount_(uint32_t(scene.strands.size())) {
    if (scene.strands.size() >= (size_t(1) << 24))
        throw vk::VulkanError(fmt::format("{} hair strands: at most 2^24 are supported", scene.strands.size()));
    // The strands in the order of their roots along a Morton curve: neighbouring strands, which grow
    // side by side, are drawn one after another, so that the camera build's atomics land nearer one
    // another in memory.
    for (size_t s = 0; s < scene.strands.size(); ++s) {
        const Strand& strand = scene.strands[s];
        if (size_t(strand.firstPoint) + strand.pointCount > scene.strandPoints.size() || strand.pointCount < 2)
            throw vk::VulkanError(fmt::format("hair strand {} has an invalid point range", s));
    }
    std::vector<glm::vec3> roots;
    for (const Strand& s : scene.strands) roots.push_back(scene.strandPoints[s.firstPoint]);
    const std::vector<uint32_t> order = mortonOrder(roots);
    const std::vector<gpu::GpuHairPoint> points = ribbonPoints(scene, order);
    std::vector<gpu::GpuStrand> strands;
    for (uint32_t s : order) strands.push_back({scene.strands[s].color, scene.strands[s].opacity});
    // The drawn points (not the zero-width copies) in the order of a Morton curve (spatialPoints()).
    std::vector<glm::vec3> drawn;
    std::vector<uint32_t> drawnIndex;
    for (uint32_t i = 0; i < points.size(); ++i)
        if (points[i].width > 0.0f) drawn.push_back(points[i].position), drawnIndex.push_back(i);
    std::vector<uint32_t> spatial = mortonOrder(drawn);
    for (uint32_t& i : spatial) i = drawnIndex[i];
    points_ = cmd.createDeviceBuffer(points.data(), points.size() * sizeof(gpu::GpuHairPoint),
                                     VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "hair-points");
    strands_ = cmd.createDeviceBuffer(strands.data(), strands.size() * sizeof(gpu::GpuStrand),
                                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "hair-strands");
    spatialPoints_ = cmd.createDeviceBuffer(spatial.data(), spatial.size() * sizeof(uint32_t),
                                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "hair-spatial-points");
    drawnPointCount_ = uint32_t(spatial.size());
    vertexCount_ = uint32_t(2 * points.size());
}

std::vector<vk::Binding> HairGpu::bindings() {
    return {{HAIR_POINTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}, {HAIR_STRANDS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
}

void HairGpu::declare(PassBuilder& pass) const {
    pass.storageBuffer(HAIR_POINTS, pass.graph().import(points_)).storageBuffer(HAIR_STRANDS, pass.graph().import(strands_));
}

vk::GraphicsDesc HairGpu::pipelineDesc(const std::string& fragmentShader) {
    vk::GraphicsDesc d;
    d.vertexShader = "dsm/hair.vert";
    d.fragmentShader = fragmentShader;
    d.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP;
    d.cullMode = VK_CULL_MODE_NONE;  // a strip alternates its winding; ribbons face the viewer anyway
    return d;
}

void HairGpu::drawRibbons(VkCommandBuffer cmd) const { vkCmdDraw(cmd, vertexCount_, 1, 0, 0); }

vk::ComputeKernel HairGpu::segmentKernel(vk::Context& ctx, const std::string& shader,
                                         const std::vector<vk::Binding>& outputs, uint32_t pushBytes) {
    std::vector<vk::Binding> b{{HAIR_VIEWS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
    for (const vk::Binding& h : bindings()) b.push_back(h);
    b.insert(b.end(), outputs.begin(), outputs.end());
    return vk::ComputeKernel(ctx, shader, b, pushBytes);
}

void HairGpu::dispatch64(VkCommandBuffer cmd, uint32_t invocations) {
    const uint32_t groups = vk::divUp(invocations, 64), x = std::min(groups, 32768u);
    vkCmdDispatch(cmd, x, vk::divUp(groups, x), 1);
}

}  // namespace penumbra
