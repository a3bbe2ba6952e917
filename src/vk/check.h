// Every Vulkan call that returns a VkResult goes through VK_CHECK: a failure throws VulkanError naming
// the call and the result, which the CLI prints as its one error line.
#pragma once
#include <stdexcept>
#include <string>

#include <vulkan/vulkan.h>

namespace penumbra::vk {

struct VulkanError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

const char* resultName(VkResult r);
[[noreturn]] void throwVkError(const char* call, VkResult r);

}  // namespace penumbra::vk

#define VK_CHECK(call)                                                     \
    do {                                                                   \
        VkResult vk_check_result_ = (call);                                \
        if (vk_check_result_ != VK_SUCCESS)                                \
            ::penumbra::vk::throwVkError(#call, vk_check_result_);         \
    } while (0)
