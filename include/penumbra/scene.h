// A scene for penumbra: loaded from glTF, one of the built-in scenes, or built from memory (vertex
// and index arrays, materials, lights, cameras); and the inputs of one frame (camera, lights, instance
// transforms). Units and conventions: right-handed, y up, metres; colours linear; directions unit length.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "penumbra/settings.h"

namespace penumbra::api {

using Mat4 = std::array<float, 16>;  // column-major, as glm and GLSL store it

struct Vertex {
    Vec3 position;  // world space
    Vec3 normal;    // unit length
    float uv[2] = {0.0f, 0.0f};
};

enum class AlphaMode : uint32_t { Opaque, Mask, Blend };

struct Texture {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba8;  // sRGB-encoded RGBA8, row-major, top row first
};

struct Material {
    float baseColor[4];         // linear RGBA factor
    int32_t baseColorTexture;   // index into SceneDesc::textures, -1 = none
    AlphaMode alphaMode;
    float alphaCutoff;
    bool doubleSided;
    Material();
};

// A range of SceneDesc::indices (whole triangles) drawn with one material.
struct Draw {
    uint32_t firstIndex = 0;
    uint32_t indexCount = 0;
    uint32_t material = 0;
};

enum class LightType : uint32_t { Directional, Spot, Point };

// Directional `intensity` is the irradiance on a surface facing the light; spot and point `intensity`
// is radiant intensity (irradiance I / d^2 at distance d), as KHR_lights_punctual used radiometrically.
struct Light {
    LightType type;
    Vec3 position;        // spot, point
    Vec3 direction;       // where the light travels (spot, directional)
    Vec3 color;
    float intensity;
    float range;          // 0 = infinite
    float innerConeAngle;  // radians, spot
    float outerConeAngle;  // radians, spot
    bool castsShadow;
    ShadowFilter shadowFilter;  // Default: Settings::shadow.filter
    Light();
};

struct Camera {
    Vec3 eye, target, up;
    float fovy;   // radians, vertical
    float znear;
    float zfar;   // 0 = from the scene's bounds
    Camera();
};

// A scene in memory. Every draw's range lies inside `indices` and is whole triangles, every index
// names a vertex, every material index and texture index exists. Without draws, all indices are one
// draw of material 0; without materials there is a white one, without lights a sun, without cameras
// one that frames the scene. Normals and light directions not of unit length are scaled (a warning).
struct SceneDesc {
    std::string name = "memory";
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;
    std::vector<Draw> draws;
    std::vector<Material> materials;
    std::vector<Texture> textures;
    std::vector<Light> lights;
    std::vector<Camera> cameras;
};

// What one frame shows: the camera, the lights, and a world transform per instance of the scene
// (empty: the rest pose). A scene built from memory has one instance.
struct Frame {
    Camera camera;
    std::vector<Light> lights;
    std::vector<Mat4> instances;
};

class Renderer;

// A loaded scene (immutable, cheap to copy). Bad input throws one line: std::runtime_error for a
// file or name, std::invalid_argument for arrays (fromMemory).
class SceneData {
public:
    static SceneData fromGltf(const std::string& path);
    static SceneData builtin(const std::string& name);  // "cornell", "plane", "hair"
    static SceneData fromMemory(const SceneDesc& desc);

    // The scene's first camera and its lights at `time` seconds (glTF animation, the built-in
    // scenes' default motion).
    Frame frame(double time = 0.0) const;
    const std::string& name() const;
    size_t triangleCount() const;
    // What the loader dropped or changed, one line each.
    const std::vector<std::string>& warnings() const;

    struct Impl;

private:
    friend class Renderer;
    explicit SceneData(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}
    std::shared_ptr<const Impl> impl_;
};

}  // namespace penumbra::api
