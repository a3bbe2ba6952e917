#include "vk/debug_utils.h"

namespace penumbra::vk {

void DebugUtils::load(VkInstance instance, VkDevice device) {
    if (!instance || !device) return;
    device_ = device;
    beginLabel_ = reinterpret_cast<PFN_vkCmdBeginDebugUtilsLabelEXT>(
        vkGetInstanceProcAddr(instance, "vkCmdBeginDebugUtilsLabelEXT"));
    endLabel_ = reinterpret_cast<PFN_vkCmdEndDebugUtilsLabelEXT>(
        vkGetInstanceProcAddr(instance, "vkCmdEndDebugUtilsLabelEXT"));
    setName_ = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
        vkGetInstanceProcAddr(instance, "vkSetDebugUtilsObjectNameEXT"));
    if (!beginLabel_ || !endLabel_ || !setName_) beginLabel_ = nullptr, endLabel_ = nullptr, setName_ = nullptr;
}

void DebugUtils::beginLabel(VkCommandBuffer cmd, const char* name) const {
    if (!beginLabel_) return;
    VkDebugUtilsLabelEXT label{VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT};
    label.pLabelName = name;
    beginLabel_(cmd, &label);
    ++labelsBegun_;
}

void DebugUtils::endLabel(VkCommandBuffer cmd) const {
    if (endLabel_) endLabel_(cmd);
}

void DebugUtils::name(VkObjectType type, uint64_t handle, const char* text) const {
    if (!setName_ || !handle) return;
    if (!text || !*text) {
        ++unnamedObjects_;
        return;
    }
    VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
    info.objectType = type;
    info.objectHandle = handle;
    info.pObjectName = text;
    setName_(device_, &info);
}

}  // namespace penumbra::vk
