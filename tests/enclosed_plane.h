// A scene for the light's rule of single-sided triangles under a sky: an open plane inside a
// single-sided box, whose fronts face inward (a sky dome's: seen from inside, letting the light of
// the outside in) or outward (a closed shed). Shared by the path tracer's and the renderer's tests.
#pragma once
#include <utility>

#include <glm/gtc/constants.hpp>

#include "scene/builders.h"

namespace penumbra::test {

// A 12 x 12 m plane at y = 0 (albedo 0.5, facing up) inside a single-sided 16 x 8 x 16 m box (y from
// -1 to 7); the camera 3 m above the plane's centre looks straight down (image x is world +x). No
// lights. Every upward direction from the plane leaves through the box's roof or one of its walls.
inline Scene enclosedPlane(bool frontsInward) {
    Scene s;
    s.name = frontsInward ? "plane-under-dome" : "plane-in-shed";
    addQuad(s, {-6, 0, -6}, {0, 0, 12}, {12, 0, 0}, addMaterial(s, glm::vec3(0.5f)));
    const size_t firstIndex = s.indices.size(), firstVertex = s.vertices.size();
    addBox(s, {0, 3, 0}, {8, 4, 8}, 0.0f, addMaterial(s, glm::vec3(0.8f)));
    if (frontsInward) {  // the box turned inside out: every triangle's winding and normal flipped
        for (size_t k = firstIndex; k < s.indices.size(); k += 3) std::swap(s.indices[k + 1], s.indices[k + 2]);
        for (size_t v = firstVertex; v < s.vertices.size(); ++v) s.vertices[v].normal = -s.vertices[v].normal;
    }
    Camera cam;
    cam.eye = {0, 3, 0};
    cam.target = {0, 0, 0};
    cam.up = {0, 0, -1};
    cam.fovy = glm::radians(60.0f);
    cam.zfar = 40.0f;
    s.cameras.push_back(cam);
    s.computeBounds();
    return s;
}

}  // namespace penumbra::test
