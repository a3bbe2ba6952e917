// Built-in scenes that need no asset files: the default Cornell box, a plane for unit tests, a
// head with procedural hair (deep shadow maps) and a terrain of large ground triangles under trees.
#include <cmath>
#include <optional>
#include <random>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <glm/gtc/constants.hpp>

#include "scene/builders.h"
#include "scene/gi_scenes.h"
#include "scene/scene.h"

namespace penumbra {

namespace {

// Cornell box in a 2x2x2 room (x,z in [-1,1], y in [0,2]) open towards +z, with the classic
// wall colours (Jensen's reflectances); a spot light under the ceiling stands in for the area light.
Scene makeCornell() {
    Scene s;
    s.name = "cornell";
    const uint32_t white = addMaterial(s, {0.725f, 0.71f, 0.68f});
    const uint32_t red = addMaterial(s, {0.63f, 0.065f, 0.05f});
    const uint32_t green = addMaterial(s, {0.14f, 0.45f, 0.091f});

    // Walls face inward: each normal = normalize(cross(edgeU, edgeV)) points into the room.
    addQuad(s, {-1, 0, -1}, {0, 0, 2}, {2, 0, 0}, white);  // floor, +y
    addQuad(s, {-1, 2, -1}, {2, 0, 0}, {0, 0, 2}, white);  // ceiling, -y
    addQuad(s, {-1, 0, -1}, {2, 0, 0}, {0, 2, 0}, white);  // back wall, +z
    addQuad(s, {-1, 0, -1}, {0, 2, 0}, {0, 0, 2}, red);    // left wall, +x
    addQuad(s, {1, 0, -1}, {0, 0, 2}, {0, 2, 0}, green);   // right wall, -x

    // Boxes stand on the floor (centre y = half height) and are placed so they cannot intersect.
    addBox(s, {-0.38f, 0.6f, -0.38f}, {0.3f, 0.6f, 0.3f}, glm::radians(17.0f), white);
    addBox(s, {0.38f, 0.3f, 0.3f}, {0.3f, 0.3f, 0.3f}, glm::radians(-17.0f), white);

    Light spot;
    spot.type = LightType::Spot;
    spot.position = {0.0f, 1.9f, 0.0f};
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.intensity = 6.0f;
    spot.outerConeAngle = glm::radians(65.0f);
    spot.innerConeAngle = glm::radians(50.0f);
    spot.name = "ceiling spot";
    s.lights.push_back(spot);

    Camera cam;
    cam.eye = {0.0f, 1.0f, 3.6f};
    cam.target = {0.0f, 1.0f, 0.0f};
    cam.fovy = glm::radians(40.0f);
    s.cameras.push_back(cam);
    return s;
}

// Cornell with a 0.3 m box sliding across the back wall at 1 m/s, above the tall box (x from -0.75
// to 0.75 and back, 3 s a cycle): moving geometry for the temporal GI's ghosting. The box is mesh 1,
// drawn by node 0, which the animation moves.
Scene makeMovingCornell() {
    Scene s = makeCornell();
    s.name = "cornell-moving";
    const uint32_t staticDraws = uint32_t(s.draws.size());
    const uint32_t boxMaterial = addMaterial(s, {0.725f, 0.71f, 0.68f});  // its own draw: not merged
    addBox(s, glm::vec3(0.0f), glm::vec3(0.15f), 0.0f, boxMaterial);
    s.meshes = {Mesh{0, staticDraws, {}}, Mesh{staticDraws, uint32_t(s.draws.size()) - staticDraws, {}}};
    Node node;
    node.translation = {-0.75f, 1.5f, -0.8f};
    node.mesh = 1;
    node.sourceNode = 0;
    node.name = "sliding box";
    s.nodes = {node};
    s.instances = {Instance{0, -1}, Instance{1, 0}};
    AnimationChannel slide;
    slide.sourceNode = 0;
    slide.path = AnimationPath::Translation;
    slide.times = {0.0f, 1.5f, 3.0f};
    slide.values = {glm::vec4(-0.75f, 1.5f, -0.8f, 0.0f), glm::vec4(0.75f, 1.5f, -0.8f, 0.0f),
                    glm::vec4(-0.75f, 1.5f, -0.8f, 0.0f)};
    s.animations = {Animation{"slide", {slide}, 3.0f}};
    return s;
}

// 20x20 plane at y = 0 lit straight from above and seen straight from above: image x maps to
// world +x and image up to world -z, which keeps test expectations simple.
Scene makePlane() {
    Scene s;
    s.name = "plane";
    const uint32_t grey = addMaterial(s, glm::vec3(0.5f));
    addQuad(s, {-10, 0, -10}, {0, 0, 20}, {20, 0, 0}, grey);

    Light sun;
    sun.type = LightType::Directional;
    sun.direction = {0.0f, -1.0f, 0.0f};
    sun.intensity = 1.0f;
    sun.name = "sun";
    s.lights.push_back(sun);

    Camera cam;
    cam.eye = {0.0f, 15.0f, 0.0f};
    cam.target = {0.0f, 0.0f, 0.0f};
    cam.up = {0.0f, 0.0f, -1.0f};  // the view direction is -y, so +y cannot be up
    cam.fovy = glm::radians(60.0f);
    s.cameras.push_back(cam);
    return s;
}

// UV sphere with smooth outward normals; triangles whose centre satisfies `second` get `material2`.
template <class Pred>
void addSphere(Scene& s, const glm::vec3& center, float radius, uint32_t material, uint32_t material2, Pred second) {
    constexpr uint32_t kRings = 32, kSegments = 64;
    std::vector<Vertex> verts;
    std::vector<uint32_t> idx[2];
    for (uint32_t r = 0; r <= kRings; ++r) {
        const float theta = glm::pi<float>() * float(r) / kRings;
        for (uint32_t k = 0; k <= kSegments; ++k) {
            const float phi = glm::two_pi<float>() * float(k) / kSegments;
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
            verts.push_back({center + radius * n, n, {float(k) / kSegments, float(r) / kRings}});
        }
    }
    for (uint32_t r = 0; r < kRings; ++r)
        for (uint32_t k = 0; k < kSegments; ++k) {
            const uint32_t a = r * (kSegments + 1) + k, b = a + kSegments + 1;
            const glm::vec3 mid = glm::normalize(verts[a].normal + verts[b + 1].normal);
            idx[second(mid) ? 1 : 0].insert(idx[second(mid) ? 1 : 0].end(), {a, b, a + 1, a + 1, b, b + 1});
        }
    addTriangles(s, verts, idx[0], material);
    addTriangles(s, verts, idx[1], material2);  // its own copy of the vertices: indices stay local
}

// Where hair grows on a head looking along +z: above the ears, lower at the nape, not on the face.
bool onScalp(const glm::vec3& d) {
    const bool face = d.z > 0.45f && d.y < 0.62f;
    return !face && d.y > 0.08f - 0.55f * std::max(0.0f, -d.z);
}

// The component of v across the unit normal n (on the tangent plane), unit length; `fallback` if none.
glm::vec3 acrossNormal(const glm::vec3& v, const glm::vec3& n, const glm::vec3& fallback) {
    const glm::vec3 t = v - n * glm::dot(v, n);
    return glm::length(t) > 1e-4f ? glm::normalize(t) : fallback;
}

// The combed direction of hair at scalp normal n: a middle parting (x = 0), the hair falling to
// either side, down and a little back, which keeps it off the face.
glm::vec3 combDirection(const glm::vec3& n) {
    return acrossNormal(glm::vec3(n.x >= 0.0f ? 1.0f : -1.0f, -0.6f, -0.6f), n, glm::vec3(0.0f, -1.0f, 0.0f));
}

// Pushes p out of the head: the sphere above its centre, below it a vertical cylinder of the same
// radius (the hair hangs from the head's widest part instead of closing in under it). Returns the
// surface normal when p was inside.
std::optional<glm::vec3> pushOut(glm::vec3& p, const glm::vec3& c, float shell) {
    glm::vec3 v = p - c;
    if (v.y < 0.0f) v.y = 0.0f;
    const float len = glm::length(v);
    if (len >= shell || len < 1e-6f) return std::nullopt;
    const glm::vec3 n = v / len;
    p += n * (shell - len);
    return n;
}

// One strand grown from the scalp point `c + radius * d`: it leaves the scalp along the comb, lies on
// the head at its own height above the scalp (which gives the hair its volume), bends under gravity
// and hangs down with a slight wave.
std::vector<glm::vec3> growStrand(const glm::vec3& c, float radius, const glm::vec3& d, std::mt19937& rng) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    constexpr int kSegments = int(BuiltinOptions::kHairPointsPerStrand) - 1;
    const float length = 0.22f + 0.12f * u(rng);
    const float shell = radius * (1.04f + 0.22f * u(rng) * u(rng));  // denser near the scalp
    const float step = length / kSegments;
    const float wave = 0.006f * u(rng), phase = glm::two_pi<float>() * u(rng);
    const glm::vec3 waveDir = glm::normalize(glm::cross(d, glm::vec3(u(rng) - 0.5f, 0.3f, u(rng) - 0.5f)));
    glm::vec3 p = c + radius * d, dir = glm::normalize(combDirection(d) + 0.4f * d);
    std::vector<glm::vec3> points{p};
    for (int k = 1; k <= kSegments; ++k) {
        const glm::vec3 n = glm::normalize(p - c);
        const bool onHead = p.y > c.y && glm::length(p - c) < shell * 1.15f;
        const glm::vec3 comb = onHead ? 0.5f * combDirection(n) : glm::vec3(0.0f);
        dir = glm::normalize(dir + glm::vec3(0.0f, -0.25f, 0.0f) + comb);
        p += dir * step;
        if (const std::optional<glm::vec3> m = pushOut(p, c, shell)) dir = acrossNormal(dir, *m, dir);
        const float t = float(k) / kSegments;
        points.push_back(p + waveDir * (wave * t * std::sin(phase + 9.0f * t)));
    }
    return points;
}

// A head-sized sphere on a stand over a floor, `strands` hairs on its scalp, one spot light from
// the upper left: the hair shadows itself and the floor (the deep-shadow-map scene).
Scene makeHair(const BuiltinOptions& options) {
    Scene s;
    s.name = "hair";
    const uint32_t floor = addMaterial(s, glm::vec3(0.6f));
    const uint32_t skin = addMaterial(s, {0.62f, 0.42f, 0.33f});
    const uint32_t scalp = addMaterial(s, {0.1f, 0.06f, 0.035f});  // under the hair: no skin shows through
    addQuad(s, {-1.5f, 0, -1.5f}, {0, 0, 3}, {3, 0, 0}, floor);
    const glm::vec3 head(0.0f, 0.42f, 0.0f);
    const float radius = 0.1f;
    addSphere(s, head, radius, skin, scalp, onScalp);
    addBox(s, {0.0f, 0.16f, 0.0f}, {0.035f, 0.16f, 0.035f}, 0.0f, skin);

    std::mt19937 rng(2024);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::normal_distribution<float> gauss;
    for (uint32_t i = 0; i < options.hairStrands; ++i) {
        glm::vec3 d;
        do d = glm::normalize(glm::vec3(gauss(rng), gauss(rng), gauss(rng)));
        while (!onScalp(d));
        Strand style;
        style.width = 8e-5f;
        style.opacity = 0.6f;
        style.color = glm::vec3(0.42f, 0.27f, 0.15f) * (0.75f + 0.5f * u(rng));
        addStrand(s, growStrand(head, radius, d, rng), style);
    }

    Light spot;
    spot.type = LightType::Spot;
    spot.position = {-0.9f, 1.3f, -0.2f};
    spot.direction = glm::normalize(glm::vec3(0.0f, 0.3f, 0.0f) - spot.position);
    spot.intensity = 6.0f;
    spot.outerConeAngle = glm::radians(28.0f);
    spot.innerConeAngle = glm::radians(20.0f);
    spot.name = "key spot";
    s.lights.push_back(spot);

    Camera cam;
    cam.eye = {0.9f, 0.75f, -1.1f};  // from behind: the hair's volume, lit from the left
    cam.target = {0.0f, 0.3f, 0.0f};
    cam.fovy = glm::radians(35.0f);
    s.cameras.push_back(cam);
    return s;
}

// Ground height of the terrain scene: two gentle hills, so that its few large triangles are not coplanar.
float terrainHeight(float x, float z) {
    return 1.5f * std::exp(-((x - 12) * (x - 12) + (z + 8) * (z + 8)) / 300.0f) +
           1.0f * std::exp(-((x + 15) * (x + 15) + (z - 14) * (z - 14)) / 200.0f);
}

// A cone of `segments` side triangles and a base (a tree's crown layer), apex up.
void addCone(Scene& s, const glm::vec3& base, float radius, float height, uint32_t segments, uint32_t material) {
    std::vector<Vertex> verts;
    std::vector<uint32_t> idx;
    const glm::vec3 apex = base + glm::vec3(0, height, 0);
    for (uint32_t k = 0; k < segments; ++k) {
        const float a0 = glm::two_pi<float>() * float(k) / segments, a1 = glm::two_pi<float>() * float(k + 1) / segments;
        const glm::vec3 p0 = base + radius * glm::vec3(std::cos(a0), 0, -std::sin(a0));
        const glm::vec3 p1 = base + radius * glm::vec3(std::cos(a1), 0, -std::sin(a1));
        const glm::vec3 n = glm::normalize(glm::cross(p1 - p0, apex - p0));
        const uint32_t first = uint32_t(verts.size());
        verts.insert(verts.end(), {{p0, n, {0, 0}}, {p1, n, {1, 0}}, {apex, n, {0.5f, 1}}, {p0, {0, -1, 0}, {0, 0}},
                                   {base, {0, -1, 0}, {0.5f, 0.5f}}, {p1, {0, -1, 0}, {1, 0}}});
        idx.insert(idx.end(), {first, first + 1, first + 2, first + 3, first + 4, first + 5});
    }
    addTriangles(s, verts, idx, material);
}

// The compute rasterizer's hardest case: 18 ground triangles of about 20 m that each cover many
// tiles of every cascade, under 60 small trees (about 11k triangles: trunks and three-layer crowns)
// and a low sun, so that the trees' shadows fall long across the ground.
Scene makeTerrain() {
    Scene s;
    s.name = "terrain";
    const uint32_t grass = addMaterial(s, {0.30f, 0.42f, 0.18f});
    const uint32_t bark = addMaterial(s, {0.32f, 0.22f, 0.14f});
    const uint32_t leaves = addMaterial(s, {0.10f, 0.30f, 0.10f});
    constexpr int kCells = 3;
    constexpr float kSize = 60.0f, kCell = kSize / kCells;
    std::vector<Vertex> ground;
    std::vector<uint32_t> idx;
    for (int j = 0; j <= kCells; ++j)
        for (int i = 0; i <= kCells; ++i) {
            const float x = -0.5f * kSize + i * kCell, z = -0.5f * kSize + j * kCell;
            ground.push_back({{x, terrainHeight(x, z), z}, {0, 1, 0}, {float(i), float(j)}});
        }
    for (int j = 0; j < kCells; ++j)
        for (int i = 0; i < kCells; ++i) {
            const uint32_t a = uint32_t(j * (kCells + 1) + i), b = a + kCells + 1;
            idx.insert(idx.end(), {a, b, a + 1, a + 1, b, b + 1});  // counter-clockwise seen from above
        }
    addTriangles(s, ground, idx, grass);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int t = 0; t < 60; ++t) {
        const float x = -25.0f + 50.0f * u(rng), z = -25.0f + 50.0f * u(rng), scale = 0.7f + 0.6f * u(rng);
        const glm::vec3 foot(x, terrainHeight(x, z), z);
        addBox(s, foot + glm::vec3(0, 0.8f * scale, 0), glm::vec3(0.12f, 0.8f, 0.12f) * scale, u(rng), bark);
        for (int layer = 0; layer < 3; ++layer)
            addCone(s, foot + glm::vec3(0, (1.2f + 0.9f * layer) * scale, 0), (1.4f - 0.35f * layer) * scale,
                    1.6f * scale, 32, leaves);
    }

    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.5f, -0.45f, 0.35f));
    sun.intensity = 4.0f;
    sun.name = "sun";
    s.lights.push_back(sun);

    Camera cam;
    cam.eye = {-22.0f, 6.0f, 24.0f};
    cam.target = {4.0f, 0.0f, -6.0f};
    cam.fovy = glm::radians(55.0f);
    s.cameras.push_back(cam);
    return s;
}

}  // namespace

std::vector<std::string> builtinSceneNames() { return {"cornell", "cornell-moving", "plane", "hair", "street", "room", "terrain"}; }

Scene makeBuiltinScene(const std::string& name, const BuiltinOptions& options) {
    Scene s;
    if (name == "cornell") {
        s = makeCornell();
    } else if (name == "cornell-moving") {
        s = makeMovingCornell();
    } else if (name == "plane") {
        s = makePlane();
    } else if (name == "hair") {
        s = makeHair(options);
    } else if (name == "street") {
        s = makeStreet();
    } else if (name == "room") {
        s = makeRoom();
    } else if (name == "terrain") {
        s = makeTerrain();
    } else {
        throw SceneError(fmt::format("unknown scene '{}': not a file and not a built-in scene ({})", name,
                                     fmt::join(builtinSceneNames(), ", ")));
    }
    s.computeBounds();
    addDefaultsIfMissing(s);  // derives zfar from the bounds
    return s;
}

}  // namespace penumbra
