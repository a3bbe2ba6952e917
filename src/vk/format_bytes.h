// Bytes per texel of the image formats penumbra allocates: size estimates (the device budget, a
// pass's traffic) take them from the format an image is made with, not from a number beside it.
#pragma once

#include <cstdint>
#include <stdexcept>

#include <vulkan/vulkan.h>

namespace penumbra::vk {

constexpr uint32_t texelBytes(VkFormat format) {
    switch (format) {
    case VK_FORMAT_R8G8B8A8_UNORM:
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_R16G16_SNORM:
    case VK_FORMAT_R16G16_SFLOAT:
    case VK_FORMAT_R32_SFLOAT:
    case VK_FORMAT_R32_UINT:
    case VK_FORMAT_D32_SFLOAT: return 4;
    case VK_FORMAT_R16G16B16A16_SFLOAT:
    case VK_FORMAT_R32G32_SFLOAT:
    case VK_FORMAT_R32G32_UINT: return 8;
    case VK_FORMAT_R32G32B32_SFLOAT: return 12;
    case VK_FORMAT_R32G32B32A32_SFLOAT:
    case VK_FORMAT_R32G32B32A32_UINT: return 16;
    default: throw std::invalid_argument("texelBytes: a format penumbra does not allocate");
    }
}

}  // namespace penumbra::vk
