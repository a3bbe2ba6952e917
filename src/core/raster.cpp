#include "core/raster.h"

namespace penumbra {

void beginRaster(VkCommandBuffer cmd, const RasterTarget& t) {
    std::vector<VkRenderingAttachmentInfo> colors;
    for (const ColorTarget& c : t.colors) {
        VkRenderingAttachmentInfo a{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        a.imageView = c.view;
        a.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        a.loadOp = t.load ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_CLEAR;
        a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        a.clearValue.color = c.clear;
        colors.push_back(a);
    }
    VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depth.imageView = t.depth;
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depth.loadOp = t.load ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_CLEAR;
    depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    depth.clearValue.depthStencil = {1.0f, 0};
    VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
    ri.renderArea = {{0, 0}, t.extent};
    ri.layerCount = 1;
    ri.colorAttachmentCount = uint32_t(colors.size());
    ri.pColorAttachments = colors.data();
    ri.pDepthAttachment = t.depth ? &depth : nullptr;
    vkCmdBeginRendering(cmd, &ri);
    VkViewport vp{0, 0, float(t.extent.width), float(t.extent.height), 0, 1};
    VkRect2D sc{{0, 0}, t.extent};
    vkCmdSetViewport(cmd, 0, 1, &vp);
    vkCmdSetScissor(cmd, 0, 1, &sc);
}

}  // namespace penumbra
