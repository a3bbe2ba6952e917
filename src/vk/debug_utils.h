// VK_EXT_debug_utils for capture tools (RenderDoc): command-buffer labels and object names. The
// entry points are loaded only when the instance enabled the extension; without it every call
// here does nothing, so a frame records the same commands either way.
#pragma once
#include <atomic>
#include <cstdint>

#include <vulkan/vulkan.h>

namespace penumbra::vk {

class DebugUtils {
public:
    // Loads the entry points through vkGetInstanceProcAddr (null instance: stays off).
    void load(VkInstance instance, VkDevice device);
    bool enabled() const { return beginLabel_ != nullptr; }

    void beginLabel(VkCommandBuffer cmd, const char* name) const;
    void endLabel(VkCommandBuffer cmd) const;
    void name(VkObjectType type, uint64_t handle, const char* name) const;
    template <class Handle> void name(VkObjectType type, Handle handle, const char* text) const {
        name(type, reinterpret_cast<uint64_t>(handle), text);
    }

    // Labels begun so far (tests: one per frame-graph pass), and objects created without a name.
    uint64_t labelsBegun() const { return labelsBegun_.load(); }
    uint64_t unnamedObjects() const { return unnamedObjects_.load(); }

private:
    VkDevice device_ = VK_NULL_HANDLE;
    PFN_vkCmdBeginDebugUtilsLabelEXT beginLabel_ = nullptr;
    PFN_vkCmdEndDebugUtilsLabelEXT endLabel_ = nullptr;
    PFN_vkSetDebugUtilsObjectNameEXT setName_ = nullptr;
    mutable std::atomic<uint64_t> labelsBegun_{0}, unnamedObjects_{0};
};

}  // namespace penumbra::vk
