// The sky behind the geometry: its radiance in world orientation as an equirectangular RGBA16F
// texture (core/sky.h's layout, rotation applied), uploaded through a per-frame staging copy when
// the sky changes; the lighting pass shows it where no surface was drawn. No sun disk: the sun is
// the directional light, which has no size.
#pragma once
#include "core/frame_graph.h"
#include "core/sky.h"
#include "vk/resources.h"

namespace penumbra {

class SkyBackground {
public:
    static constexpr uint32_t kWidth = 256, kHeight = 128;

    explicit SkyBackground(vk::Allocator& alloc);
    // Writes `sky` into frame slot `slot`'s staging copy; the next addTo uploads it.
    void fill(const Sky& sky, uint32_t slot);
    // The texture (after the upload, when one is pending).
    ImageHandle addTo(FrameGraph& graph);

private:
    vk::Image image_;
    vk::BufferRing staging_;
    int pendingSlot_ = -1;
};

}  // namespace penumbra
