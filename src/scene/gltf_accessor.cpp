#include "scene/gltf_accessor.h"

#include <algorithm>
#include <cstring>

#include <fmt/format.h>

#include "scene/scene.h"

namespace penumbra::gltf {

namespace {

// Far more than any real asset; stops a bogus count from allocating gigabytes for a zero accessor.
constexpr size_t kMaxElements = size_t(1) << 28;

struct Range {
    const uint8_t* data = nullptr;
    size_t stride = 0;
};

size_t componentSize(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_INT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
        default: return 0;
    }
}

// Validates that `count` elements of `elemSize` bytes, `stride` apart (0 = the view's byteStride or
// tightly packed), starting at `offset` inside buffer view `viewIndex`, lie inside its buffer.
Range checkedRange(const tinygltf::Model& m, int viewIndex, size_t offset, size_t count, size_t elemSize,
                   size_t compSize, bool useViewStride, const std::string& what) {
    if (viewIndex < 0 || size_t(viewIndex) >= m.bufferViews.size())
        throw SceneError(fmt::format("{}: bufferView {} does not exist", what, viewIndex));
    const tinygltf::BufferView& view = m.bufferViews[size_t(viewIndex)];
    if (view.buffer < 0 || size_t(view.buffer) >= m.buffers.size())
        throw SceneError(fmt::format("{}: bufferView {} refers to missing buffer {}", what, viewIndex, view.buffer));
    const size_t bufferSize = m.buffers[size_t(view.buffer)].data.size();
    if (view.byteLength > bufferSize || view.byteOffset > bufferSize - view.byteLength)
        throw SceneError(fmt::format("{}: bufferView {} (offset {}, length {}) exceeds its buffer of {} bytes", what,
                                     viewIndex, view.byteOffset, view.byteLength, bufferSize));
    const size_t stride = (useViewStride && view.byteStride != 0) ? view.byteStride : elemSize;
    if (stride < elemSize)
        throw SceneError(fmt::format("{}: byteStride {} is smaller than the element size {}", what, stride, elemSize));
    // glTF 2.0 3.6.2.4: offsets and strides are multiples of the component size.
    if ((view.byteOffset + offset) % compSize != 0 || stride % compSize != 0)
        throw SceneError(fmt::format("{}: data at byte {} of the buffer (stride {}) is not aligned to its {}-byte "
                                     "components", what, view.byteOffset + offset, stride, compSize));
    // Written to avoid overflow: offset + (count-1)*stride + elemSize <= byteLength.
    if (count > 0 && (offset > view.byteLength || elemSize > view.byteLength - offset ||
                      count - 1 > (view.byteLength - offset - elemSize) / stride))
        throw SceneError(fmt::format("{}: {} elements at offset {} exceed bufferView {} ({} bytes)", what, count,
                                     offset, viewIndex, view.byteLength));
    return {m.buffers[size_t(view.buffer)].data.data() + view.byteOffset + offset, stride};
}

template <typename T>
T load(const uint8_t* p) {
    T v;
    std::memcpy(&v, p, sizeof(T));  // glTF data need not be aligned
    return v;
}

float toFloat(const uint8_t* p, int componentType, bool normalized) {
    // The glTF 2.0 rules for normalized integers (signed values clamp at -1).
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return load<float>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? load<uint8_t>(p) / 255.0f : load<uint8_t>(p);
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return normalized ? std::max(load<int8_t>(p) / 127.0f, -1.0f) : load<int8_t>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return normalized ? load<uint16_t>(p) / 65535.0f : load<uint16_t>(p);
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            return normalized ? std::max(load<int16_t>(p) / 32767.0f, -1.0f) : load<int16_t>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return float(load<uint32_t>(p));
        case TINYGLTF_COMPONENT_TYPE_INT: return float(load<int32_t>(p));
        default: return 0.0f;
    }
}

uint32_t toIndex(const uint8_t* p, int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return load<uint8_t>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return load<uint16_t>(p);
        default: return load<uint32_t>(p);
    }
}

bool isIndexType(int componentType) {
    return componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
           componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
           componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}

const tinygltf::Accessor& accessorAt(const tinygltf::Model& m, int index, const std::string& what) {
    if (index < 0 || size_t(index) >= m.accessors.size())
        throw SceneError(fmt::format("{}: accessor {} does not exist ({} accessors)", what, index, m.accessors.size()));
    const tinygltf::Accessor& a = m.accessors[size_t(index)];
    if (componentSize(a.componentType) == 0)
        throw SceneError(fmt::format("{}: accessor {} has invalid componentType {}", what, index, a.componentType));
    if (a.count > kMaxElements)
        throw SceneError(fmt::format("{}: accessor {} count {} is implausibly large", what, index, a.count));
    return a;
}

// Reads all elements (dense part, then sparse substitution) through `conv`, `comps` per element.
template <typename T, typename Convert>
std::vector<T> gather(const tinygltf::Model& m, const tinygltf::Accessor& a, int comps, const std::string& what,
                      Convert conv) {
    const size_t compSize = componentSize(a.componentType);
    const size_t elemSize = compSize * size_t(comps);
    std::vector<T> out(a.count * size_t(comps), T{});  // no bufferView means zeros (glTF spec)
    if (a.bufferView >= 0) {
        const Range r = checkedRange(m, a.bufferView, a.byteOffset, a.count, elemSize, compSize, true, what);
        for (size_t i = 0; i < a.count; ++i)
            for (int c = 0; c < comps; ++c) out[i * comps + c] = conv(r.data + i * r.stride + c * compSize);
    }
    if (!a.sparse.isSparse) return out;
    const auto& sp = a.sparse;
    if (sp.count < 0 || size_t(sp.count) > a.count || sp.indices.byteOffset < 0 || sp.values.byteOffset < 0 ||
        !isIndexType(sp.indices.componentType))
        throw SceneError(fmt::format("{}: invalid sparse accessor", what));
    const size_t n = size_t(sp.count);
    const size_t idxSize = componentSize(sp.indices.componentType);
    const Range idx =
        checkedRange(m, sp.indices.bufferView, size_t(sp.indices.byteOffset), n, idxSize, idxSize, false, what);
    const Range val =
        checkedRange(m, sp.values.bufferView, size_t(sp.values.byteOffset), n, elemSize, compSize, false, what);
    for (size_t k = 0; k < n; ++k) {
        const uint32_t j = toIndex(idx.data + k * idxSize, sp.indices.componentType);
        if (j >= a.count) throw SceneError(fmt::format("{}: sparse index {} out of range", what, j));
        for (int c = 0; c < comps; ++c) out[j * comps + c] = conv(val.data + k * elemSize + c * compSize);
    }
    return out;
}

}  // namespace

std::vector<float> readFloats(const tinygltf::Model& model, int index, int components, const std::string& what) {
    const tinygltf::Accessor& a = accessorAt(model, index, what);
    if (tinygltf::GetNumComponentsInType(uint32_t(a.type)) != components)
        throw SceneError(fmt::format("{}: accessor {} has {} components per element, expected {}", what, index,
                                     tinygltf::GetNumComponentsInType(uint32_t(a.type)), components));
    return gather<float>(model, a, components, what,
                         [&](const uint8_t* p) { return toFloat(p, a.componentType, a.normalized); });
}

void checkAttributeType(const tinygltf::Model& model, int index, const std::string& attribute, bool quantized,
                        const std::string& what) {
    const tinygltf::Accessor& a = accessorAt(model, index, what + " " + attribute);
    const int t = a.componentType;
    const bool isFloat = t == TINYGLTF_COMPONENT_TYPE_FLOAT;
    const bool unsignedNorm = a.normalized && (t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                               t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    const bool smallInt = t == TINYGLTF_COMPONENT_TYPE_BYTE || t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                          t == TINYGLTF_COMPONENT_TYPE_SHORT || t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    const bool signedNorm = a.normalized && (t == TINYGLTF_COMPONENT_TYPE_BYTE || t == TINYGLTF_COMPONENT_TYPE_SHORT);
    bool ok = isFloat;
    if (attribute == "POSITION") ok = isFloat || (quantized && smallInt);
    else if (attribute == "NORMAL") ok = isFloat || (quantized && signedNorm);
    else if (attribute.rfind("TEXCOORD_", 0) == 0) ok = isFloat || unsignedNorm || (quantized && smallInt);
    if (!ok)
        throw SceneError(fmt::format("{} {}: accessor {} has componentType {}{}, which glTF does not allow for {}{}",
                                     what, attribute, index, t, a.normalized ? " (normalized)" : "", attribute,
                                     quantized ? "" : " without KHR_mesh_quantization"));
}

std::vector<uint32_t> readIndices(const tinygltf::Model& model, int index) {
    const std::string what = "indices";
    const tinygltf::Accessor& a = accessorAt(model, index, what);
    if (a.type != TINYGLTF_TYPE_SCALAR || !isIndexType(a.componentType))
        throw SceneError(fmt::format("indices: accessor {} is not a scalar of unsigned integers", index));
    return gather<uint32_t>(model, a, 1, what, [&](const uint8_t* p) { return toIndex(p, a.componentType); });
}

}  // namespace penumbra::gltf
