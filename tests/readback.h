// Values read back from GPU images as raw bytes (half and 32-bit floats), shared by the GPU tests.
#pragma once
#include <cstdint>
#include <cstring>
#include <vector>

#include <glm/gtc/packing.hpp>

namespace penumbra::test {

inline float half(const std::vector<uint8_t>& bytes, size_t index) {
    uint16_t h;
    std::memcpy(&h, bytes.data() + index * 2, 2);
    return glm::unpackHalf1x16(h);
}

inline float f32(const std::vector<uint8_t>& bytes, size_t index) {
    float f;
    std::memcpy(&f, bytes.data() + index * 4, 4);
    return f;
}

inline uint32_t u32(const std::vector<uint8_t>& bytes, size_t index) {
    uint32_t v;
    std::memcpy(&v, bytes.data() + index * 4, 4);
    return v;
}

}  // namespace penumbra::test
