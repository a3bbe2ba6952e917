#include "api/impl.h"

namespace penumbra::api {

std::vector<const char*> requiredDeviceExtensions() { return vk::requiredDeviceExtensions(); }

RequiredFeatures::RequiredFeatures() {
    vk::FeatureChain chain;
    vk::FeatureChain::enableRequired(chain);
    features2 = chain.features2, v11 = chain.v11, v12 = chain.v12, v13 = chain.v13, atomicFloat = chain.atomicFloat;
    features2.pNext = &v11, v11.pNext = &v12, v12.pNext = &v13, v13.pNext = &atomicFloat, atomicFloat.pNext = nullptr;
}

Device::Device(const DeviceOptions& options) : impl_(std::make_unique<Impl>()) {
    vk::ContextOptions o;
    o.device = options.device;
    o.validate = options.validate;
    o.syncValidation = options.syncValidation;
    o.quiet = true;  // the log is the caller's to print (validationLog)
    impl_->ctx = std::make_unique<vk::Context>(o);  // vk::VulkanError is a std::runtime_error
}

Device::Device(const ExternalDevice& device) : impl_(std::make_unique<Impl>()) {
    vk::ExternalDevice d{device.instance,    device.physicalDevice,      device.device, device.queue,
                         device.queueFamily, device.enabledFeatureChain, device.enabledFeatures,
                         device.enabledExtensions};
    impl_->ctx = std::make_unique<vk::Context>(d);
}

Device::~Device() = default;

std::string Device::name() const { return impl_->ctx->info().name; }
VkDevice Device::handle() const { return impl_->ctx->device(); }
uint32_t Device::validationMessages() const { return impl_->ctx->validationMessages(); }
std::vector<std::string> Device::validationLog() const { return impl_->ctx->validationLog(); }

}  // namespace penumbra::api
