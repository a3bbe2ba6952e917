// Bounds-checked reading of glTF accessors (internal to the glTF loader).
// tinygltf parses the JSON but does not check that accessors fit their buffers, so every read here
// is validated first; failures throw SceneError without the file path (the loader prefixes it).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace penumbra::gltf {

// Reads accessor `index` as `components` floats per element (`what` names it in errors). The
// accessor type must have exactly that many components. Normalized integers map to [0,1] / [-1,1];
// other integers convert to their value. Sparse accessors and accessors without a bufferView
// (all zeros) are supported.
std::vector<float> readFloats(const tinygltf::Model& model, int index, int components, const std::string& what);

// The component types glTF 2.0 allows for a vertex attribute (POSITION and NORMAL: FLOAT; TEXCOORD_n:
// FLOAT or normalized UNSIGNED_BYTE/SHORT; with KHR_mesh_quantization (`quantized`) also the integer
// forms that extension lists). Throws SceneError naming the attribute and the type.
void checkAttributeType(const tinygltf::Model& model, int accessor, const std::string& attribute, bool quantized,
                        const std::string& what);

// Reads a SCALAR accessor of UNSIGNED_BYTE/SHORT/INT as indices.
std::vector<uint32_t> readIndices(const tinygltf::Model& model, int index);

}  // namespace penumbra::gltf
