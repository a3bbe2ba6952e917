#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <system_error>

#include <fmt/format.h>

#include "scene/animation.h"

namespace penumbra {

void Scene::computeBounds() {
    ensureSceneGraph(*this);
    for (Mesh& m : meshes) {
        m.bounds = Bounds{};
        for (uint32_t d = m.firstDraw; d < m.firstDraw + m.drawCount; ++d)
            for (uint32_t k = 0; k < draws[d].indexCount; ++k)
                m.bounds.extend(vertices[indices[draws[d].firstIndex + k]].position);
    }
    bounds = animatedBounds(*this);
}

bool Scene::hasBlendedMaterials() const {
    for (const Material& m : materials)
        if (m.alphaMode == AlphaMode::Blend) return true;
    return false;
}

Bounds Scene::translucentCasterBounds() const {
    if (hasBlendedMaterials()) return bounds;
    Bounds b;
    for (const glm::vec3& p : strandPoints) b.extend(p);
    return b;
}

size_t Scene::drawnTriangleCount() const {
    if (instances.empty()) return triangleCount();
    size_t n = 0;
    for (const Instance& i : instances)
        for (uint32_t d = meshes[i.mesh].firstDraw; d < meshes[i.mesh].firstDraw + meshes[i.mesh].drawCount; ++d)
            n += draws[d].indexCount / 3;
    return n;
}

void ensureSceneGraph(Scene& scene) {
    if (!scene.nodes.empty() && !scene.meshes.empty()) return;  // the loader made them
    if (scene.meshes.size() == 1 && scene.meshes[0].drawCount == scene.draws.size() && scene.instances.size() == 1)
        return;
    scene.meshes = {Mesh{0, uint32_t(scene.draws.size()), {}}};
    scene.instances = {Instance{0, -1}};
}

namespace {

// A name with '.' or '/' is clearly meant as a file, so "not found" is the useful message for it.
bool looksLikePath(const std::string& s) { return s.find_first_of("./\\") != std::string::npos; }

struct Sphere {
    glm::vec3 center;
    float radius;
};

Sphere boundingSphere(const Scene& scene) {
    if (scene.bounds.empty()) return {glm::vec3(0.0f), 1.0f};
    // A flat or point-like scene still needs a usable camera distance.
    return {scene.bounds.center(), std::max(scene.bounds.radius(), 1e-3f)};
}

Camera framingCamera(const Sphere& s) {
    Camera cam;
    cam.fovy = glm::radians(45.0f);
    // 3/4 view from above: front-right, about 30 degrees of elevation.
    const glm::vec3 dir = glm::normalize(glm::vec3(0.6f, 0.6f, 1.0f));
    // Distance at which the bounding sphere fits the vertical field of view, plus a margin.
    const float dist = 1.1f * s.radius / std::sin(0.5f * cam.fovy);
    cam.target = s.center;
    cam.eye = s.center + dir * dist;
    cam.up = glm::vec3(0, 1, 0);
    cam.znear = std::max(1e-3f, 0.01f * s.radius);
    return cam;
}

}  // namespace

void addDefaultsIfMissing(Scene& scene) {
    if (scene.materials.empty()) scene.materials.push_back(Material{});
    if (scene.bounds.empty() && !scene.vertices.empty()) scene.computeBounds();
    const Sphere sphere = boundingSphere(scene);
    if (scene.lights.empty()) {
        Light sun;
        sun.type = LightType::Directional;
        sun.direction = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f));
        sun.color = glm::vec3(1.0f);
        sun.intensity = 3.0f;
        sun.name = "sun";
        scene.lights.push_back(sun);
    }
    if (scene.cameras.empty()) scene.cameras.push_back(framingCamera(sphere));
    for (Camera& cam : scene.cameras) {
        if (cam.zfar > 0.0f) continue;
        // Far enough to see the far side of the bounding sphere from wherever the camera is.
        const float dist = glm::length(cam.eye - sphere.center);
        cam.zfar = std::max(dist + 2.0f * sphere.radius, 10.0f * cam.znear);
    }
}

Scene loadScene(const std::string& pathOrName, const BuiltinOptions& options) {
    std::error_code ec;
    const bool exists = std::filesystem::is_regular_file(pathOrName, ec);
    Scene scene;
    if (exists) {
        scene = loadGltf(pathOrName);
    } else if (!pathOrName.empty() && !looksLikePath(pathOrName)) {
        scene = makeBuiltinScene(pathOrName, options);
    } else if (std::filesystem::is_directory(pathOrName, ec)) {
        throw SceneError(fmt::format("{}: is a directory, not a scene file (.gltf or .glb)", pathOrName));
    } else {
        throw SceneError(fmt::format("scene file not found: {}", pathOrName));
    }
    addDefaultsIfMissing(scene);
    return scene;
}

}  // namespace penumbra
