#include "vk/context.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <sstream>

#include <fmt/format.h>

namespace penumbra::vk {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

const char* typeName(VkPhysicalDeviceType t) {
    switch (t) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete";
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated";
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual";
        case VK_PHYSICAL_DEVICE_TYPE_CPU: return "cpu";
        default: return "other";
    }
}

// Higher is better: discrete GPUs first, software rasterizers last.
int typeRank(VkPhysicalDeviceType t) {
    switch (t) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 4;
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 3;
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
        case VK_PHYSICAL_DEVICE_TYPE_CPU: return 1;
        default: return 0;
    }
}

bool hidden(const std::string& name) {
    const char* env = std::getenv("PENUMBRA_HIDE_FEATURES");
    if (!env) return false;
    std::stringstream ss(env);
    for (std::string item; std::getline(ss, item, ',');)
        if (item == name) return true;
    return false;
}

bool instanceOffers(const char* name) {
    uint32_t n = 0;
    VK_CHECK(vkEnumerateInstanceExtensionProperties(nullptr, &n, nullptr));
    std::vector<VkExtensionProperties> exts(n);
    VK_CHECK(vkEnumerateInstanceExtensionProperties(nullptr, &n, exts.data()));
    return std::any_of(exts.begin(), exts.end(),
                       [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

bool hasExtension(VkPhysicalDevice device, const char* name) {
    uint32_t n = 0;
    VK_CHECK(vkEnumerateDeviceExtensionProperties(device, nullptr, &n, nullptr));
    std::vector<VkExtensionProperties> exts(n);
    VK_CHECK(vkEnumerateDeviceExtensionProperties(device, nullptr, &n, exts.data()));
    return std::any_of(exts.begin(), exts.end(),
                       [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

uint32_t findQueueFamily(VkPhysicalDevice device) {
    uint32_t n = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &n, nullptr);
    std::vector<VkQueueFamilyProperties> families(n);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &n, families.data());
    for (uint32_t i = 0; i < n; ++i) {
        const VkQueueFlags need = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
        if ((families[i].queueFlags & need) == need && families[i].timestampValidBits > 0) return i;
    }
    return UINT32_MAX;
}

std::vector<VkPhysicalDevice> physicalDevices(VkInstance instance) {
    uint32_t n = 0;
    VK_CHECK(vkEnumeratePhysicalDevices(instance, &n, nullptr));
    std::vector<VkPhysicalDevice> devices(n);
    VK_CHECK(vkEnumeratePhysicalDevices(instance, &n, devices.data()));
    return devices;
}

DeviceLimits deviceLimits(VkPhysicalDevice physical) {
    VkPhysicalDeviceMaintenance3Properties m3{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES};
    VkPhysicalDeviceProperties2 p{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &m3};
    vkGetPhysicalDeviceProperties2(physical, &p);
    VkPhysicalDeviceMemoryProperties mem;
    vkGetPhysicalDeviceMemoryProperties(physical, &mem);
    DeviceLimits d;
    for (uint32_t i = 0; i < mem.memoryHeapCount; ++i)
        if (mem.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
            d.deviceMemory = std::max<uint64_t>(d.deviceMemory, mem.memoryHeaps[i].size);
    const VkPhysicalDeviceLimits& l = p.properties.limits;
    d.storageBufferRange = l.maxStorageBufferRange;
    d.allocationSize = m3.maxMemoryAllocationSize;
    d.imageDimension2D = l.maxImageDimension2D;
    d.imageArrayLayers = l.maxImageArrayLayers;
    d.sampledImagesPerStage = std::min({l.maxPerStageDescriptorSampledImages, l.maxDescriptorSetSampledImages,
                                        l.maxPerStageResources, l.maxPerStageDescriptorSamplers});
    for (int i = 0; i < 3; ++i) d.workGroupCount[i] = l.maxComputeWorkGroupCount[i];
    return d;
}

DeviceInfo describe(VkPhysicalDevice device, uint32_t index) {
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &driver};
    vkGetPhysicalDeviceProperties2(device, &props);
    DeviceInfo info{index, props.properties.deviceName, typeName(props.properties.deviceType),
                    fmt::format("{} {}", driver.driverName, driver.driverInfo), props.properties.apiVersion, {}};
    for (const FeatureCheck& f : checkRequiredFeatures(device))
        if (!f.present) info.missing.push_back(f.name);
    info.limits = deviceLimits(device);
    return info;
}

// Every device feature penumbra enables, by the name checkRequiredFeatures reports it under: one list
// for creating its own device and for checking an engine's.
struct RequiredFeature {
    const char* name;
    VkBool32& (*flag)(FeatureChain&);
};
constexpr RequiredFeature kRequiredFeatures[] = {
    {"dynamicRendering", [](FeatureChain& c) -> VkBool32& { return c.v13.dynamicRendering; }},
    {"synchronization2", [](FeatureChain& c) -> VkBool32& { return c.v13.synchronization2; }},
    // glslc's Vulkan 1.3 SPIR-V uses LocalSizeId.
    {"maintenance4", [](FeatureChain& c) -> VkBool32& { return c.v13.maintenance4; }},
    {"hostQueryReset", [](FeatureChain& c) -> VkBool32& { return c.v12.hostQueryReset; }},
    {"shaderOutputLayer", [](FeatureChain& c) -> VkBool32& { return c.v12.shaderOutputLayer; }},
    {"shaderBufferInt64Atomics", [](FeatureChain& c) -> VkBool32& { return c.v12.shaderBufferInt64Atomics; }},
    {"shaderDrawParameters", [](FeatureChain& c) -> VkBool32& { return c.v11.shaderDrawParameters; }},
    {"fragmentStoresAndAtomics", [](FeatureChain& c) -> VkBool32& { return c.features2.features.fragmentStoresAndAtomics; }},
    {"tessellationShader", [](FeatureChain& c) -> VkBool32& { return c.features2.features.tessellationShader; }},
    {"shaderClipDistance", [](FeatureChain& c) -> VkBool32& { return c.features2.features.shaderClipDistance; }},
    {"shaderInt64", [](FeatureChain& c) -> VkBool32& { return c.features2.features.shaderInt64; }},
    {"geometryShader", [](FeatureChain& c) -> VkBool32& { return c.features2.features.geometryShader; }},
    {"shaderStorageImageExtendedFormats",
     [](FeatureChain& c) -> VkBool32& { return c.features2.features.shaderStorageImageExtendedFormats; }},
    {"shaderBufferFloat32AtomicAdd (VK_EXT_shader_atomic_float)",
     [](FeatureChain& c) -> VkBool32& { return c.atomicFloat.shaderBufferFloat32AtomicAdd; }},
};

// Copies `from` over `to` but keeps `to`'s place in its own chain.
template <class T>
void copyStruct(T& to, const void* from) {
    void* next = to.pNext;
    std::memcpy(&to, from, sizeof(T));
    to.pNext = next;
}

}  // namespace

FeatureChain::FeatureChain() {
    features2.pNext = &v11;
    v11.pNext = &v12;
    v12.pNext = &v13;
    v13.pNext = &atomicFloat;
}

void FeatureChain::enableRequired(FeatureChain& chain) {
    for (const RequiredFeature& f : kRequiredFeatures) f.flag(chain) = VK_TRUE;
}

std::vector<std::string> FeatureChain::missingRequired() {
    std::vector<std::string> missing;
    for (const RequiredFeature& f : kRequiredFeatures)
        if (!f.flag(*this)) missing.push_back(f.name);
    return missing;
}

void FeatureChain::copyFrom(const void* pNext, const VkPhysicalDeviceFeatures* features10) {
    if (features10) features2.features = *features10;
    for (auto* s = static_cast<const VkBaseInStructure*>(pNext); s; s = s->pNext) {
        switch (s->sType) {
            case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2: copyStruct(features2, s); break;
            case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES: copyStruct(v11, s); break;
            case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES: copyStruct(v12, s); break;
            case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES: copyStruct(v13, s); break;
            case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_ATOMIC_FLOAT_FEATURES_EXT: copyStruct(atomicFloat, s); break;
            default: break;
        }
    }
}

std::vector<const char*> requiredDeviceExtensions() {
    return {VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME, VK_EXT_SHADER_ATOMIC_FLOAT_EXTENSION_NAME};
}

std::vector<FeatureCheck> checkRequiredFeatures(VkPhysicalDevice device) {
    const bool hasAtomicFloat = hasExtension(device, VK_EXT_SHADER_ATOMIC_FLOAT_EXTENSION_NAME);
    VkPhysicalDeviceShaderAtomicFloatFeaturesEXT af{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_ATOMIC_FLOAT_FEATURES_EXT};
    VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES,
                                         hasAtomicFloat ? &af : nullptr};
    VkPhysicalDeviceVulkan12Features f12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &f13};
    VkPhysicalDeviceVulkan11Features f11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES, &f12};
    VkPhysicalDeviceFeatures2 f{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &f11};
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(device, &props);
    const bool is13 = props.apiVersion >= VK_API_VERSION_1_3;
    if (is13) vkGetPhysicalDeviceFeatures2(device, &f);
    VkPhysicalDeviceVulkan11Properties p11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_PROPERTIES};
    VkPhysicalDeviceProperties2 props2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &p11};
    if (is13) vkGetPhysicalDeviceProperties2(device, &props2);
    const VkSubgroupFeatureFlags subgroupNeed =
        VK_SUBGROUP_FEATURE_BASIC_BIT | VK_SUBGROUP_FEATURE_BALLOT_BIT | VK_SUBGROUP_FEATURE_ARITHMETIC_BIT;
    VkFormatProperties depth;
    vkGetPhysicalDeviceFormatProperties(device, VK_FORMAT_D32_SFLOAT, &depth);
    const VkFormatFeatureFlags depthNeed =
        VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT;

    std::vector<FeatureCheck> checks = {
        {"Vulkan 1.3", is13},
        {"dynamicRendering", is13 && f13.dynamicRendering},
        {"synchronization2", is13 && f13.synchronization2},
        {"hostQueryReset", is13 && f12.hostQueryReset},
        {"maintenance4", is13 && f13.maintenance4},
        {"VK_KHR_push_descriptor", hasExtension(device, VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME)},
        {"timestampComputeAndGraphics", props.limits.timestampComputeAndGraphics == VK_TRUE},
        {"graphics+compute queue with timestamps", findQueueFamily(device) != UINT32_MAX},
        {"D32_SFLOAT depth attachment and sampled", (depth.optimalTilingFeatures & depthNeed) == depthNeed},
        {"fragmentStoresAndAtomics", is13 && f.features.fragmentStoresAndAtomics},
        // Shadow maps (src/shadow): all layers of a light in one instanced draw (gl_Layer written by
        // the vertex or tessellation stage); dual-paraboloid maps tessellate and clip at the rim.
        {"shaderOutputLayer", is13 && f12.shaderOutputLayer},
        // Draws name their scene instance through firstInstance (gl_BaseInstance).
        {"shaderDrawParameters", is13 && f11.shaderDrawParameters},
        {"tessellationShader", is13 && f.features.tessellationShader},
        {"shaderClipDistance", is13 && f.features.shaderClipDistance},
        // The compute rasterizer's edge functions are exact 64-bit integers (src/raster).
        {"shaderInt64", is13 && f.features.shaderInt64},
        // Its layers with visibility IDs test depth << 32 | ID with one 64-bit atomicMin.
        {"shaderBufferInt64Atomics", is13 && f12.shaderBufferInt64Atomics},
        // Visibility IDs (core/visibility.glsl): gl_PrimitiveID in fragment shaders needs the Geometry
        // capability; the RSM resolve writes its RG16_SNORM normals as a storage image.
        {"geometryShader", is13 && f.features.geometryShader},
        {"shaderStorageImageExtendedFormats", is13 && f.features.shaderStorageImageExtendedFormats},
        // Deep opacity maps sum optical depth with float atomics (dsm/opacity_build.comp).
        {"shaderBufferFloat32AtomicAdd (VK_EXT_shader_atomic_float)", is13 && af.shaderBufferFloat32AtomicAdd},
        // LPV injection sums a subgroup's VPLs per cell before its atomics (lpv/subgroup_cells.glsl).
        {"subgroup basic, ballot and arithmetic in compute",
         is13 && (p11.subgroupSupportedOperations & subgroupNeed) == subgroupNeed &&
             (p11.subgroupSupportedStages & VK_SHADER_STAGE_COMPUTE_BIT)},
    };
    for (FeatureCheck& c : checks)
        if (hidden(c.name)) c.present = false;
    return checks;
}

VkBool32 debugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT,
                       const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    auto* ctx = static_cast<Context*>(user);
    ctx->validationMessages_++;
    const char* level = severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error" : "warning";
    std::string msg = fmt::format("validation {}: {}", level, data->pMessage ? data->pMessage : "");
    if (ctx->validationLog_.size() < 64) ctx->validationLog_.push_back(msg);
    if (!ctx->options_.quiet) std::cerr << msg << "\n";
    return VK_FALSE;
}

namespace {

void destroyHandles(VkInstance instance, VkDebugUtilsMessengerEXT messenger, VkDevice device) {
    if (device) vkDestroyDevice(device, nullptr);
    if (messenger) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy) destroy(instance, messenger, nullptr);
    }
    if (instance) vkDestroyInstance(instance, nullptr);
}

}  // namespace

// A constructor that throws never runs the destructor: release what was already created (e.g. the
// instance when the device lacks a feature), so callers that catch the error do not leak it.
Context::Context(const ContextOptions& options) : options_(options) {
    try {
        createInstance(options.validate);
        pickDevice(options.device);
        createDevice();
    } catch (...) {
        destroyHandles(instance_, messenger_, device_);
        throw;
    }
}

Context::Context(const ContextOptions& options, InstanceOnly) : options_(options) {
    try {
        createInstance(options.validate);
    } catch (...) {
        destroyHandles(instance_, messenger_, device_);
        throw;
    }
}

Context::Context(const ExternalDevice& device, const ContextOptions& options) : options_(options) {
    options_.validate = false;
    ownsHandles_ = false;
    adopt(device);
}

Context::~Context() {
    pipelineCache_.reset();  // its pipelines and layouts go before the device
    if (ownsHandles_) destroyHandles(instance_, messenger_, device_);
}

void Context::createInstance(bool validate) {
    if (validate) {
        uint32_t n = 0;
        VK_CHECK(vkEnumerateInstanceLayerProperties(&n, nullptr));
        std::vector<VkLayerProperties> layers(n);
        VK_CHECK(vkEnumerateInstanceLayerProperties(&n, layers.data()));
        if (std::none_of(layers.begin(), layers.end(),
                         [](const VkLayerProperties& l) { return std::strcmp(l.layerName, kValidationLayer) == 0; }))
            throw VulkanError("validation: the Khronos validation layer is not installed "
                              "(Debian package vulkan-validationlayers)");
    }
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "penumbra";
    app.pEngineName = "penumbra";
    app.apiVersion = VK_API_VERSION_1_3;
    std::vector<const char*> exts;
    for (const std::string& e : options_.instanceExtensions) exts.push_back(e.c_str());
    // Debug utils carry the validation messages, and labels and names for capture tools.
    debugUtilsEnabled_ = validate || (options_.debugLabels && instanceOffers(VK_EXT_DEBUG_UTILS_EXTENSION_NAME));
    const auto isDebugUtils = [](const char* e) { return std::strcmp(e, VK_EXT_DEBUG_UTILS_EXTENSION_NAME) == 0; };
    if (debugUtilsEnabled_ && std::none_of(exts.begin(), exts.end(), isDebugUtils))
        exts.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    VkDebugUtilsMessengerCreateInfoEXT dbg{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    dbg.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    dbg.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                      VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    dbg.pfnUserCallback = debugCallback;
    dbg.pUserData = this;
    VkInstanceCreateInfo ci{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    ci.pApplicationInfo = &app;
    // Synchronization validation: hazards between passes and across frames in flight.
    const VkValidationFeatureEnableEXT syncFeature = VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
    VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = &syncFeature;
    if (validate) {
        ci.enabledLayerCount = 1;
        ci.ppEnabledLayerNames = &kValidationLayer;
        ci.pNext = &dbg;  // also reports problems inside vkCreateInstance itself
        if (options_.syncValidation) {
            features.pNext = &dbg;
            ci.pNext = &features;
        }
    }
    ci.enabledExtensionCount = uint32_t(exts.size());
    ci.ppEnabledExtensionNames = exts.data();
    VkResult r = vkCreateInstance(&ci, nullptr, &instance_);
    if (r == VK_ERROR_INCOMPATIBLE_DRIVER)
        throw VulkanError("no Vulkan driver found (install mesa-vulkan-drivers for lavapipe)");
    VK_CHECK(r);
    if (validate) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
        if (!create) throw VulkanError("VK_EXT_debug_utils is not available for validation");
        VK_CHECK(create(instance_, &dbg, nullptr, &messenger_));
    }
}

std::vector<DeviceInfo> Context::enumerate(const ContextOptions& options) {
    Context probe(options, InstanceOnly{});
    std::vector<DeviceInfo> out;
    auto devices = physicalDevices(probe.instance_);
    for (uint32_t i = 0; i < devices.size(); ++i) out.push_back(describe(devices[i], i));
    return out;
}

void Context::pickDevice(const std::string& selector) {
    auto devices = physicalDevices(instance_);
    if (devices.empty()) throw VulkanError("no Vulkan device found (install mesa-vulkan-drivers for lavapipe)");
    std::vector<DeviceInfo> infos;
    for (uint32_t i = 0; i < devices.size(); ++i) infos.push_back(describe(devices[i], i));
    int chosen = -1;
    if (!selector.empty()) {
        const bool numeric = std::all_of(selector.begin(), selector.end(), ::isdigit);
        for (const DeviceInfo& d : infos)
            if ((numeric && std::to_string(d.index) == selector) ||
                (!numeric && d.name.find(selector) != std::string::npos)) {
                chosen = static_cast<int>(d.index);
                break;
            }
        if (chosen < 0) throw VulkanError(fmt::format("device '{}': no such device (see `penumbra info`)", selector));
    } else {
        int best = -1;
        for (const DeviceInfo& d : infos) {
            VkPhysicalDeviceProperties p;
            vkGetPhysicalDeviceProperties(devices[d.index], &p);
            int score = typeRank(p.deviceType) + (d.missing.empty() ? 100 : 0);
            if (score > best) best = score, chosen = static_cast<int>(d.index);
        }
    }
    info_ = infos[chosen];
    if (!info_.missing.empty())
        throw VulkanError(fmt::format("device '{}' lacks required feature: {}", info_.name,
                                      fmt::join(info_.missing, ", ")));
    physical_ = devices[chosen];
    vkGetPhysicalDeviceProperties(physical_, &properties_);
    queueFamily_ = findQueueFamily(physical_);
    if (options_.presentSupport && !options_.presentSupport(instance_, physical_, queueFamily_))
        throw VulkanError(fmt::format("device '{}' cannot present to this display", info_.name));
}

void Context::createDevice() {
    float priority = 1.0f;
    VkDeviceQueueCreateInfo q{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    q.queueFamilyIndex = queueFamily_;
    q.queueCount = 1;
    q.pQueuePriorities = &priority;
    FeatureChain features;
    FeatureChain::enableRequired(features);
    std::vector<const char*> exts = requiredDeviceExtensions();
    if (options_.presentSupport) exts.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    VkDeviceCreateInfo ci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &features.features2};
    ci.queueCreateInfoCount = 1;
    ci.pQueueCreateInfos = &q;
    ci.enabledExtensionCount = uint32_t(exts.size());
    ci.ppEnabledExtensionNames = exts.data();
    VK_CHECK(vkCreateDevice(physical_, &ci, nullptr, &device_));
    vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
    loadDeviceFunctions();
}

void Context::loadDeviceFunctions() {
    cmdPushDescriptorSet = reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(
        vkGetDeviceProcAddr(device_, "vkCmdPushDescriptorSetKHR"));
    if (!cmdPushDescriptorSet) throw VulkanError("vkCmdPushDescriptorSetKHR not found");
    if (debugUtilsEnabled_ && options_.debugLabels) debugUtils_.load(instance_, device_);
}

void Context::adopt(const ExternalDevice& d) {
    if (!d.instance || !d.physicalDevice || !d.device || !d.queue)
        throw VulkanError("external device: the instance, physical device, device and queue must all be given");
    const std::vector<VkPhysicalDevice> devices = physicalDevices(d.instance);
    const auto found = std::find(devices.begin(), devices.end(), d.physicalDevice);
    if (found == devices.end()) throw VulkanError("external device: the physical device is not one of the instance's");
    info_ = describe(d.physicalDevice, uint32_t(found - devices.begin()));
    std::vector<std::string> problems;
    for (const std::string& m : info_.missing) problems.push_back(m + " (the device lacks it)");
    uint32_t n = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(d.physicalDevice, &n, nullptr);
    std::vector<VkQueueFamilyProperties> families(n);
    vkGetPhysicalDeviceQueueFamilyProperties(d.physicalDevice, &n, families.data());
    const VkQueueFlags need = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    if (d.queueFamily >= n)
        problems.push_back(fmt::format("queue family {} (the device has {})", d.queueFamily, n));
    else if ((families[d.queueFamily].queueFlags & need) != need || families[d.queueFamily].timestampValidBits == 0)
        problems.push_back(fmt::format("queue family {} with graphics, compute and timestamps", d.queueFamily));
    FeatureChain enabled;
    enabled.copyFrom(d.enabledFeatureChain, d.enabledFeatures);
    for (const std::string& m : enabled.missingRequired()) problems.push_back(m + " (not enabled)");
    for (const char* ext : requiredDeviceExtensions())
        if (std::find(d.enabledExtensions.begin(), d.enabledExtensions.end(), ext) == d.enabledExtensions.end())
            problems.push_back(fmt::format("{} (not enabled)", ext));
    if (!problems.empty())
        throw VulkanError(fmt::format("the engine's device '{}' cannot run penumbra; it needs: {}", info_.name,
                                      fmt::join(problems, ", ")));
    instance_ = d.instance;
    physical_ = d.physicalDevice;
    device_ = d.device;
    queue_ = d.queue;
    queueFamily_ = d.queueFamily;
    vkGetPhysicalDeviceProperties(physical_, &properties_);
    loadDeviceFunctions();
}

void Context::waitIdle() const { VK_CHECK(vkDeviceWaitIdle(device_)); }

DeviceLimits Context::limits() const { return deviceLimits(physical_); }

}  // namespace penumbra::vk
