// penumbra as a library: a Vulkan device (penumbra's own, or the engine's), a scene, and a Renderer
// that renders frames of it with the chosen shadow and GI techniques, read back to memory or handed
// to the engine as a VkImage. Link penumbra::core (find_package(penumbra CONFIG REQUIRED)).
//
// Threads: a Device and everything made on it are used from one thread at a time; penumbra submits
// to the device's queue from the calling thread (an engine sharing the queue serializes its own
// submissions with penumbra's calls).
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "penumbra/scene.h"
#include "penumbra/settings.h"

namespace penumbra::api {

// penumbra's own device: the best one (discrete GPU first, lavapipe last), or one chosen by index
// or name substring.
struct DeviceOptions {
    std::string device;
    bool validate = false;        // VK_LAYER_KHRONOS_validation; messages are counted and logged
    bool syncValidation = false;  // with validate: synchronization validation too
};

// What an engine's own device must have for penumbra (Device(const ExternalDevice&) checks all of it
// and throws std::runtime_error naming everything missing):
// - an instance created with apiVersion >= VK_API_VERSION_1_3 (kRequiredApiVersion);
// - a queue of a family with graphics, compute and timestamps (timestampValidBits > 0);
// - the extensions of requiredDeviceExtensions() enabled;
// - the features of RequiredFeatures enabled, in VkPhysicalDeviceFeatures2 (or pEnabledFeatures),
//   VkPhysicalDeviceVulkan11/12/13Features and VkPhysicalDeviceShaderAtomicFloatFeaturesEXT of the
//   VkDeviceCreateInfo::pNext chain, which the engine hands in as enabledFeatureChain.
inline constexpr uint32_t kRequiredApiVersion = VK_API_VERSION_1_3;
std::vector<const char*> requiredDeviceExtensions();

// The feature structs with every feature penumbra needs on, chained from features2: point
// VkDeviceCreateInfo::pNext at features2 (or copy the bits into the engine's own chain). Not copyable:
// the chain points into the object.
struct RequiredFeatures {
    VkPhysicalDeviceFeatures2 features2{};
    VkPhysicalDeviceVulkan11Features v11{};
    VkPhysicalDeviceVulkan12Features v12{};
    VkPhysicalDeviceVulkan13Features v13{};
    VkPhysicalDeviceShaderAtomicFloatFeaturesEXT atomicFloat{};
    RequiredFeatures();
    RequiredFeatures(const RequiredFeatures&) = delete;
    RequiredFeatures& operator=(const RequiredFeatures&) = delete;
};

// An engine's device: penumbra uses these handles and destroys none of them (destroy the Device and
// every Renderer on it first).
struct ExternalDevice {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t queueFamily = 0;
    const void* enabledFeatureChain = nullptr;                  // VkDeviceCreateInfo::pNext
    const VkPhysicalDeviceFeatures* enabledFeatures = nullptr;  // VkDeviceCreateInfo::pEnabledFeatures
    std::vector<std::string> enabledExtensions;
};

class Renderer;

class Device {
public:
    explicit Device(const DeviceOptions& options = {});
    explicit Device(const ExternalDevice& device);
    ~Device();
    Device(const Device&) = delete;
    Device& operator=(const Device&) = delete;

    std::string name() const;
    VkDevice handle() const;
    // Validation messages seen so far (DeviceOptions::validate), and the first of them.
    uint32_t validationMessages() const;
    std::vector<std::string> validationLog() const;

    struct Impl;

private:
    friend class Renderer;
    std::unique_ptr<Impl> impl_;
};

// A frame's tone-mapped image for the engine: RGBA8 (sRGB-encoded values in a UNORM format), usable
// for sampling (SAMPLED) and copying (TRANSFER_SRC). `ready` is signalled when the frame is done; the
// engine waits on it (once) before it reads the image, in `layout`. The image and view stay valid and
// unchanged until the next submitToImage (a different size makes a new image).
struct FrameImage {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    uint32_t width = 0, height = 0;
    VkSemaphore ready = VK_NULL_HANDLE;
};

struct PassTiming {
    std::string name;
    double ms = 0.0;
};

// GPU time of the newest completed frame: the whole frame, and per pass with setPassTimings(true).
struct Timings {
    double gpuMs = 0.0;
    double cpuMs = 0.0;  // recording and submission on the host
    std::vector<PassTiming> passes;
};

class Renderer {
public:
    // Uploads the scene and builds the techniques the settings ask for. Throws std::invalid_argument
    // for settings out of range.
    Renderer(Device& device, const SceneData& scene, const Settings& settings);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // New settings; what they invalidate is rebuilt before the next frame.
    void apply(const Settings& settings);
    const Settings& settings() const;

    // One frame, waited for (then read it back with readRgba8 / readRgba32f).
    void render(const Frame& frame);
    // One frame submitted without waiting (frames in flight); finish() waits for all.
    void submit(const Frame& frame);
    // One frame whose image the engine samples or copies (see FrameImage). The frame waits on
    // `engineDone` (if given) before it writes the image again: signal it when done with the previous one.
    FrameImage submitToImage(const Frame& frame, VkSemaphore engineDone = VK_NULL_HANDLE);
    void finish();

    std::vector<uint8_t> readRgba8();    // tone-mapped, sRGB-encoded, top row first
    std::vector<float> readRgba32f();    // linear radiance (or the debug view's values)

    void setPassTimings(bool on);  // per-pass GPU scopes (serialize the passes)
    Timings timings() const;
    // Things worth telling the user (e.g. lights rendered without shadows), one line each.
    const std::vector<std::string>& warnings() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Image files; both throw std::runtime_error with one line.
void writePng(const std::string& path, uint32_t width, uint32_t height, const std::vector<uint8_t>& rgba8);
void writeExr(const std::string& path, uint32_t width, uint32_t height, const std::vector<float>& rgba32f);

}  // namespace penumbra::api
