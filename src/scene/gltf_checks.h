// Checks of a glTF file's bytes before tinygltf parses them (internal to the glTF loader). tinygltf
// parses JSON recursively (a 30 KB file nested 15000 deep overflows the stack), truncates integers
// that do not fit an int (an index of 2^32 + 1 becomes 1) and accepts any GLB version. Failures throw
// SceneError without the file path (the loader prefixes it).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace penumbra::gltf {

// Deeper JSON is refused: real glTF files nest under 10 levels (extras may add a few).
constexpr size_t kMaxJsonDepth = 64;

// The deepest nesting of arrays and objects in `json`, found iteratively (no recursion, so any
// input is safe); brackets inside strings do not count.
size_t jsonNestingDepth(std::string_view json);

// The JSON text of a .gltf file, or of a GLB's JSON chunk (GLB header checked: version 2, lengths
// inside the file, the first chunk JSON). `bytes` is the whole file.
std::string_view jsonText(const std::vector<uint8_t>& bytes, bool glb);

// Depth (kMaxJsonDepth) and the integer properties tinygltf reads as int (indices of nodes, meshes,
// accessors, buffer views, ... and enums): each must be an integer in [-1, 2^31 - 1].
void checkJson(std::string_view json);

}  // namespace penumbra::gltf
