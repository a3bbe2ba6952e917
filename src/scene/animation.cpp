#include "scene/animation.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/builders.h"

namespace penumbra {
namespace {

// Shorter-arc spherical interpolation of unit quaternions stored as (x, y, z, w).
glm::vec4 slerp(glm::vec4 a, glm::vec4 b, float u) {
    float d = glm::dot(a, b);
    if (d < 0.0f) b = -b, d = -d;
    if (d > 0.9995f) return glm::normalize(glm::mix(a, b, u));  // nearly equal: lerp is exact to float
    const float theta = std::acos(std::clamp(d, -1.0f, 1.0f));
    const float s = std::sin(theta);
    return (std::sin((1.0f - u) * theta) / s) * a + (std::sin(u * theta) / s) * b;
}

glm::quat toQuat(const glm::vec4& v) { return glm::quat(v.w, v.x, v.y, v.z); }

// The scene nodes each glTF node became (a node reached twice in a malformed file became two).
std::vector<std::vector<uint32_t>> nodesBySource(const Scene& scene) {
    int32_t count = 0;
    for (const Node& n : scene.nodes) count = std::max(count, n.sourceNode + 1);
    std::vector<std::vector<uint32_t>> out(static_cast<size_t>(count));
    for (uint32_t i = 0; i < scene.nodes.size(); ++i)
        if (scene.nodes[i].sourceNode >= 0) out[size_t(scene.nodes[i].sourceNode)].push_back(i);
    return out;
}

}  // namespace

glm::mat4 Node::local() const {
    if (matrix) return *matrix;
    return glm::translate(glm::mat4(1.0f), translation) * glm::mat4_cast(rotation) *
           glm::scale(glm::mat4(1.0f), scale);
}

glm::vec4 sampleChannel(const AnimationChannel& c, float t) {
    const size_t keys = c.times.size();
    const bool cubic = c.interpolation == Interpolation::CubicSpline;
    auto value = [&](size_t k) { return c.values[cubic ? 3 * k + 1 : k]; };
    if (keys == 0) return glm::vec4(0.0f);
    if (t <= c.times.front() || keys == 1) return value(0);
    if (t >= c.times.back()) return value(keys - 1);
    const size_t k = size_t(std::upper_bound(c.times.begin(), c.times.end(), t) - c.times.begin()) - 1;
    const float dt = c.times[k + 1] - c.times[k];
    const float u = dt > 0.0f ? (t - c.times[k]) / dt : 0.0f;
    const bool rotation = c.path == AnimationPath::Rotation;
    switch (c.interpolation) {
        case Interpolation::Step: return value(k);
        case Interpolation::Linear:
            return rotation ? slerp(value(k), value(k + 1), u) : glm::mix(value(k), value(k + 1), u);
        case Interpolation::CubicSpline: {
            const float u2 = u * u, u3 = u2 * u;
            const glm::vec4 outTangent = c.values[3 * k + 2], inTangent = c.values[3 * (k + 1)];
            const glm::vec4 p = (2 * u3 - 3 * u2 + 1) * value(k) + (u3 - 2 * u2 + u) * dt * outTangent +
                                (-2 * u3 + 3 * u2) * value(k + 1) + (u3 - u2) * dt * inTangent;
            return rotation ? glm::normalize(p) : p;
        }
    }
    return value(k);
}

float animationLocalTime(const Animation& a, double t, bool clamp) {
    if (!(a.duration > 0.0f)) return 0.0f;
    if (clamp) return float(std::clamp(t, 0.0, double(a.duration)));
    const double wrapped = std::fmod(t, double(a.duration));
    return float(wrapped < 0.0 ? wrapped + a.duration : wrapped);
}

std::vector<glm::mat4> nodeWorldTransforms(const Scene& scene, double t, const AnimationOptions& options) {
    std::vector<Node> nodes = scene.nodes;  // local TRS at time t
    if (!scene.animations.empty()) {
        const std::vector<std::vector<uint32_t>> bySource = nodesBySource(scene);
        for (size_t a = 0; a < scene.animations.size(); ++a) {
            if (options.animation >= 0 && size_t(options.animation) != a) continue;
            const Animation& anim = scene.animations[a];
            const float local = animationLocalTime(anim, t, options.clamp);
            for (const AnimationChannel& c : anim.channels) {
                if (c.sourceNode < 0 || size_t(c.sourceNode) >= bySource.size()) continue;
                const glm::vec4 v = sampleChannel(c, local);
                for (uint32_t n : bySource[size_t(c.sourceNode)]) {
                    if (c.path == AnimationPath::Translation) nodes[n].translation = glm::vec3(v);
                    else if (c.path == AnimationPath::Rotation) nodes[n].rotation = glm::normalize(toQuat(v));
                    else nodes[n].scale = glm::vec3(v);
                }
            }
        }
    }
    std::vector<glm::mat4> world(nodes.size());
    for (size_t i = 0; i < nodes.size(); ++i) {  // parents come first: one pass, no recursion
        const glm::mat4 local = nodes[i].local();
        world[i] = nodes[i].parent >= 0 ? world[size_t(nodes[i].parent)] * local : local;
    }
    return world;
}

std::vector<glm::mat4> instanceTransforms(const Scene& scene, const std::vector<glm::mat4>& nodeWorld) {
    std::vector<glm::mat4> out;
    out.reserve(scene.instances.size());
    for (const Instance& i : scene.instances)
        out.push_back(i.node >= 0 && size_t(i.node) < nodeWorld.size() ? nodeWorld[size_t(i.node)] : glm::mat4(1.0f));
    return out;
}

void placeOnNodes(const Scene&, const std::vector<glm::mat4>& nodeWorld, std::vector<Light>& lights) {
    for (Light& l : lights) {
        if (l.node < 0 || size_t(l.node) >= nodeWorld.size()) continue;
        const glm::mat4& w = nodeWorld[size_t(l.node)];
        l.position = glm::vec3(w[3]);
        const glm::vec3 d = glm::mat3(w) * glm::vec3(0, 0, -1);  // lights shine down their node's -Z
        if (glm::dot(d, d) > 1e-30f) l.direction = glm::normalize(d);
    }
}

void placeOnNodes(const Scene&, const std::vector<glm::mat4>& nodeWorld, Camera& cam) {
    if (cam.node < 0 || size_t(cam.node) >= nodeWorld.size()) return;
    const glm::mat4& w = nodeWorld[size_t(cam.node)];
    const float distance = std::max(glm::length(cam.target - cam.eye), 1e-3f);
    const glm::vec3 forward = glm::mat3(w) * glm::vec3(0, 0, -1), up = glm::mat3(w) * glm::vec3(0, 1, 0);
    if (!(glm::dot(forward, forward) > 1e-30f) || !(glm::dot(up, up) > 1e-30f)) return;
    cam.eye = glm::vec3(w[3]);
    cam.target = cam.eye + glm::normalize(forward) * distance;
    cam.up = glm::normalize(up);
}

bool isAnimated(const Scene& scene) {
    for (const Animation& a : scene.animations)
        if (!a.channels.empty()) return true;
    return false;
}

Scene worldSpaceScene(const Scene& scene, const std::vector<glm::mat4>& transforms) {
    Scene out = scene;
    out.vertices.clear();
    out.indices.clear();
    out.draws.clear();
    std::vector<uint32_t> remap(scene.vertices.size(), UINT32_MAX);
    for (size_t i = 0; i < scene.instances.size() && i < transforms.size(); ++i) {
        const Mesh& mesh = scene.meshes[scene.instances[i].mesh];
        const glm::mat4& m = transforms[i];
        const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(m)));
        const bool mirrored = glm::determinant(glm::mat3(m)) < 0.0f;
        // The mesh's vertices in their own order (as baking at load would give), then its triangles,
        // wound the other way when the transform mirrors.
        std::vector<uint32_t> used;
        for (uint32_t d = mesh.firstDraw; d < mesh.firstDraw + mesh.drawCount; ++d)
            for (uint32_t k = 0; k < scene.draws[d].indexCount; ++k) used.push_back(scene.indices[scene.draws[d].firstIndex + k]);
        std::sort(used.begin(), used.end());
        used.erase(std::unique(used.begin(), used.end()), used.end());
        for (uint32_t src : used) {
            remap[src] = uint32_t(out.vertices.size());
            Vertex v = scene.vertices[src];
            v.position = glm::vec3(m * glm::vec4(v.position, 1.0f));
            const glm::vec3 n = normalMatrix * v.normal;
            if (glm::dot(n, n) > 1e-30f) v.normal = glm::normalize(n);
            out.vertices.push_back(v);
        }
        for (uint32_t d = mesh.firstDraw; d < mesh.firstDraw + mesh.drawCount; ++d) {
            const Draw& draw = scene.draws[d];
            const Draw copy{uint32_t(out.indices.size()), draw.indexCount, draw.material};
            for (uint32_t k = 0; k < draw.indexCount; ++k)
                out.indices.push_back(remap[scene.indices[draw.firstIndex + (mirrored ? (k / 3 * 3 + (3 - k % 3) % 3) : k)]]);
            if (!out.draws.empty() && out.draws.back().material == copy.material) out.draws.back().indexCount += copy.indexCount;
            else out.draws.push_back(copy);
        }
    }
    mergeDrawsByMaterial(out);
    out.nodes.clear();
    out.meshes.clear();
    out.instances.clear();
    out.animations.clear();
    for (Light& l : out.lights) l.node = -1;
    for (Camera& c : out.cameras) c.node = -1;
    ensureSceneGraph(out);
    return out;
}

Bounds animatedBounds(const Scene& scene) {
    Bounds b;
    for (const glm::vec3& p : scene.strandPoints) b.extend(p);
    std::vector<double> times{0.0};
    for (const Animation& a : scene.animations)
        for (int k = 1; k <= 64; ++k) times.push_back(a.duration * k / 64.0);
    for (double t : times) {
        const std::vector<glm::mat4> m = instanceTransforms(scene, nodeWorldTransforms(scene, t, {-1, true}));
        for (size_t i = 0; i < scene.instances.size(); ++i) {
            const Bounds& mb = scene.meshes[scene.instances[i].mesh].bounds;
            if (mb.empty()) continue;
            for (int c = 0; c < 8; ++c)
                b.extend(glm::vec3(m[i] * glm::vec4((c & 1) ? mb.max.x : mb.min.x, (c & 2) ? mb.max.y : mb.min.y,
                                                    (c & 4) ? mb.max.z : mb.min.z, 1.0f)));
        }
    }
    return b;
}

}  // namespace penumbra
