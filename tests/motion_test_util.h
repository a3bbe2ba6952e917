// Test scenes for motion (tests/animation_test.cpp, tests/motion_gi_test.cpp): a glTF of two quads
// (a 4 m ground and a 0.5 m square) that tests place and animate, cameras, a sun, hard-shadow settings.
#pragma once
#include <string>
#include <vector>

#include <glm/gtc/constants.hpp>

#include "gltf_test_util.h"
#include "gpu_fixture.h"

namespace penumbra::test {
// Two quads in one buffer: mesh 0 the ground (4 m square at y = 0), mesh 1 a 0.5 m square at y = 0
// (its node lifts it); both facing +y, double-sided.
struct QuadFile {
    std::vector<uint8_t> bin;
    json doc;
    QuadFile() {
        auto quad = [&](float h) {
            for (float z : {-h, h})
                for (float x : {-h, h}) append(bin, x), append(bin, 0.0f), append(bin, z);
        };
        quad(2.0f);
        quad(0.25f);
        for (int q = 0; q < 2; ++q)
            for (uint16_t i : {0, 2, 1, 1, 2, 3}) append(bin, uint16_t(i));
        doc = json{{"asset", {{"version", "2.0"}}},
                   {"scene", 0},
                   {"buffers", json::array()},
                   {"bufferViews", {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 96}},
                                    {{"buffer", 0}, {"byteOffset", 96}, {"byteLength", 24}}}},
                   {"accessors",
                    {{{"bufferView", 0}, {"byteOffset", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"},
                      {"min", {-2, 0, -2}}, {"max", {2, 0, 2}}},
                     {{"bufferView", 0}, {"byteOffset", 48}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"},
                      {"min", {-0.25, 0, -0.25}}, {"max", {0.25, 0, 0.25}}},
                     {{"bufferView", 1}, {"byteOffset", 0}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}},
                     {{"bufferView", 1}, {"byteOffset", 12}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}}},
                   {"materials", {{{"doubleSided", true}}}}};
        for (int m = 0; m < 2; ++m) {
            json primitive{{"attributes", {{"POSITION", m}}}, {"indices", 2 + m}, {"material", 0}};
            doc["meshes"].push_back({{"primitives", json::array({primitive})}});
        }
    }
    // Adds a float accessor (after the geometry) and returns its index.
    int addFloats(const std::vector<float>& v, const char* type, int count) {
        const size_t offset = bin.size();
        for (float f : v) append(bin, f);
        doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", v.size() * 4}});
        json acc{{"bufferView", doc["bufferViews"].size() - 1}, {"componentType", 5126}, {"count", count}, {"type", type}};
        if (std::string(type) == "SCALAR") acc["min"] = {v.front()}, acc["max"] = {v.back()};
        doc["accessors"].push_back(acc);
        return int(doc["accessors"].size() - 1);
    }
    std::string write(const TempDir& dir) {
        doc["buffers"] = {{{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}};
        const std::string path = dir.file("scene.gltf");
        writeFile(path, doc.dump());
        return path;
    }
};

// The ground, and the small square at y = 1 sliding along x from -0.5 (t = 0) to 0.5 (t = 1).
inline std::string slidingOccluder(const TempDir& dir) {
    QuadFile f;
    const int times = f.addFloats({0.0f, 1.0f}, "SCALAR", 2);
    const int values = f.addFloats({-0.5f, 1.0f, 0.0f, 0.5f, 1.0f, 0.0f}, "VEC3", 2);
    f.doc["nodes"] = {{{"mesh", 0}}, {{"mesh", 1}, {"translation", {-0.5, 1, 0}}}};
    f.doc["scenes"] = {{{"nodes", {0, 1}}}};
    f.doc["animations"] = {{{"channels", {{{"sampler", 0}, {"target", {{"node", 1}, {"path", "translation"}}}}}},
                            {"samplers", {{{"input", times}, {"output", values}, {"interpolation", "LINEAR"}}}}}};
    return f.write(dir);
}

// A camera at `eye` looking at `target` (y up).
inline Camera lookingAt(glm::vec3 eye, glm::vec3 target, float fovyDegrees) {
    Camera c;
    c.eye = eye;
    c.target = target;
    c.fovy = glm::radians(fovyDegrees);
    return c;
}

// 96x72 hard-shadow AOV frames with one 512^2 map, no GI: where a pixel is lit is all the tests read.
inline RenderSettings hardShadowAov() {
    RenderSettings s;
    s.width = 96;
    s.height = 72;
    s.aov = Aov::Shadow;
    s.gi = GiMode::None;
    s.shadow.filter = ShadowFilter::Hard;
    s.shadow.resolution = 512;
    return s;
}

inline Light sunAlong(glm::vec3 direction) {
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = direction;
    sun.intensity = 3.0f;
    return sun;
}


}  // namespace penumbra::test
