// glTF 2.0 (.gltf / .glb) loading through tinygltf. The Debian libtinygltf.so is built with its
// defaults (stb_image and stb_image_write enabled, filesystem callbacks on), so the header is
// included without any TINYGLTF_* defines: defining TINYGLTF_NO_STB_IMAGE here would leave the
// loader without an image decoder.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <optional>
#include <unordered_set>

#include <fmt/format.h>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <tiny_gltf.h>

#include "io/one_line.h"
#include "scene/builders.h"
#include "scene/gltf_accessor.h"
#include "scene/gltf_checks.h"
#include "scene/gltf_images.h"
#include "scene/gltf_lights.h"
#include "scene/gltf_primitives.h"
#include "scene/gltf_texture_transform.h"
#include "scene/scene.h"

namespace penumbra {

namespace {

constexpr int kMaxNodeDepth = 1024;  // deeper hierarchies are treated as malformed (and spare the stack)
// World coordinates beyond this overflow lengths, bounds and matrices in single precision (NaN
// images); the CLI's numbers have the same limit.
constexpr float kMaxCoordinate = 1e9f;

// Required extensions that change nothing we read, or whose data we read anyway.
bool isTolerableRequiredExtension(const std::string& name) {
    static const std::array<const char*, 6> ok{"KHR_lights_punctual", "KHR_mesh_quantization",
                                               "KHR_materials_emissive_strength", "KHR_materials_unlit",
                                               "KHR_texture_transform", "KHR_materials_ior"};
    return std::find(ok.begin(), ok.end(), name) != ok.end();
}

// tinygltf's file reader for buffers and images, refusing directories (reading one as a buffer
// gave std::bad_alloc).
bool readRegularFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        if (err) *err += "'" + path + "' is a directory, not a file\n";
        return false;
    }
    return tinygltf::ReadWholeFile(out, err, path, user);
}

std::vector<uint8_t> readFile(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw SceneError(fmt::format("{}: is a directory, not a scene file (.gltf or .glb)", path));
    if (!std::filesystem::is_regular_file(path, ec)) throw SceneError(fmt::format("scene file not found: {}", path));
    const uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec || size >= (uintmax_t(1) << 32))
        throw SceneError(fmt::format("{}: cannot read it (glTF files are at most 4 GiB)", path));
    std::vector<uint8_t> bytes(size);
    std::ifstream f(path, std::ios::binary);
    if (!f.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size)))
        throw SceneError(fmt::format("{}: cannot read it", path));
    return bytes;
}

tinygltf::Model parseFile(const std::string& path) {
    const std::vector<uint8_t> bytes = readFile(path);
    // Sniff the content rather than trusting the extension (GLB bytes load whatever the name), but a
    // .glb without the magic gets a clear message instead of a JSON parse error about binary junk.
    const bool glb = bytes.size() >= 4 && std::equal(bytes.begin(), bytes.begin() + 4, "glTF");
    if (!glb && std::filesystem::path(path).extension() == ".glb")
        throw SceneError(fmt::format("{}: invalid glTF: not a binary glTF file (no 'glTF' magic)", path));
    try {
        gltf::checkJson(gltf::jsonText(bytes, glb));  // before tinygltf's recursive parser sees it
    } catch (const SceneError& e) {
        throw SceneError(fmt::format("{}: {}", path, e.what()));
    }
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(gltf::keepEncodedImage, &model);  // decoded later, in parallel, if used
    loader.SetFsCallbacks({&tinygltf::FileExists, &tinygltf::ExpandFilePath, &readRegularFile,
                           &tinygltf::WriteWholeFile, nullptr});
    std::string err, warn;
    bool ok = false;
    const std::string baseDir = std::filesystem::path(path).parent_path().string();
    try {
        ok = glb ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), baseDir)
                 : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                              unsigned(bytes.size()), baseDir);
    } catch (const std::exception& e) {
        throw SceneError(fmt::format("{}: invalid glTF: {}", path, oneLine(e.what())));
    }
    // Warnings (e.g. an image file that could not be read) are not fatal; decodeImages names the
    // textures that are dropped.
    if (!ok) throw SceneError(fmt::format("{}: invalid glTF: {}", path, oneLine(err.empty() ? warn : err)));
    for (const std::string& ext : model.extensionsRequired)
        if (!isTolerableRequiredExtension(ext))
            throw SceneError(fmt::format("{}: requires unsupported glTF extension {}", path, ext));
    return model;
}


// Unit vector or `fallback` when v is zero, tiny or not finite (degenerate input must not give NaNs).
glm::vec3 safeNormalize(const glm::vec3& v, const glm::vec3& fallback) {
    const float len2 = glm::dot(v, v);
    if (!(len2 > 1e-30f) || !std::isfinite(len2)) return fallback;
    return v / std::sqrt(len2);
}

// Walks the node hierarchy once, appending world-space geometry, lights and cameras to the scene.
class Loader {
public:
    Loader(const tinygltf::Model& model, Scene& scene, std::vector<std::optional<Texture>> images)
        : m_(model), s_(scene), images_(std::move(images)), imageTexture_(model.images.size(), kNotConverted),
          onPath_(model.nodes.size()),
          quantized_(std::count(model.extensionsUsed.begin(), model.extensionsUsed.end(), "KHR_mesh_quantization")) {}

    void run() {
        checkVersion();
        loadMaterials();
        readAnimations();
        for (int root : withoutRepeats(rootNodes(), "the scene")) visitTree(root);
        if (!m_.skins.empty()) warn("skins are not supported: skinned meshes are drawn in their bind pose");
        placeGeometry();
    }

private:
    static constexpr int32_t kNotConverted = -2;

    // glTF 2.x is what this loader reads; another major version (or a newer minVersion) is read as 2.0.
    void checkVersion() {
        const auto major = [](const std::string& v) { return v.substr(0, v.find('.')); };
        const std::string& version = m_.asset.version;
        if (major(version) != "2")
            warn(fmt::format("asset.version '{}' is not 2.x: read as glTF 2.0", version));
        const std::string& minVersion = m_.asset.minVersion;
        if (!minVersion.empty() && minVersion != "2.0")
            warn(fmt::format("asset.minVersion '{}' is newer than glTF 2.0: read as glTF 2.0", minVersion));
    }

    std::vector<int> rootNodes() const {
        if (!m_.scenes.empty()) {
            const int si = m_.defaultScene >= 0 ? m_.defaultScene : 0;
            if (size_t(si) >= m_.scenes.size()) throw SceneError(fmt::format("default scene {} does not exist", si));
            return m_.scenes[size_t(si)].nodes;
        }
        // No scenes: every node that is nobody's child is a root.
        std::vector<bool> isChild(m_.nodes.size());
        for (const auto& n : m_.nodes)
            for (int c : n.children)
                if (c >= 0 && size_t(c) < isChild.size()) isChild[size_t(c)] = true;
        std::vector<int> roots;
        for (size_t i = 0; i < m_.nodes.size(); ++i)
            if (!isChild[i]) roots.push_back(int(i));
        return roots;
    }

    void loadMaterials() {
        ensureDefaultMaterial(s_);  // index 0; glTF material k becomes k + 1
        for (const tinygltf::Material& gm : m_.materials) {
            Material mat;
            const auto& f = gm.pbrMetallicRoughness.baseColorFactor;
            if (f.size() == 4) mat.baseColor = glm::vec4(f[0], f[1], f[2], f[3]);
            mat.baseColorTexture = textureFor(gm.pbrMetallicRoughness.baseColorTexture.index);
            uvTransforms_.push_back(gltf::readUvTransform(gm.pbrMetallicRoughness.baseColorTexture,
                                                          fmt::format("material {} baseColorTexture", s_.materials.size() - 1)));
            if (gm.alphaMode == "MASK") mat.alphaMode = AlphaMode::Mask;
            else if (gm.alphaMode == "BLEND") mat.alphaMode = AlphaMode::Blend;
            mat.alphaCutoff = float(gm.alphaCutoff);
            mat.doubleSided = gm.doubleSided;
            s_.materials.push_back(mat);
        }
    }

    // Scene texture index for glTF texture `index`, converting each image once; -1 when none/unusable.
    int32_t textureFor(int index) {
        if (index < 0) return -1;
        if (size_t(index) >= m_.textures.size()) throw SceneError(fmt::format("texture {} does not exist", index));
        const int source = m_.textures[size_t(index)].source;
        if (source < 0) return -1;  // e.g. only an extension image (basisu, webp) that we do not decode
        if (size_t(source) >= m_.images.size()) throw SceneError(fmt::format("image {} does not exist", source));
        int32_t& slot = imageTexture_[size_t(source)];
        if (slot == kNotConverted) {
            std::optional<Texture>& tex = images_[size_t(source)];
            slot = -1;  // not decoded (decodeImages warned): render untextured
            if (tex) {
                slot = int32_t(s_.textures.size());
                s_.textures.push_back(std::move(*tex));
            }
        }
        return slot;
    }

    // Depth-first over the tree under `root` with an explicit stack (a file cannot deepen the call
    // stack); each node is entered (recorded as a Scene node, parents before children) and later left
    // (taken off the root-to-node path that detects cycles).
    void visitTree(int root) {
        struct Step {
            int node;
            int32_t parent;  // Scene::nodes index of the parent, -1 for the root
            int depth;
            bool leave;
        };
        std::vector<Step> stack{{root, -1, 0, false}};
        while (!stack.empty()) {
            const Step step = stack.back();
            stack.pop_back();
            if (step.leave) {
                onPath_[size_t(step.node)] = false;
                continue;
            }
            const int index = step.node;
            if (index < 0 || size_t(index) >= m_.nodes.size())
                throw SceneError(fmt::format("node {} does not exist", index));
            if (onPath_[size_t(index)] || step.depth > kMaxNodeDepth)
                throw SceneError(fmt::format("node hierarchy is cyclic or too deep at node {}", index));
            onPath_[size_t(index)] = true;
            const tinygltf::Node& node = m_.nodes[size_t(index)];
            const int32_t self = addNode(node, index, step.parent);
            const glm::mat4& world = restWorld_.back();
            if (node.mesh >= 0) {
                if (size_t(node.mesh) >= m_.meshes.size())
                    throw SceneError(fmt::format("mesh {} does not exist", node.mesh));
                ++meshUses_[size_t(node.mesh)];
            }
            if (node.camera >= 0) addCamera(node.camera, world, self);
            addLight(node, world, self);
            stack.push_back({index, self, step.depth, true});
            const std::vector<int> children = withoutRepeats(node.children, fmt::format("node {}", index));
            for (auto child = children.rbegin(); child != children.rend(); ++child)
                stack.push_back({*child, self, step.depth + 1, false});  // reversed: visited in file order
        }
    }

    int32_t addNode(const tinygltf::Node& node, int index, int32_t parent) {
        Node n;
        n.parent = parent;
        n.sourceNode = index;
        n.mesh = node.mesh;
        n.name = node.name;
        if (node.matrix.size() == 16) n.matrix = glm::mat4(glm::make_mat4(node.matrix.data()));
        if (node.translation.size() == 3) n.translation = glm::vec3(node.translation[0], node.translation[1], node.translation[2]);
        if (node.rotation.size() == 4) {
            // glTF stores (x, y, z, w); glm's constructor takes w first.
            const glm::quat q(float(node.rotation[3]), float(node.rotation[0]), float(node.rotation[1]),
                              float(node.rotation[2]));
            if (glm::length(q) > 0.0f) n.rotation = glm::normalize(q);
        }
        if (node.scale.size() == 3) n.scale = glm::vec3(node.scale[0], node.scale[1], node.scale[2]);
        const int32_t self = int32_t(s_.nodes.size());
        restWorld_.push_back(parent >= 0 ? restWorld_[size_t(parent)] * n.local() : n.local());
        const glm::mat4& world = restWorld_.back();
        if (!std::all_of(&world[0][0], &world[0][0] + 16, [](float x) { return std::isfinite(x); }))
            throw SceneError(fmt::format("node {}: its world transform is not finite", index));
        moving_.push_back(animatedSource_[size_t(index)] || (parent >= 0 && moving_[size_t(parent)]));
        s_.nodes.push_back(std::move(n));
        return self;
    }

    // Static batching (scene.h): a mesh drawn by one node that no animation moves is baked into mesh 0
    // in world space; every other mesh keeps one local-space copy drawn per instance. Lines (hair) are
    // always baked at the rest pose.
    void placeGeometry() {
        auto instanced = [&](size_t n) { return moving_[n] || meshUses_[size_t(s_.nodes[n].mesh)] > 1; };
        for (size_t n = 0; n < s_.nodes.size(); ++n)
            if (s_.nodes[n].mesh >= 0) addMesh(s_.nodes[n].mesh, restWorld_[n], instanced(n) ? kLines : kEverything);
        mergeDrawsByMaterial(s_);
        s_.meshes = {Mesh{0, uint32_t(s_.draws.size()), {}}};
        s_.instances = {Instance{0, -1}};
        std::vector<int32_t> meshOf(m_.meshes.size(), -1);
        for (size_t n = 0; n < s_.nodes.size(); ++n) {
            if (s_.nodes[n].mesh < 0 || !instanced(n)) continue;
            int32_t& mesh = meshOf[size_t(s_.nodes[n].mesh)];
            if (mesh < 0) {
                const uint32_t first = uint32_t(s_.draws.size());
                newDraw_ = true;  // never merged into the previous mesh's last draw
                addMesh(s_.nodes[n].mesh, glm::mat4(1.0f), kTriangles);
                mesh = int32_t(s_.meshes.size());
                s_.meshes.push_back(Mesh{first, uint32_t(s_.draws.size()) - first, {}});
            }
            s_.instances.push_back(Instance{uint32_t(mesh), int32_t(n)});
        }
        // Instances of one mesh side by side: each mesh is one instanced draw per pass (SceneGpu::draw).
        std::stable_sort(s_.instances.begin(), s_.instances.end(),
                         [](const Instance& a, const Instance& b) { return a.mesh < b.mesh; });
    }

    void readAnimations() {
        animatedSource_.assign(m_.nodes.size(), false);
        for (size_t a = 0; a < m_.animations.size(); ++a) {
            const tinygltf::Animation& ga = m_.animations[a];
            Animation anim;
            anim.name = ga.name;
            for (size_t c = 0; c < ga.channels.size(); ++c) {
                const tinygltf::AnimationChannel& gc = ga.channels[c];
                const std::string what = fmt::format("animation {} channel {}", a, c);
                if (gc.target_path == "weights") {
                    warn("morph-target weight animations are not supported: meshes keep their default weights");
                    continue;
                }
                AnimationChannel ch;
                if (gc.target_path == "translation") ch.path = AnimationPath::Translation;
                else if (gc.target_path == "rotation") ch.path = AnimationPath::Rotation;
                else if (gc.target_path == "scale") ch.path = AnimationPath::Scale;
                else throw SceneError(fmt::format("{}: unknown target path '{}'", what, gc.target_path));
                if (gc.target_node < 0) continue;  // glTF allows a channel without a node (an extension's target)
                if (size_t(gc.target_node) >= m_.nodes.size()) {
                    warn(fmt::format("{}: target node {} does not exist ({} nodes): the channel is dropped", what,
                                     gc.target_node, m_.nodes.size()));
                    continue;
                }
                if (gc.sampler < 0 || size_t(gc.sampler) >= ga.samplers.size())
                    throw SceneError(fmt::format("{}: sampler {} does not exist", what, gc.sampler));
                readSampler(ga.samplers[size_t(gc.sampler)], ch, what);
                ch.sourceNode = gc.target_node;
                anim.duration = std::max(anim.duration, ch.times.back());
                animatedSource_[size_t(gc.target_node)] = true;
                anim.channels.push_back(std::move(ch));
            }
            s_.animations.push_back(std::move(anim));
        }
    }

    void readSampler(const tinygltf::AnimationSampler& gs, AnimationChannel& ch, const std::string& what) {
        if (gs.interpolation == "STEP") ch.interpolation = Interpolation::Step;
        else if (gs.interpolation == "CUBICSPLINE") ch.interpolation = Interpolation::CubicSpline;
        else if (gs.interpolation.empty() || gs.interpolation == "LINEAR") ch.interpolation = Interpolation::Linear;
        else throw SceneError(fmt::format("{}: unknown interpolation '{}'", what, gs.interpolation));
        ch.times = gltf::readFloats(m_, gs.input, 1, what + " input");
        if (ch.times.empty()) throw SceneError(fmt::format("{}: no keys", what));
        for (size_t k = 0; k < ch.times.size(); ++k)
            if (!std::isfinite(ch.times[k]) || ch.times[k] < 0.0f || (k > 0 && ch.times[k] < ch.times[k - 1]))
                throw SceneError(fmt::format("{}: key times must be finite, >= 0 and increasing", what));
        const int comps = ch.path == AnimationPath::Rotation ? 4 : 3;
        const std::vector<float> v = gltf::readFloats(m_, gs.output, comps, what + " output");
        const size_t perKey = ch.interpolation == Interpolation::CubicSpline ? 3 : 1;
        if (v.size() != ch.times.size() * perKey * size_t(comps))
            throw SceneError(fmt::format("{}: {} output values for {} keys", what, v.size() / size_t(comps),
                                         ch.times.size()));
        for (size_t i = 0; i < v.size(); i += size_t(comps)) {
            glm::vec4 value(v[i], v[i + 1], v[i + 2], comps == 4 ? v[i + 3] : 0.0f);
            if (!std::isfinite(value.x + value.y + value.z + value.w))
                throw SceneError(fmt::format("{}: output values must be finite", what));
            ch.values.push_back(value);
        }
    }

    static constexpr uint32_t kTriangles = 1, kLines = 2, kEverything = 3;

    void addMesh(int index, const glm::mat4& world, uint32_t kinds) {
        const auto& prims = m_.meshes[size_t(index)].primitives;
        for (size_t p = 0; p < prims.size(); ++p)
            addPrimitive(prims[p], world, fmt::format("mesh {} primitive {}", index, p), kinds);
    }

    std::vector<float> optionalAttribute(const tinygltf::Primitive& p, const char* name, int comps, size_t count,
                                         const std::string& what) {
        const auto it = p.attributes.find(name);
        if (it == p.attributes.end()) return {};
        gltf::checkAttributeType(m_, it->second, name, quantized_, what);
        std::vector<float> data = gltf::readFloats(m_, it->second, comps, what + " " + name);
        if (data.size() != count * size_t(comps))
            throw SceneError(fmt::format("{}: {} count differs from POSITION count", what, name));
        return data;
    }

    // The primitive's texture coordinates as its material's base-colour texture reads them: the set
    // it names, transformed (gltf_texture_transform.h); non-finite ones become 0 with a warning. A
    // textured material naming a set the primitive lacks reads its texture at (0, 0), with a warning.
    std::vector<float> texCoords(const tinygltf::Primitive& p, size_t n, uint32_t material, const std::string& what) {
        const gltf::UvTransform uvt = p.material >= 0 ? uvTransforms_[size_t(p.material)] : gltf::UvTransform{};
        const std::string set = fmt::format("TEXCOORD_{}", uvt.texCoord);
        std::vector<float> uv = optionalAttribute(p, set.c_str(), 2, n, what);
        if (uv.empty() && s_.materials[material].baseColorTexture >= 0)
            warn(fmt::format("{}: material {} reads {}, which the primitive lacks: its texture is read at (0, 0)",
                             what, p.material, set));
        size_t nonFinite = 0;
        for (size_t i = 0; i + 1 < uv.size(); i += 2) {
            glm::vec2 t = uvt.apply(glm::vec2(uv[i], uv[i + 1]));
            if (!std::isfinite(t.x + t.y)) t = glm::vec2(0.0f), ++nonFinite;
            uv[i] = t.x, uv[i + 1] = t.y;
        }
        if (nonFinite) warn(fmt::format("{}: {} texture coordinate(s) are not finite: set to 0", what, nonFinite));
        return uv;
    }

    // Vertex indices of a primitive (0..n-1 when it has none), each checked against n.
    std::vector<uint32_t> primitiveIndices(const tinygltf::Primitive& p, size_t n, const std::string& what) {
        std::vector<uint32_t> idx(n);
        if (p.indices >= 0) idx = gltf::readIndices(m_, p.indices);
        else std::iota(idx.begin(), idx.end(), 0u);
        for (uint32_t i : idx)
            if (i >= n) throw SceneError(fmt::format("{}: index {} out of range ({} vertices)", what, i, n));
        return idx;
    }

    // LINES / LINE_STRIP / LINE_LOOP: hair strands with the material's colour; a BLEND material's
    // alpha is the strand's opacity. glTF has no line width: the default strand width, scaled with the node.
    void addStrands(const tinygltf::Primitive& p, const std::vector<float>& pos, const glm::mat4& world, int mode,
                    const std::string& what) {
        Strand style;
        const Material& mat = s_.materials[size_t(p.material + 1)];
        style.color = glm::vec3(mat.baseColor);
        if (mat.alphaMode == AlphaMode::Blend) style.opacity = mat.baseColor.a;
        style.width *= std::cbrt(std::abs(glm::determinant(glm::mat3(world))));
        for (const std::vector<uint32_t>& line : gltf::toPolylines(primitiveIndices(p, pos.size() / 3, what), mode)) {
            std::vector<glm::vec3> points;
            for (uint32_t i : line)
                points.push_back(glm::vec3(world * glm::vec4(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2], 1.0f)));
            addStrand(s_, points, style);
        }
    }

    void addPrimitive(const tinygltf::Primitive& p, const glm::mat4& world, const std::string& what, uint32_t kinds) {
        const int mode = p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode;
        if (mode == TINYGLTF_MODE_POINTS) return;  // points are not drawn
        const auto posIt = p.attributes.find("POSITION");
        if (posIt == p.attributes.end()) return;  // nothing to draw
        gltf::checkAttributeType(m_, posIt->second, "POSITION", quantized_, what);
        const std::vector<float> pos = gltf::readFloats(m_, posIt->second, 3, what + " POSITION");
        const size_t n = pos.size() / 3;
        if (p.material < -1 || p.material >= int(m_.materials.size()))
            throw SceneError(fmt::format("{}: material {} does not exist", what, p.material));
        if (mode == TINYGLTF_MODE_LINE || mode == TINYGLTF_MODE_LINE_STRIP || mode == TINYGLTF_MODE_LINE_LOOP)
            return (kinds & kLines) ? addStrands(p, pos, world, mode, what) : void();
        if (!(kinds & kTriangles)) return;
        if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
            mode != TINYGLTF_MODE_TRIANGLE_FAN)
            return;  // unknown mode
        const std::vector<float> nrm = optionalAttribute(p, "NORMAL", 3, n, what);
        const uint32_t material = uint32_t(p.material + 1);
        const std::vector<float> uv = texCoords(p, n, material, what);
        std::vector<uint32_t> tris = gltf::toTriangleList(primitiveIndices(p, n, what), mode);
        // A mirroring transform turns counter-clockwise triangles clockwise; swap to keep them front-facing.
        const glm::mat3 linear(world);
        if (glm::determinant(linear) < 0.0f)
            for (size_t t = 0; t + 2 < tris.size(); t += 3) std::swap(tris[t + 1], tris[t + 2]);

        const glm::mat3 normalMatrix = glm::transpose(glm::inverse(linear));
        std::vector<Vertex> verts(n);
        for (size_t i = 0; i < n; ++i) {
            verts[i].position = glm::vec3(world * glm::vec4(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2], 1.0f));
            if (!nrm.empty()) verts[i].normal = normalMatrix * glm::vec3(nrm[3 * i], nrm[3 * i + 1], nrm[3 * i + 2]);
            verts[i].uv = uv.empty() ? glm::vec2(0.0f) : glm::vec2(uv[2 * i], uv[2 * i + 1]);
            if (!std::isfinite(verts[i].position.x + verts[i].position.y + verts[i].position.z) ||
                glm::any(glm::greaterThan(glm::abs(verts[i].position), glm::vec3(kMaxCoordinate))))
                throw SceneError(fmt::format("{}: vertex {} lies at ({}, {}, {}) in the world, not finite or beyond "
                                             "+-{:g}", what, i, verts[i].position.x, verts[i].position.y,
                                             verts[i].position.z, kMaxCoordinate));
        }
        if (nrm.empty()) gltf::generateNormals(verts, tris);
        for (Vertex& v : verts) v.normal = safeNormalize(v.normal, glm::vec3(0, 1, 0));
        addTriangles(s_, verts, tris, material, !newDraw_);
        newDraw_ = false;
    }

    void addLight(const tinygltf::Node& node, const glm::mat4& world, int32_t sceneNode) {
        const auto ext = node.extensions.find("KHR_lights_punctual");
        if (ext == node.extensions.end() || !ext->second.IsObject() || !ext->second.Has("light")) return;
        const tinygltf::Value& v = ext->second.Get("light");
        const int index = v.IsNumber() ? v.GetNumberAsInt() : -1;
        if (index < 0 || size_t(index) >= m_.lights.size())
            throw SceneError(fmt::format("node '{}' refers to missing light {}", node.name, index));
        std::optional<Light> light = gltf::readLight(m_, index, node.name, warner());
        if (!light) return;
        Light& l = *light;
        // Lights shine down their node's -Z; position is the node origin.
        l.position = glm::vec3(world[3]);
        l.direction = safeNormalize(glm::mat3(world) * glm::vec3(0, 0, -1), glm::vec3(0, -1, 0));
        l.node = sceneNode;
        s_.lights.push_back(std::move(l));
    }

    void addCamera(int index, const glm::mat4& world, int32_t sceneNode) {
        if (size_t(index) >= m_.cameras.size()) throw SceneError(fmt::format("camera {} does not exist", index));
        std::optional<Camera> camera = gltf::readCamera(m_, index, warner());
        if (!camera) return;
        Camera& cam = *camera;
        cam.node = sceneNode;
        cam.eye = glm::vec3(world[3]);
        const glm::vec3 forward = safeNormalize(glm::mat3(world) * glm::vec3(0, 0, -1), glm::vec3(0, 0, -1));
        cam.target = cam.eye + forward;  // distance fixed up once the bounds are known
        cam.up = safeNormalize(glm::mat3(world) * glm::vec3(0, 1, 0), glm::vec3(0, 1, 0));
        s_.cameras.push_back(cam);
    }

    // glTF lists each node once (scene.nodes and node.children are uniqueItems): a repeat would draw the
    // same triangles again on top of themselves (a file listing one node 200000 times rendered for
    // minutes), so repeats are skipped with one warning.
    std::vector<int> withoutRepeats(const std::vector<int>& nodes, const std::string& where) {
        std::vector<int> out;
        std::unordered_set<int> seen;
        for (int n : nodes)
            if (seen.insert(n).second) out.push_back(n);
        if (out.size() < nodes.size())
            warn(fmt::format("{} lists a node more than once: {} repeat(s) skipped (glTF lists each node once)", where,
                             nodes.size() - out.size()));
        return out;
    }

    // One line per dropped or changed thing, once even when many nodes refer to it.
    void warn(const std::string& line) {
        if (std::find(s_.warnings.begin(), s_.warnings.end(), line) == s_.warnings.end()) s_.warnings.push_back(line);
    }
    gltf::Warn warner() {
        return [this](const std::string& line) { warn(line); };
    }

    const tinygltf::Model& m_;
    Scene& s_;
    std::vector<std::optional<Texture>> images_;  // decoded glTF images (those materials use)
    std::vector<int32_t> imageTexture_;           // glTF image -> Scene::textures index
    std::vector<bool> onPath_;                    // nodes on the current root-to-node path (cycle detection)
    std::vector<bool> animatedSource_;            // glTF nodes an animation channel targets
    std::vector<uint32_t> meshUses_ = std::vector<uint32_t>(m_.meshes.size());  // nodes drawing each glTF mesh
    std::vector<glm::mat4> restWorld_;            // per Scene node: world transform at rest
    std::vector<bool> moving_;                    // per Scene node: it or an ancestor is animated
    bool newDraw_ = false;                        // the next triangles start a draw of their own
    bool quantized_;                              // KHR_mesh_quantization: integer positions, normals, uvs
    std::vector<gltf::UvTransform> uvTransforms_;   // per glTF material: its base-colour texture's uv set
};

// The glTF images that materials use as base colour: the only ones decoded.
std::vector<bool> usedImages(const tinygltf::Model& m) {
    std::vector<bool> used(m.images.size());
    for (const tinygltf::Material& mat : m.materials) {
        const int t = mat.pbrMetallicRoughness.baseColorTexture.index;
        if (t < 0 || size_t(t) >= m.textures.size()) continue;
        const int source = m.textures[size_t(t)].source;
        if (source >= 0 && size_t(source) < used.size()) used[size_t(source)] = true;
    }
    return used;
}

// glTF cameras have no target; put it at the distance of the scene centre so orbiting feels natural.
void placeCameraTargets(Scene& scene) {
    const glm::vec3 center = scene.bounds.center();
    for (Camera& cam : scene.cameras) {
        const glm::vec3 forward = cam.target - cam.eye;  // unit length from addCamera
        const float dist = std::max(glm::length(center - cam.eye), 1e-3f);
        cam.target = cam.eye + forward * dist;
    }
}

}  // namespace

Scene loadGltf(const std::string& path) {
    const tinygltf::Model model = parseFile(path);
    Scene scene;
    scene.name = std::filesystem::path(path).stem().string();
    try {
        Loader(model, scene, gltf::decodeImages(model, usedImages(model), scene.warnings)).run();
    } catch (const SceneError& e) {
        throw SceneError(fmt::format("{}: {}", path, e.what()));
    }
    if (scene.indices.empty() && scene.strands.empty())
        throw SceneError(fmt::format("{}: no triangles or lines in the default scene", path));
    scene.computeBounds();
    placeCameraTargets(scene);
    return scene;
}

}  // namespace penumbra
