#include "view/overlays.h"

#include <array>

#include <imgui.h>

#include "core/light_space.h"
#include "core/names.h"
#include "lpv/lpv_names.h"

namespace penumbra::view {
namespace {

// The layer colours of the cascade AOV (docs/viewer.md): cascade 0 red, 1 green, 2 blue, 3 yellow, ...
const std::array<ImU32, 8> kLayerColors = {IM_COL32(255, 64, 64, 255),  IM_COL32(64, 255, 64, 255),
                                           IM_COL32(80, 120, 255, 255), IM_COL32(255, 255, 64, 255),
                                           IM_COL32(255, 64, 255, 255), IM_COL32(64, 255, 255, 255),
                                           IM_COL32(255, 160, 32, 255), IM_COL32(160, 160, 160, 255)};

// The 12 edges of a box given by its 8 corners (bit 0: x, bit 1: y, bit 2: z).
constexpr std::array<std::pair<int, int>, 12> kEdges = {{{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                                         {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}}};

struct Projector {
    glm::mat4 viewProj;
    float width, height;
    // A world line on screen, clipped against the camera's near plane.
    void line(glm::vec3 a, glm::vec3 b, ImU32 color) const {
        glm::vec4 pa = viewProj * glm::vec4(a, 1.0f), pb = viewProj * glm::vec4(b, 1.0f);
        const float eps = 1e-4f;
        if (pa.w < eps && pb.w < eps) return;
        if (pa.w < eps) pa = glm::mix(pb, pa, (pb.w - eps) / (pb.w - pa.w));
        if (pb.w < eps) pb = glm::mix(pa, pb, (pa.w - eps) / (pa.w - pb.w));
        auto screen = [&](const glm::vec4& p) {
            return ImVec2((p.x / p.w * 0.5f + 0.5f) * width, (p.y / p.w * 0.5f + 0.5f) * height);
        };
        ImGui::GetBackgroundDrawList()->AddLine(screen(pa), screen(pb), color, 1.5f);
    }
    void box(const std::array<glm::vec3, 8>& corners, ImU32 color) const {
        for (const auto& [i, j] : kEdges) line(corners[i], corners[j], color);
    }
};

void shadowFrusta(Renderer& renderer, const Projector& p) {
    const ShadowLayers* layers = renderer.blackboard().get(names::kShadowLayers);
    if (!layers) return;
    for (const ShadowLayerView& layer : layers->layers) {
        if (layer.projection.paraboloid) continue;  // no matrix: a hemisphere, not a frustum
        const glm::mat4 inv = glm::inverse(layer.projection.viewProj);
        std::array<glm::vec3, 8> corners;
        for (int c = 0; c < 8; ++c) {
            const glm::vec4 w = inv * glm::vec4((c & 1) ? 1.0f : -1.0f, (c & 2) ? 1.0f : -1.0f, (c & 4) ? 1.0f : 0.0f, 1.0f);
            corners[c] = glm::vec3(w) / w.w;
        }
        p.box(corners, kLayerColors[layer.index % kLayerColors.size()]);
    }
}

void lpvBoxes(Renderer& renderer, const Projector& p) {
    const LpvCascadeBoxes* cascades = renderer.blackboard().get(names::kLpvCascadeBoxes);
    if (!cascades) return;
    for (size_t k = 0; k < cascades->boxes.size(); ++k) {
        const LpvCascadeBoxes::Box& b = cascades->boxes[k];
        std::array<glm::vec3, 8> corners;
        for (int i = 0; i < 8; ++i)
            corners[i] = b.origin + b.side * glm::vec3(i & 1 ? 1.0f : 0.0f, i & 2 ? 1.0f : 0.0f, i & 4 ? 1.0f : 0.0f);
        p.box(corners, kLayerColors[k % kLayerColors.size()]);
    }
}

}  // namespace

void drawOverlays(const OverlayOptions& options, Renderer& renderer, const Camera& camera, uint32_t width,
                  uint32_t height) {
    if (!options.shadowFrusta && !options.lpvBoxes) return;
    const float zfar = renderer.frameUniforms().farPlane;  // the far plane the renderer used
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const Projector p{cameraViewProj(camera, float(width) / float(height), zfar), display.x, display.y};
    if (options.shadowFrusta) shadowFrusta(renderer, p);
    if (options.lpvBoxes) lpvBoxes(renderer, p);
}

}  // namespace penumbra::view
