#include "vk/check.h"

#include <fmt/format.h>

namespace penumbra::vk {

const char* resultName(VkResult r) {
    switch (r) {
#define PN_CASE(x) case x: return #x;
        PN_CASE(VK_SUCCESS) PN_CASE(VK_NOT_READY) PN_CASE(VK_TIMEOUT) PN_CASE(VK_INCOMPLETE)
        PN_CASE(VK_ERROR_OUT_OF_HOST_MEMORY) PN_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        PN_CASE(VK_ERROR_INITIALIZATION_FAILED) PN_CASE(VK_ERROR_DEVICE_LOST)
        PN_CASE(VK_ERROR_MEMORY_MAP_FAILED) PN_CASE(VK_ERROR_LAYER_NOT_PRESENT)
        PN_CASE(VK_ERROR_EXTENSION_NOT_PRESENT) PN_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
        PN_CASE(VK_ERROR_INCOMPATIBLE_DRIVER) PN_CASE(VK_ERROR_TOO_MANY_OBJECTS)
        PN_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED) PN_CASE(VK_ERROR_FRAGMENTED_POOL)
        PN_CASE(VK_ERROR_OUT_OF_POOL_MEMORY) PN_CASE(VK_ERROR_UNKNOWN)
#undef PN_CASE
        default: return "VK_ERROR_(unlisted)";
    }
}

void throwVkError(const char* call, VkResult r) {
    throw VulkanError(fmt::format("Vulkan call failed: {} returned {} ({})", call, resultName(r),
                                  static_cast<int>(r)));
}

}  // namespace penumbra::vk
