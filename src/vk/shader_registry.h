// SPIR-V modules compiled from shaders/ at build time and embedded (cmake/EmbedShaders.cmake).
#pragma once
#include <cstddef>
#include <string>

namespace penumbra::vk {

struct EmbeddedShader {
    const char* key;  // path below shaders/, e.g. "lighting/lighting.comp"
    const unsigned char* code;
    unsigned long size;
};

extern const EmbeddedShader kEmbeddedShaders[];

// Throws VulkanError when no shader has that key.
const EmbeddedShader& findShader(const std::string& key);

}  // namespace penumbra::vk
