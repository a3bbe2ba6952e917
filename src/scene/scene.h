// Scene description shared by the renderer, the CLI and the reference renderer.
// The node hierarchy survives loading (Scene::nodes, parents before children). Geometry is stored
// per mesh (Scene::meshes) and drawn per instance (Scene::instances) with the instance's world
// transform. Static batching: a mesh that only one node draws and that no animation moves is baked
// into world space at load into mesh 0 (drawn by the identity instance), so a file of 200000 static
// nodes stays a few draws per pass; meshes drawn by several nodes, or moved by an animation, keep
// their own local-space copy, uploaded once and drawn once per instance.
#pragma once
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace penumbra {

struct Vertex {
    glm::vec3 position;  // the mesh's space (world space for mesh 0, the static batch)
    glm::vec3 normal;    // the mesh's space, unit length
    glm::vec2 uv;
};

enum class AlphaMode : uint32_t { Opaque = 0, Mask = 1, Blend = 2 };

struct Texture {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba8;  // sRGB-encoded RGBA8, row-major, top row first
};

struct Material {
    glm::vec4 baseColor{1.0f};      // linear RGBA factor
    int32_t baseColorTexture = -1;  // index into Scene::textures, -1 = none
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    bool doubleSided = false;
};

// A contiguous range of Scene::indices drawn with one material.
struct Draw {
    uint32_t firstIndex = 0;
    uint32_t indexCount = 0;
    uint32_t material = 0;
};

// Hair: a polyline strand in world space, drawn as a ribbon that faces the viewer (camera or light),
// never narrower than one pixel or shadow texel. Strands are semi-transparent shadow casters (deep
// shadow maps, src/dsm) and Kajiya-Kay-shaded receivers.
struct Strand {
    uint32_t firstPoint = 0;  // into Scene::strandPoints
    uint32_t pointCount = 0;  // >= 2
    float width = 1e-4f;      // world-space width (m); a thinner-than-a-texel strand casts with its coverage
    float opacity = 0.5f;     // fraction of the light a strand stops where it fully covers a shadow texel
    glm::vec3 color{0.35f, 0.22f, 0.12f};  // linear base colour
};

struct Bounds {
    glm::vec3 min{1e30f};
    glm::vec3 max{-1e30f};
    void extend(const glm::vec3& p) { min = glm::min(min, p); max = glm::max(max, p); }
    bool empty() const { return min.x > max.x; }
    glm::vec3 center() const { return 0.5f * (min + max); }
    glm::vec3 corner(int i) const { return {i & 1 ? max.x : min.x, i & 2 ? max.y : min.y, i & 4 ? max.z : min.z}; }
    float radius() const { return 0.5f * glm::length(max - min); }
};

enum class LightType : uint32_t { Directional = 0, Spot = 1, Point = 2 };

// Shadow-map filter of one light (values = SHADOW_FILTER_* in shaders/shared/types.h). Default:
// the renderer's setting (`--shadow`); anything else overrides it for this light.
enum class ShadowFilter : uint32_t { Default = 0, Hard = 1, Pcf = 2, Pcss = 3, Vsm = 4, Evsm = 5, Msm = 6 };

// Photometric units follow KHR_lights_punctual, used radiometrically: directional `intensity` is
// irradiance E on a surface facing the light; spot/point `intensity` is radiant intensity I, so a
// surface at distance d facing the light receives E = I / d^2.
struct Light {
    LightType type = LightType::Directional;
    glm::vec3 position{0.0f};          // spot, point
    glm::vec3 direction{0, -1, 0};     // direction the light travels (spot, directional), unit length
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
    float range = 0.0f;                // 0 = infinite
    float innerConeAngle = 0.0f;       // radians, spot only
    float outerConeAngle = 0.7853982f; // radians, spot only
    bool castsShadow = true;
    ShadowFilter shadowFilter = ShadowFilter::Default;
    std::string name;
    int32_t node = -1;  // the Scene::nodes entry it hangs from (moves with it), -1 = none
};

// A node of the hierarchy: its rest transform (TRS, or a matrix, which glTF never animates).
struct Node {
    int32_t parent = -1;  // index into Scene::nodes, smaller than this node's (parents come first)
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    glm::vec3 scale{1.0f};
    std::optional<glm::mat4> matrix;  // replaces TRS when present
    int32_t mesh = -1;        // glTF mesh drawn here (informative; Scene::instances draws it)
    int32_t sourceNode = -1;  // the glTF node it came from (animation channels target these)
    std::string name;
    glm::mat4 local() const;
};

// A range of Scene::draws in one coordinate space.
struct Mesh {
    uint32_t firstDraw = 0;
    uint32_t drawCount = 0;
    Bounds bounds;  // of its vertices, in its own space
};

// One drawing of a mesh: with the world transform of `node`, or the identity (node -1: mesh 0,
// the static batch already in world space).
struct Instance {
    uint32_t mesh = 0;
    int32_t node = -1;
};

// glTF animation (translation, rotation, scale channels; STEP, LINEAR, CUBICSPLINE).
enum class AnimationPath : uint32_t { Translation = 0, Rotation = 1, Scale = 2 };
enum class Interpolation : uint32_t { Linear = 0, Step = 1, CubicSpline = 2 };

struct AnimationChannel {
    int32_t sourceNode = -1;  // glTF node index
    AnimationPath path = AnimationPath::Translation;
    Interpolation interpolation = Interpolation::Linear;
    std::vector<float> times;       // increasing key times (s)
    std::vector<glm::vec4> values;  // xyz(w): one per key, three (in-tangent, value, out-tangent) for CUBICSPLINE
};

struct Animation {
    std::string name;
    std::vector<AnimationChannel> channels;
    float duration = 0.0f;  // last key time over all channels
};

struct Camera {
    glm::vec3 eye{0, 0, 5};
    glm::vec3 target{0, 0, 0};
    glm::vec3 up{0, 1, 0};
    float fovy = 0.7853982f;  // radians, vertical
    float znear = 0.05f;
    float zfar = 0.0f;        // 0 = derived from the scene bounds
    int32_t node = -1;        // the Scene::nodes entry it hangs from (moves with it), -1 = none
};

struct Scene {
    std::string name;
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;
    std::vector<Draw> draws;
    std::vector<Material> materials;  // never empty after loading: index 0 is a default white
    std::vector<Texture> textures;
    std::vector<Light> lights;
    std::vector<Camera> cameras;      // from the file; the first is the default view
    std::vector<Node> nodes;          // the hierarchy, parents first (empty: everything is in mesh 0)
    std::vector<Mesh> meshes;         // mesh 0 is the static batch (world space); see ensureSceneGraph
    std::vector<Instance> instances;  // what is drawn: instance 0 is mesh 0 with the identity
    std::vector<Animation> animations;
    Bounds bounds;                    // world-space bounds of all vertices and strand points, over every animation
    std::vector<glm::vec3> strandPoints;  // hair: the points of every strand, strand after strand
    std::vector<Strand> strands;
    // One line per thing the loader dropped or changed (a missing texture, an orthographic camera, a
    // clamped value); the CLI prints each as a warning.
    std::vector<std::string> warnings;

    void computeBounds();
    bool hasBlendedMaterials() const;
    // Where light passes partly (the DSM's and the camera translucency's casters): the strands' points,
    // or with alphaMode BLEND materials the whole scene's bounds.
    Bounds translucentCasterBounds() const;
    size_t triangleCount() const { return indices.size() / 3; }  // stored (each mesh once)
    size_t drawnTriangleCount() const;                            // drawn (each instance of each mesh)
};

// Thrown for every bad scene input (missing file, malformed glTF, unknown built-in name...).
// The CLI prints what() as its one error line.
struct SceneError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Loads a .gltf or .glb file. Node transforms are baked in, missing normals are generated
// (area-weighted vertex normals), KHR_lights_punctual lights and perspective cameras are read.
Scene loadGltf(const std::string& path);

// Parameters of the built-in scenes (CLI: --strands).
struct BuiltinOptions {
    uint32_t hairStrands = 25000;  // strands grown on the `hair` scene's head
    static constexpr uint32_t kHairPointsPerStrand = 25;  // points of each grown strand
};

// Built-in procedural scenes: "cornell" (the default), "cornell-moving" (a box sliding across its
// back wall), "plane" (unit test scene), "hair" (a head with procedural hair over a floor, under a
// spot light), "street", "room" and "terrain".
std::vector<std::string> builtinSceneNames();
Scene makeBuiltinScene(const std::string& name, const BuiltinOptions& options = {});

// A path or a built-in name: a name without '.' or '/' that is not a file is looked up as built-in.
// The result has had addDefaultsIfMissing applied.
Scene loadScene(const std::string& pathOrName, const BuiltinOptions& options = {});

// Adds a default sun and camera where the scene has none, so that any glTF model renders.
void addDefaultsIfMissing(Scene& scene);

// A scene built by appending triangles (built-in scenes, tests) has no meshes or instances yet: all
// its draws become mesh 0, drawn once by the identity instance. Idempotent.
void ensureSceneGraph(Scene& scene);

}  // namespace penumbra
