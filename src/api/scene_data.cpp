#include <cmath>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

#include "api/convert.h"
#include "api/impl.h"
#include "scene/motion.h"

namespace penumbra::api {

namespace {

static_assert(sizeof(Vertex) == sizeof(penumbra::Vertex) && offsetof(Vertex, normal) == offsetof(penumbra::Vertex, normal) &&
              offsetof(Vertex, uv) == offsetof(penumbra::Vertex, uv));

void require(bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("scene from memory: " + what);
}

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Unit length, or an error for a zero or non-finite vector; counts those it had to scale.
glm::vec3 unit(const Vec3& v, const std::string& what, size_t& scaled) {
    const glm::vec3 g(v.x, v.y, v.z);
    const float length = glm::length(g);
    require(finite(v) && length > 0.0f, fmt::format("{} is zero or not finite", what));
    if (std::abs(length - 1.0f) <= 1e-3f) return g;  // as given: a scene's own unit vectors keep their bits
    ++scaled;
    return g / length;
}

void checkGeometry(const SceneDesc& d) {
    require(!d.vertices.empty() && !d.indices.empty(), "no vertices or no indices");
    for (size_t i = 0; i < d.vertices.size(); ++i)
        require(finite(d.vertices[i].position), fmt::format("vertex {}'s position is not finite", i));
    for (size_t i = 0; i < d.indices.size(); ++i)
        require(d.indices[i] < d.vertices.size(),
                fmt::format("index {} is {}, past the {} vertices", i, d.indices[i], d.vertices.size()));
    for (size_t i = 0; i < d.draws.size(); ++i) {
        const Draw& draw = d.draws[i];
        require(draw.indexCount > 0 && draw.indexCount % 3 == 0,
                fmt::format("draw {} has {} indices, not whole triangles", i, draw.indexCount));
        require(uint64_t(draw.firstIndex) + draw.indexCount <= d.indices.size(),
                fmt::format("draw {} reaches past the {} indices", i, d.indices.size()));
        require(draw.material < std::max<size_t>(d.materials.size(), 1),
                fmt::format("draw {} names material {} of {}", i, draw.material, d.materials.size()));
    }
    for (size_t i = 0; i < d.materials.size(); ++i)
        require(d.materials[i].baseColorTexture < int32_t(d.textures.size()),
                fmt::format("material {} names texture {} of {}", i, d.materials[i].baseColorTexture, d.textures.size()));
    for (size_t i = 0; i < d.textures.size(); ++i)
        require(d.textures[i].width > 0 && d.textures[i].height > 0 &&
                    d.textures[i].rgba8.size() == size_t(d.textures[i].width) * d.textures[i].height * 4,
                fmt::format("texture {} is not width x height RGBA8 texels", i));
}

penumbra::Scene buildScene(const SceneDesc& d) {
    checkGeometry(d);
    penumbra::Scene s;
    s.name = d.name;
    s.vertices.resize(d.vertices.size());
    std::memcpy(s.vertices.data(), d.vertices.data(), d.vertices.size() * sizeof(Vertex));
    size_t scaled = 0;
    for (size_t i = 0; i < d.vertices.size(); ++i)
        s.vertices[i].normal = unit(d.vertices[i].normal, fmt::format("vertex {}'s normal", i), scaled);
    s.indices = d.indices;
    for (const Draw& draw : d.draws) s.draws.push_back({draw.firstIndex, draw.indexCount, draw.material});
    if (d.draws.empty()) {
        require(d.indices.size() % 3 == 0, fmt::format("{} indices are not whole triangles", d.indices.size()));
        s.draws.push_back({0, uint32_t(d.indices.size()), 0});
    }
    for (const Material& m : d.materials) {
        penumbra::Material& out = s.materials.emplace_back();
        std::memcpy(&out.baseColor, m.baseColor, sizeof(m.baseColor));
        out.baseColorTexture = m.baseColorTexture;
        out.alphaMode = penumbra::AlphaMode(m.alphaMode);
        out.alphaCutoff = m.alphaCutoff;
        out.doubleSided = m.doubleSided;
    }
    for (const Texture& t : d.textures) s.textures.push_back({t.width, t.height, t.rgba8});
    for (size_t i = 0; i < d.lights.size(); ++i) {
        penumbra::Light& l = s.lights.emplace_back(toInternal(d.lights[i]));
        l.direction = unit(d.lights[i].direction, fmt::format("light {}'s direction", i), scaled);
        l.name = fmt::format("light {}", i);
    }
    for (const Camera& c : d.cameras) s.cameras.push_back(toInternal(c));
    if (scaled > 0)
        s.warnings.push_back(fmt::format("scene from memory: {} normals and directions scaled to unit length", scaled));
    penumbra::ensureSceneGraph(s);
    s.computeBounds();
    penumbra::addDefaultsIfMissing(s);
    return s;
}

}  // namespace

SceneData SceneData::fromGltf(const std::string& path) {
    auto impl = std::make_shared<Impl>();
    impl->scene = penumbra::loadGltf(path);
    penumbra::addDefaultsIfMissing(impl->scene);
    return SceneData(std::move(impl));
}

SceneData SceneData::builtin(const std::string& name) {
    auto impl = std::make_shared<Impl>();
    impl->scene = penumbra::makeBuiltinScene(name);
    penumbra::addDefaultsIfMissing(impl->scene);
    return SceneData(std::move(impl));
}

SceneData SceneData::fromMemory(const SceneDesc& desc) {
    auto impl = std::make_shared<Impl>();
    impl->scene = buildScene(desc);
    return SceneData(std::move(impl));
}

Frame SceneData::frame(double time) const {
    const penumbra::Scene& s = impl_->scene;
    const penumbra::SceneMotion motion(s, s.cameras.at(0), s.lights, penumbra::MotionPaths{}, penumbra::AnimationOptions{});
    const penumbra::ScenePose pose = motion.at(time);
    return fromInternal(pose.camera, pose.lights, pose.instances);
}

const std::string& SceneData::name() const { return impl_->scene.name; }
size_t SceneData::triangleCount() const { return impl_->scene.drawnTriangleCount(); }
const std::vector<std::string>& SceneData::warnings() const { return impl_->scene.warnings; }

}  // namespace penumbra::api
