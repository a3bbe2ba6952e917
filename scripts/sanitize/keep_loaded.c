/* Preloaded by scripts/sanitize.sh: opens the Vulkan driver and validation layer once with
 * RTLD_NODELETE | RTLD_LOCAL, so that the loader's dlclose() leaves them mapped (LeakSanitizer then
 * names them and lsan.supp can suppress their process-lifetime allocations) without their exported
 * vk* entry points shadowing the loader's, as preloading the libraries themselves would. */
#include <dlfcn.h>

__attribute__((constructor)) static void keepVulkanModulesLoaded(void) {
    dlopen("libvulkan_lvp.so", RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
    dlopen("libVkLayer_khronos_validation.so", RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
}
