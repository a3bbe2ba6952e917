#include "lighting/gpu_sky.h"

#include <cmath>
#include <vector>

#include <glm/gtc/packing.hpp>

#include "core/names.h"

namespace penumbra {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr float kHalfMax = 65000.0f;  // the background's half floats: brighter radiance is clamped

// The background's texel (r, c) looks along the layout's direction at its mid polar angle.
glm::vec3 backgroundDirection(uint32_t r, uint32_t c) {
    const double theta = kPi * (r + 0.5) / GpuSky::kHeight;
    const double phi = skyAzimuth(c + 0.5, GpuSky::kWidth);
    return glm::vec3(std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi));
}

glm::vec2 cosSin(double angle) { return glm::vec2(std::cos(angle), std::sin(angle)); }
glm::vec2 sinCos(double angle) { return glm::vec2(std::sin(angle), std::cos(angle)); }
glm::vec2 cosSinOfCosine(double c) { return glm::vec2(c, std::sqrt(std::max(0.0, 1.0 - c * c))); }

// The layout's sample points in double precision (core/sky.h), rounded once to single.
struct SkyLayout {
    gpu::SkyLayoutRow rows[GpuSky::kHeight];
    gpu::SkyLayoutColumn columns[GpuSky::kWidth];
};

SkyLayout makeLayout() {
    SkyLayout layout{};
    const double texelPhi = 2.0 * kPi / GpuSky::kWidth;
    for (uint32_t r = 0; r < GpuSky::kHeight; ++r) {
        const SkyRowPoints p = skyRowPoints(r, GpuSky::kHeight);
        gpu::SkyLayoutRow& row = layout.rows[r];
        row.tableCentre = cosSinOfCosine(p.cosCentre);
        row.backgroundCentre = cosSin(kPi * (r + 0.5) / GpuSky::kHeight);
        row.gauss0 = cosSinOfCosine(p.cosGauss[0]);
        row.gauss1 = cosSinOfCosine(p.cosGauss[1]);
        row.subSolidAngle = float(p.cosSpan / kSkyGaussOffsets.size() * texelPhi / kSkyGaussOffsets.size());
    }
    for (uint32_t c = 0; c < GpuSky::kWidth; ++c) {
        gpu::SkyLayoutColumn& column = layout.columns[c];
        column.centre = sinCos(skyAzimuth(c + 0.5, GpuSky::kWidth));
        column.gauss0 = sinCos(skyAzimuth(c + kSkyGaussOffsets[0], GpuSky::kWidth));
        column.gauss1 = sinCos(skyAzimuth(c + kSkyGaussOffsets[1], GpuSky::kWidth));
    }
    return layout;
}

gpu::SkyAnalyticPush analyticPush(const AnalyticSkyModel& m) {
    gpu::SkyAnalyticPush p{};
    for (int k = 0; k < 3; ++k) {
        const AnalyticSkyModel::Perez& q = m.perez[k];
        p.a[k] = float(q.a), p.b[k] = float(q.b), p.c[k] = float(q.c), p.d[k] = float(q.d), p.e[k] = float(q.e);
        p.zenithScale[k] = float(m.zenith[k]);
    }
    p.zenithScale.w = float(m.scale);
    p.toSun = glm::vec4(m.toSun, 0.0f);
    return p;
}

}  // namespace

GpuSky::GpuSky(vk::Allocator& alloc, vk::CommandContext& cmd)
    : analytic_(alloc.context(), "sky/analytic.comp",
                {{SKY_ANALYTIC_LAYOUT, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                 {SKY_ANALYTIC_BACKGROUND, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                 {SKY_ANALYTIC_TABLE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                 {SKY_ANALYTIC_ROW_SH, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}},
                sizeof(gpu::SkyAnalyticPush)),
      shSum_(alloc.context(), "sky/sh_sum.comp",
             {{SKY_SH_SUM_ROWS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}, {SKY_SH_SUM_OUT, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}},
             0) {
    const VkImageUsageFlags read = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    background_ = vk::Image(alloc, {VK_FORMAT_R16G16B16A16_SFLOAT, kWidth, kHeight, 1,
                                    read | VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                    "sky.background"});
    table_ = vk::Image(alloc, {VK_FORMAT_R32G32B32A32_SFLOAT, kWidth, kHeight, 1,
                               VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, "sky.table"});
    const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    rowSh_ = vk::Buffer(alloc, VkDeviceSize(kHeight) * SKY_SH_COEFFICIENTS * sizeof(glm::vec4), storage, false,
                        "sky.row-sh");
    sh_ = vk::Buffer(alloc, SKY_SH_COEFFICIENTS * sizeof(glm::vec4),
                     storage | VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, false, "sky.sh");
    staging_ = vk::BufferRing(alloc, VkDeviceSize(kWidth) * kHeight * 8, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                              "sky.background-staging");
    const SkyLayout layout = makeLayout();
    layout_ = cmd.createDeviceBuffer(&layout, sizeof(layout), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "sky.layout");
}

// Radiance at the background's texel centres, in world directions, and the table's SH.
void GpuSky::set(const Sky& sky, uint32_t slot) {
    std::vector<uint16_t> texels(size_t(kWidth) * kHeight * 4);
    for (uint32_t r = 0; r < kHeight; ++r)
        for (uint32_t c = 0; c < kWidth; ++c) {
            const glm::vec3 l = glm::min(sky.radiance(backgroundDirection(r, c)), glm::vec3(kHalfMax));
            uint16_t* t = &texels[(size_t(r) * kWidth + c) * 4];
            t[0] = glm::packHalf1x16(l.r), t[1] = glm::packHalf1x16(l.g), t[2] = glm::packHalf1x16(l.b);
            t[3] = glm::packHalf1x16(1.0f);
        }
    staging_.select(slot);
    staging_.write(texels.data(), texels.size() * sizeof(uint16_t));
    const std::array<glm::dvec3, 9> sh = sky.sh();
    for (size_t k = 0; k < sh.size(); ++k) uploadSh_[k] = glm::vec4(glm::vec3(sh[k]), 0.0f);
    pending_ = Pending::Upload;
    pendingSlot_ = slot;
}

void GpuSky::set(const AnalyticSkyModel& model) {
    analyticPush_ = analyticPush(model);
    pending_ = Pending::Analytic;
}

ImageHandle GpuSky::addTo(FrameGraph& graph) {
    const ImageHandle radiance = graph.import(background_);
    const BufferHandle sh = graph.import(sh_);
    graph.publish(names::kSkySh, sh);
    graph.publish(names::kSkyRadiance, radiance);
    if (pending_ == Pending::Upload) addUpload(graph, radiance, sh);
    if (pending_ == Pending::Analytic) addAnalytic(graph, radiance, sh);
    pending_ = Pending::None;
    return radiance;
}

void GpuSky::addUpload(FrameGraph& graph, ImageHandle skyImage, BufferHandle sh) {
    const BufferHandle source = graph.import(staging_.at(pendingSlot_));
    graph.pass("sky.upload", PassKind::Transfer)
        .use(source, Use::TransferSrc)
        .use(skyImage, Use::TransferDst)
        .use(sh, Use::TransferDst)
        .record([source, skyImage, sh, coefficients = uploadSh_](PassContext& c) {
            VkBufferImageCopy region{};
            region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.imageExtent = {kWidth, kHeight, 1};
            vkCmdCopyBufferToImage(c.cmd, c.buffer(source).handle(), c.image(skyImage).handle(),
                                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
            vkCmdUpdateBuffer(c.cmd, c.buffer(sh).handle(), 0, sizeof(coefficients), coefficients.data());
        });
}

void GpuSky::addAnalytic(FrameGraph& graph, ImageHandle skyImage, BufferHandle sh) {
    const BufferHandle rows = graph.import(rowSh_);
    graph.pass("sky.analytic")
        .pipeline(analytic_.pipeline)
        .storageBuffer(SKY_ANALYTIC_LAYOUT, graph.import(layout_))
        .storageImage(SKY_ANALYTIC_BACKGROUND, skyImage)
        .storageImage(SKY_ANALYTIC_TABLE, graph.import(table_))
        .storageBuffer(SKY_ANALYTIC_ROW_SH, rows, Use::StorageWrite)
        .record([this, push = analyticPush_](PassContext& c) {
            analytic_.pipeline.push(c.cmd, push);
            vkCmdDispatch(c.cmd, 1, kHeight, 1);
        });
    graph.pass("sky.sh")
        .pipeline(shSum_.pipeline)
        .storageBuffer(SKY_SH_SUM_ROWS, rows)
        .storageBuffer(SKY_SH_SUM_OUT, sh, Use::StorageWrite)
        .record([](PassContext& c) { vkCmdDispatch(c.cmd, 1, 1, 1); });
}

}  // namespace penumbra
