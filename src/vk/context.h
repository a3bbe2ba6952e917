// Vulkan instance, physical-device choice and logical device. Knows nothing about techniques.
#pragma once
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "vk/check.h"
#include "vk/debug_utils.h"

namespace penumbra::vk {

// Pipelines and set layouts of this device, made once per description (vk/pipeline.cpp): a rebuilt
// frame pipeline gets the same objects back instead of compiling them again.
struct PipelineCache;
void destroyPipelineCache(PipelineCache* cache);

struct ContextOptions {
    bool validate = false;     // enable VK_LAYER_KHRONOS_validation; every message is counted
    std::string device;        // "" = best (discrete GPU first, lavapipe last); index or name substring
    bool quiet = false;        // do not echo validation messages to stderr
    bool syncValidation = false;  // with `validate`: also the layer's synchronization validation
    // Command-buffer labels and object names (VK_EXT_debug_utils, where the instance offers it) for
    // capture tools; off: none are recorded, as on an instance without the extension.
    bool debugLabels = true;
    // Presentation (a viewer; headless when unset): the window system's instance extensions, and a
    // test that a queue family of a device can present to it. With it, VK_KHR_swapchain is enabled
    // and a device whose queue cannot present is an error. src/vk stays free of window libraries.
    std::vector<std::string> instanceExtensions;
    std::function<bool(VkInstance, VkPhysicalDevice, uint32_t queueFamily)> presentSupport;
};

// A device that an embedding engine created: penumbra records its own command buffers, submits them to
// `queue` and destroys none of these handles. The instance must be created for Vulkan 1.3; the queue
// family must support graphics, compute and timestamps; the device must have been created with the
// extensions of requiredDeviceExtensions() and every feature of RequiredFeatures (named in the
// Vulkan 1.1/1.2/1.3 feature structs and VkPhysicalDeviceShaderAtomicFloatFeaturesEXT of the chain).
struct ExternalDevice {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t queueFamily = 0;
    const void* enabledFeatureChain = nullptr;                // VkDeviceCreateInfo::pNext as the engine passed it
    const VkPhysicalDeviceFeatures* enabledFeatures = nullptr;  // VkDeviceCreateInfo::pEnabledFeatures, if used
    std::vector<std::string> enabledExtensions;
};

// The feature structs of a device that penumbra reads and enables, chained from `features2`.
// Not copyable: the chain points into the object itself.
struct FeatureChain {
    VkPhysicalDeviceFeatures2 features2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    VkPhysicalDeviceVulkan11Features v11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
    VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceShaderAtomicFloatFeaturesEXT atomicFloat{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_ATOMIC_FLOAT_FEATURES_EXT};
    FeatureChain();
    FeatureChain(const FeatureChain&) = delete;
    FeatureChain& operator=(const FeatureChain&) = delete;
    // With every feature penumbra needs switched on (what its own device is created with).
    static void enableRequired(FeatureChain& chain);
    // The required features that `chain` (copied from a device's creation) leaves off, by name.
    std::vector<std::string> missingRequired();
    // Copies the structs of a VkDeviceCreateInfo::pNext chain that it knows; others are skipped.
    void copyFrom(const void* pNext, const VkPhysicalDeviceFeatures* features10);
};

// The device extensions penumbra needs.
std::vector<const char*> requiredDeviceExtensions();

// The limits that resource sizes are checked against before anything is allocated.
struct DeviceLimits {
    uint64_t storageBufferRange = 0;  // maxStorageBufferRange
    uint64_t allocationSize = 0;      // maxMemoryAllocationSize (Maintenance3)
    uint64_t deviceMemory = 0;        // the largest device-local heap
    uint32_t imageDimension2D = 0;    // maxImageDimension2D
    uint32_t imageArrayLayers = 0;    // maxImageArrayLayers
    // Sampled images one pipeline stage may see across all its sets: the least of
    // maxPerStageDescriptorSampledImages, maxDescriptorSetSampledImages, maxPerStageResources and
    // maxPerStageDescriptorSamplers. The last because Mesa 22.3's lavapipe (32) keeps only that many
    // fragment sampler views across a vkCmdBlitImage recorded after draws (its blitter's save
    // array): with more, the blit overwrites memory and the queue thread crashes.
    uint32_t sampledImagesPerStage = 0;
    uint32_t workGroupCount[3] = {};  // maxComputeWorkGroupCount
};

struct DeviceInfo {
    uint32_t index;
    std::string name;
    std::string type;          // "discrete", "integrated", "virtual", "cpu", "other"
    std::string driver;        // driver name and info
    uint32_t apiVersion;
    std::vector<std::string> missing;  // required features this device lacks (empty = usable)
    DeviceLimits limits;
};

// One required capability and whether a device has it; the CLI's `info` prints these.
struct FeatureCheck {
    std::string name;
    bool present;
};

class Context {
public:
    explicit Context(const ContextOptions& options);
    // Adopts an engine's device after checking it (VulkanError naming everything it lacks); the
    // handles stay the engine's. `options.validate` is ignored: validation is the instance's owner's.
    Context(const ExternalDevice& device, const ContextOptions& options = {});
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    // Devices and their required-feature checks, without creating a logical device.
    static std::vector<DeviceInfo> enumerate(const ContextOptions& options);

    VkInstance instance() const { return instance_; }
    VkPhysicalDevice physicalDevice() const { return physical_; }
    VkDevice device() const { return device_; }
    VkQueue queue() const { return queue_; }
    uint32_t queueFamily() const { return queueFamily_; }
    const VkPhysicalDeviceProperties& properties() const { return properties_; }
    const DeviceInfo& info() const { return info_; }
    float timestampPeriodNs() const { return properties_.limits.timestampPeriod; }
    DeviceLimits limits() const;

    // Validation messages (warnings and errors) seen so far; tests fail when this is non-zero.
    uint32_t validationMessages() const { return validationMessages_.load(); }
    const std::vector<std::string>& validationLog() const { return validationLog_; }

    void waitIdle() const;
    bool presents() const { return bool(options_.presentSupport); }

    // Pipelines created on this device so far (tests: what a settings change costs).
    uint64_t pipelinesCreated() const { return pipelinesCreated_.load(); }
    int64_t pipelinesAlive() const { return pipelinesAlive_.load(); }
    void countPipeline(int delta) {
        if (delta > 0) ++pipelinesCreated_;
        pipelinesAlive_ += delta;
    }
    PipelineCache& pipelineCache();

    // Extension entry point (the loader exports core functions only).
    PFN_vkCmdPushDescriptorSetKHR cmdPushDescriptorSet = nullptr;
    // Labels and object names, live when the instance offers VK_EXT_debug_utils.
    const DebugUtils& debugUtils() const { return debugUtils_; }

private:
    struct InstanceOnly {};
    Context(const ContextOptions& options, InstanceOnly);
    friend VkBool32 debugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT, VkDebugUtilsMessageTypeFlagsEXT,
                                  const VkDebugUtilsMessengerCallbackDataEXT*, void*);
    void createInstance(bool validate);
    void pickDevice(const std::string& selector);
    void createDevice();
    void adopt(const ExternalDevice& device);
    void loadDeviceFunctions();

    ContextOptions options_;
    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    uint32_t queueFamily_ = 0;
    bool ownsHandles_ = true;  // false for an adopted device
    VkPhysicalDeviceProperties properties_{};
    DeviceInfo info_;
    std::atomic<uint32_t> validationMessages_{0};
    std::atomic<uint64_t> pipelinesCreated_{0};
    std::atomic<int64_t> pipelinesAlive_{0};
    std::unique_ptr<PipelineCache, void (*)(PipelineCache*)> pipelineCache_{nullptr, destroyPipelineCache};
    std::vector<std::string> validationLog_;
    bool debugUtilsEnabled_ = false;
    DebugUtils debugUtils_;
};

// The features penumbra needs, checked on one physical device. Names listed in the environment
// variable PENUMBRA_HIDE_FEATURES (comma separated) are reported missing: a test seam for the
// "device without a needed feature" error path, which no real test machine can otherwise reach.
std::vector<FeatureCheck> checkRequiredFeatures(VkPhysicalDevice device);

}  // namespace penumbra::vk
