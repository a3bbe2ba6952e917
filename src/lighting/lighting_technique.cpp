#include "lighting/lighting_technique.h"

#include "core/gpu_scene.h"
#include "core/names.h"

namespace penumbra {

CameraTechnique::CameraTechnique(const TechniqueBuild& b)
    : gbuffer_(b.alloc, b.scene.meshes(), b.core.width, b.core.height, b.drawLayout, b.core.cameraPath,
               !b.core.translucency, b.core.computeRaster,
               // opaque hair ribbons are drawn into the depth afterwards (src/dsm)
               !b.core.translucency && !b.scene.scene().strands.empty()) {
    noIds_ = vk::Image(b.alloc, {VK_FORMAT_R32_UINT, 1, 1, 1,
                                 VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, "no-ids"});
    const uint32_t zero = 0;
    b.cmd.uploadImage(noIds_, &zero, sizeof(zero));
}

// The classic G-buffer has no triangle IDs: readers of "gbuffer.ids" (velocity, temporal GI) get a
// 1x1 zero image, published here so that every technique after the camera finds it.
void CameraTechnique::addPasses(const FrameContext& f) {
    gbuffer_.addTo(f.graph, f.slot);
    if (!f.graph.has(names::kGbufferIds)) f.graph.publish(names::kGbufferIds, f.graph.import(noIds_));
}

LightingTechnique::LightingTechnique(const TechniqueBuild& b)
    : board_(b.board), irradiance_(b.alloc, b.core.width, b.core.height), lighting_(b.alloc, b.core.width, b.core.height),
      debugView_(b.alloc.context()), tonemap_(b.alloc, b.core.width, b.core.height) {
    noIndirect_ = vk::Image(b.alloc, {VK_FORMAT_R16G16B16A16_SFLOAT, 1, 1, 1,
                                      VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, "no-indirect"});
    noSky_ = vk::Image(b.alloc, {VK_FORMAT_R16G16B16A16_SFLOAT, 1, 1, 1,
                                 VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, "no-sky"});
    const uint64_t zero = 0;
    b.cmd.uploadImage(noIndirect_, &zero, sizeof(zero));
    b.cmd.uploadImage(noSky_, &zero, sizeof(zero));
    b.board.put(names::kHdrImage, &lighting_.hdr, this);
    b.board.put(names::kLdrImage, &tonemap_.ldr, this);
}

LightingTechnique::~LightingTechnique() { board_.dropOwner(this); }

gpu::TonemapPush LightingTechnique::tonemapParams(const FrameContext& f) const {
    const float depthFar = f.sceneFar;
    switch (f.core.aov) {
        case Aov::Direct:
        case Aov::Final:
        case Aov::Indirect:
        case Aov::LpvSlice:
        case Aov::RsmFlux: return {f.core.exposure, 0.0f, TONEMAP_ACES, 0};
        case Aov::RsmDepth:
        case Aov::RsmNormal:
        case Aov::ShadowMap: return {1.0f, 0.0f, TONEMAP_LINEAR, 0};
        case Aov::GvSlice: return {1.0f, 0.0f, TONEMAP_LINEAR, 0};
        case Aov::Albedo:
        case Aov::Cascade: return {1.0f, 0.0f, TONEMAP_SRGB, 0};
        case Aov::Normal: return {0.5f, 0.5f, TONEMAP_LINEAR, 0};
        case Aov::Depth: return {1.0f / depthFar, 0.0f, TONEMAP_LINEAR, 0};
        case Aov::Shadow:
        case Aov::Transmittance: return {1.0f, 0.0f, TONEMAP_LINEAR, 0};
        case Aov::DsmLists: {
            const float* scale = f.board.get(names::kCountAovScale);
            return {scale ? *scale : 1.0f, 0.0f, TONEMAP_LINEAR, 0};
        }
        case Aov::Velocity: return {1.0f / 32.0f, 0.5f, TONEMAP_LINEAR, 0};  // +-16 pixels
    }
    return {};
}

void LightingTechnique::addPasses(const FrameContext& f) {
    const ImageHandle indirect = irradiance_.addTo(f.graph);
    f.graph.publish(names::kIrradiance, indirect ? indirect : f.graph.import(noIndirect_));
    if (!f.graph.has(names::kSkyIrradiance)) f.graph.publish(names::kSkyIrradiance, f.graph.import(noSky_));
    lighting_.addTo(f.graph);
}

void LightingTechnique::addOutputPasses(const FrameContext& f) {
    debugView_.addTo(f.graph, f.core.aov, f.core.aovLayer);
    tonemap_.addTo(f.graph, tonemapParams(f));
}

}  // namespace penumbra
