// A minimal "engine" for the embedding tests: its own VkInstance (validation and synchronization
// validation on, messages counted by its own messenger), a VkDevice created with what
// include/penumbra/penumbra.h documents, a queue, and the commands an engine would record to use
// penumbra's FrameImage (wait on its semaphore, copy it to a host buffer, signal back).
#pragma once
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "penumbra/penumbra.h"

namespace penumbra::test {

#define ENGINE_CHECK(x)                                                                          \
    do {                                                                                         \
        if (VkResult r_ = (x); r_ != VK_SUCCESS) throw std::runtime_error(#x " failed: " + std::to_string(r_)); \
    } while (0)

class Engine {
public:
    Engine() {
        createInstance();
        pickDevice();
        createDevice();
    }
    ~Engine() {
        if (device_) vkDeviceWaitIdle(device_);
        for (VkSemaphore s : semaphores_) vkDestroySemaphore(device_, s, nullptr);
        if (pool_) vkDestroyCommandPool(device_, pool_, nullptr);
        if (device_) vkDestroyDevice(device_, nullptr);
        if (messenger_) destroyMessenger_(instance_, messenger_, nullptr);
        if (instance_) vkDestroyInstance(instance_, nullptr);
    }
    Engine(const Engine&) = delete;
    Engine& operator=(const Engine&) = delete;

    // The device as penumbra adopts it: the features and extensions this engine enabled.
    api::ExternalDevice external() const {
        api::ExternalDevice d;
        d.instance = instance_, d.physicalDevice = physical_, d.device = device_, d.queue = queue_;
        d.queueFamily = queueFamily_;
        d.enabledFeatureChain = &features_.features2;
        d.enabledExtensions.assign(extensions_.begin(), extensions_.end());
        return d;
    }

    uint32_t validationMessages() const { return messages_; }
    const std::string& validationLog() const { return log_; }
    VkDevice device() const { return device_; }

    VkSemaphore newSemaphore() {
        VkSemaphoreCreateInfo ci{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
        VkSemaphore s;
        ENGINE_CHECK(vkCreateSemaphore(device_, &ci, nullptr, &s));
        semaphores_.push_back(s);
        return s;
    }

    // What an engine does with a frame: waits on `image.ready`, copies the image (leaving it in its
    // layout), signals `done` when the copy is finished, and returns the texels.
    std::vector<uint8_t> copyOut(const api::FrameImage& image, VkSemaphore done);

private:
    static VkBool32 onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT, VkDebugUtilsMessageTypeFlagsEXT,
                              const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
        auto* self = static_cast<Engine*>(user);
        ++self->messages_;
        if (self->log_.size() < 4000) self->log_ += std::string(data->pMessage) + "\n";
        return VK_FALSE;
    }
    void createInstance();
    void pickDevice();
    void createDevice();

    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    PFN_vkDestroyDebugUtilsMessengerEXT destroyMessenger_ = nullptr;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    uint32_t queueFamily_ = UINT32_MAX;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    api::RequiredFeatures features_;
    std::vector<const char*> extensions_ = api::requiredDeviceExtensions();
    std::vector<VkSemaphore> semaphores_;
    uint32_t messages_ = 0;
    std::string log_;
};

inline void Engine::createInstance() {
    const char* layer = "VK_LAYER_KHRONOS_validation";
    const char* ext = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "engine";
    app.apiVersion = api::kRequiredApiVersion;
    VkDebugUtilsMessengerCreateInfoEXT dbg{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    dbg.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    dbg.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT;
    dbg.pfnUserCallback = onMessage;
    dbg.pUserData = this;
    const VkValidationFeatureEnableEXT sync = VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
    VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT, &dbg};
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = &sync;
    VkInstanceCreateInfo ci{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO, &features};
    ci.pApplicationInfo = &app;
    ci.enabledLayerCount = 1;
    ci.ppEnabledLayerNames = &layer;
    ci.enabledExtensionCount = 1;
    ci.ppEnabledExtensionNames = &ext;
    ENGINE_CHECK(vkCreateInstance(&ci, nullptr, &instance_));
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
    destroyMessenger_ = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    ENGINE_CHECK(create(instance_, &dbg, nullptr, &messenger_));
}

inline void Engine::pickDevice() {
    uint32_t n = 0;
    ENGINE_CHECK(vkEnumeratePhysicalDevices(instance_, &n, nullptr));
    std::vector<VkPhysicalDevice> devices(n);
    ENGINE_CHECK(vkEnumeratePhysicalDevices(instance_, &n, devices.data()));
    if (devices.empty()) throw std::runtime_error("no Vulkan device");
    physical_ = devices[0];  // the tests pin lavapipe with VK_DRIVER_FILES
    vkGetPhysicalDeviceQueueFamilyProperties(physical_, &n, nullptr);
    std::vector<VkQueueFamilyProperties> families(n);
    vkGetPhysicalDeviceQueueFamilyProperties(physical_, &n, families.data());
    const VkQueueFlags need = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    for (uint32_t i = 0; i < n && queueFamily_ == UINT32_MAX; ++i)
        if ((families[i].queueFlags & need) == need && families[i].timestampValidBits > 0) queueFamily_ = i;
    if (queueFamily_ == UINT32_MAX) throw std::runtime_error("no graphics+compute queue with timestamps");
}

inline void Engine::createDevice() {
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo q{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    q.queueFamilyIndex = queueFamily_;
    q.queueCount = 1;
    q.pQueuePriorities = &priority;
    VkDeviceCreateInfo ci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &features_.features2};
    ci.queueCreateInfoCount = 1;
    ci.pQueueCreateInfos = &q;
    ci.enabledExtensionCount = uint32_t(extensions_.size());
    ci.ppEnabledExtensionNames = extensions_.data();
    ENGINE_CHECK(vkCreateDevice(physical_, &ci, nullptr, &device_));
    vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
    VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool.queueFamilyIndex = queueFamily_;
    ENGINE_CHECK(vkCreateCommandPool(device_, &pool, nullptr, &pool_));
}

inline uint32_t hostMemoryType(VkPhysicalDevice physical, uint32_t bits) {
    VkPhysicalDeviceMemoryProperties mem;
    vkGetPhysicalDeviceMemoryProperties(physical, &mem);
    const VkMemoryPropertyFlags need = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    for (uint32_t i = 0; i < mem.memoryTypeCount; ++i)
        if ((bits & (1u << i)) && (mem.memoryTypes[i].propertyFlags & need) == need) return i;
    throw std::runtime_error("no host-visible memory");
}

// A host-visible buffer the engine copies an image into.
struct HostBuffer {
    VkDevice device;
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    HostBuffer(VkDevice d, VkPhysicalDevice physical, VkDeviceSize bytes) : device(d) {
        VkBufferCreateInfo bi{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
        bi.size = bytes;
        bi.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
        ENGINE_CHECK(vkCreateBuffer(device, &bi, nullptr, &buffer));
        VkMemoryRequirements req;
        vkGetBufferMemoryRequirements(device, buffer, &req);
        VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        ai.allocationSize = req.size;
        ai.memoryTypeIndex = hostMemoryType(physical, req.memoryTypeBits);
        ENGINE_CHECK(vkAllocateMemory(device, &ai, nullptr, &memory));
        ENGINE_CHECK(vkBindBufferMemory(device, buffer, memory, 0));
    }
    ~HostBuffer() {
        vkDestroyBuffer(device, buffer, nullptr);
        vkFreeMemory(device, memory, nullptr);
    }
    std::vector<uint8_t> read(VkDeviceSize bytes) const {
        void* mapped = nullptr;
        ENGINE_CHECK(vkMapMemory(device, memory, 0, bytes, 0, &mapped));
        std::vector<uint8_t> out(static_cast<const uint8_t*>(mapped), static_cast<const uint8_t*>(mapped) + bytes);
        vkUnmapMemory(device, memory);
        return out;
    }
};

inline std::vector<uint8_t> Engine::copyOut(const api::FrameImage& image, VkSemaphore done) {
    const VkDeviceSize bytes = VkDeviceSize(image.width) * image.height * 4;
    const HostBuffer host(device_, physical_, bytes);
    const VkBuffer buffer = host.buffer;
    VkCommandBufferAllocateInfo ci{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ci.commandPool = pool_;
    ci.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ci.commandBufferCount = 1;
    VkCommandBuffer cmd;
    ENGINE_CHECK(vkAllocateCommandBuffers(device_, &ci, &cmd));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    ENGINE_CHECK(vkBeginCommandBuffer(cmd, &begin));
    auto layout = [&](VkImageLayout from, VkImageLayout to, VkPipelineStageFlags2 srcStage, VkPipelineStageFlags2 dstStage,
                      VkAccessFlags2 dstAccess) {
        VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
        b.srcStageMask = srcStage, b.dstStageMask = dstStage, b.dstAccessMask = dstAccess;
        b.oldLayout = from, b.newLayout = to;
        b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.image = image.image;
        b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        dep.imageMemoryBarrierCount = 1;
        dep.pImageMemoryBarriers = &b;
        vkCmdPipelineBarrier2(cmd, &dep);
    };
    layout(image.layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
           VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {image.width, image.height, 1};
    vkCmdCopyImageToBuffer(cmd, image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer, 1, &region);
    layout(VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image.layout, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
           VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_NONE);
    VkMemoryBarrier2 toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    toHost.srcStageMask = VK_PIPELINE_STAGE_2_TRANSFER_BIT, toHost.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    toHost.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT, toHost.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.memoryBarrierCount = 1;
    dep.pMemoryBarriers = &toHost;
    vkCmdPipelineBarrier2(cmd, &dep);
    ENGINE_CHECK(vkEndCommandBuffer(cmd));

    VkCommandBufferSubmitInfo cb{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
    cb.commandBuffer = cmd;
    VkSemaphoreSubmitInfo wait{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    wait.semaphore = image.ready;
    wait.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    VkSemaphoreSubmitInfo signal{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    signal.semaphore = done;
    signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    VkSubmitInfo2 si{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    si.waitSemaphoreInfoCount = 1;
    si.pWaitSemaphoreInfos = &wait;
    si.commandBufferInfoCount = 1;
    si.pCommandBufferInfos = &cb;
    si.signalSemaphoreInfoCount = done ? 1 : 0;
    si.pSignalSemaphoreInfos = &signal;
    VkFenceCreateInfo fi{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence;
    ENGINE_CHECK(vkCreateFence(device_, &fi, nullptr, &fence));
    ENGINE_CHECK(vkQueueSubmit2(queue_, 1, &si, fence));
    ENGINE_CHECK(vkWaitForFences(device_, 1, &fence, VK_TRUE, UINT64_MAX));
    vkDestroyFence(device_, fence, nullptr);
    vkFreeCommandBuffers(device_, pool_, 1, &cmd);
    return host.read(bytes);
}

}  // namespace penumbra::test
