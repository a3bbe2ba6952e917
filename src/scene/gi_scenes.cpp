#include "scene/gi_scenes.h"

#include <glm/gtc/constants.hpp>

#include "scene/builders.h"

namespace penumbra {

Scene makeStreet() {
    Scene s;
    s.name = "street";
    const uint32_t asphalt = addMaterial(s, glm::vec3(0.25f));
    addQuad(s, {-5, 0, -20}, {0, 0, 40}, {10, 0, 0}, asphalt);  // the street, +y
    // Facades: blocks 6 m deep on both sides, x in [-11, -5] and [5, 11], along z in [-20, 20].
    struct Block {
        float z0, z1, height;
        glm::vec3 colour;
    };
    const Block left[] = {{-20, -7, 7, {0.70f, 0.35f, 0.20f}}, {-7, 6, 9, {0.80f, 0.65f, 0.30f}},
                          {6, 20, 6, {0.75f, 0.72f, 0.65f}}};
    const Block right[] = {{-20, -5, 8, {0.35f, 0.45f, 0.60f}}, {-5, 8, 6, {0.40f, 0.60f, 0.40f}},
                           {8, 20, 10, {0.60f, 0.25f, 0.20f}}};
    for (float side : {-8.0f, 8.0f})
        for (const Block& b : side < 0 ? left : right)
            addBox(s, {side, 0.5f * b.height, 0.5f * (b.z0 + b.z1)}, {3.0f, 0.5f * b.height, 0.5f * (b.z1 - b.z0)},
                   0.0f, addMaterial(s, b.colour));
    addBox(s, {-2.5f, 0.7f, -6.0f}, {0.9f, 0.7f, 2.2f}, 0.0f, addMaterial(s, {0.55f, 0.08f, 0.06f}));  // cars
    addBox(s, {2.6f, 0.7f, 4.0f}, {0.9f, 0.7f, 2.2f}, 0.0f, addMaterial(s, glm::vec3(0.8f)));

    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.45f, -0.35f, 0.82f));  // 20 degrees above the horizon
    sun.intensity = 4.0f;
    sun.name = "low sun";
    s.lights.push_back(sun);

    Camera cam;
    cam.eye = {-1.0f, 1.7f, -17.0f};
    cam.target = {1.5f, 3.5f, 5.0f};
    cam.fovy = glm::radians(55.0f);
    s.cameras.push_back(cam);
    return s;
}

Scene makeRoom() {
    Scene s;
    s.name = "room";
    const uint32_t white = addMaterial(s, glm::vec3(0.75f));
    // Walls face inward: x in [-3, 3], y in [0, 3], z in [-2.5, 2.5].
    addQuad(s, {-3, 0, -2.5f}, {0, 0, 5}, {6, 0, 0}, addMaterial(s, {0.55f, 0.40f, 0.25f}));  // wooden floor, +y
    addQuad(s, {-3, 3, -2.5f}, {6, 0, 0}, {0, 0, 5}, white);                                  // ceiling, -y
    addQuad(s, {-3, 0, -2.5f}, {6, 0, 0}, {0, 3, 0}, addMaterial(s, {0.80f, 0.45f, 0.20f}));  // back, +z
    addQuad(s, {-3, 0, 2.5f}, {0, 3, 0}, {6, 0, 0}, addMaterial(s, glm::vec3(0.6f)));         // front, -z
    addQuad(s, {-3, 0, -2.5f}, {0, 3, 0}, {0, 0, 5}, addMaterial(s, {0.25f, 0.40f, 0.70f}));  // left, +x
    addQuad(s, {3, 0, -2.5f}, {0, 0, 5}, {0, 3, 0}, white);                                   // right, -x
    addBox(s, {0.5f, 0.375f, -0.5f}, {0.8f, 0.375f, 0.5f}, glm::radians(10.0f), addMaterial(s, {0.45f, 0.3f, 0.2f}));
    addBox(s, {-2.4f, 1.0f, -1.8f}, {0.5f, 1.0f, 0.6f}, 0.0f, white);  // cabinet
    addBox(s, {1.8f, 0.4f, 1.2f}, {0.9f, 0.4f, 0.4f}, 0.0f, addMaterial(s, {0.60f, 0.15f, 0.12f}));  // sofa
    // Closed to any light from outside (a sky, a sun), as walls with two faces are: a single-sided
    // wall blocks a light only where its front faces the light (the shadow maps' rule), and these
    // fronts face inward.
    for (Material& m : s.materials) m.doubleSided = true;

    Light lamp;
    lamp.type = LightType::Point;
    lamp.position = {-0.8f, 2.3f, 0.3f};
    lamp.intensity = 15.0f;
    lamp.name = "lamp";
    s.lights.push_back(lamp);

    Camera cam;
    cam.eye = {2.6f, 1.6f, 2.3f};
    cam.target = {-1.0f, 1.0f, -1.5f};
    cam.fovy = glm::radians(65.0f);
    s.cameras.push_back(cam);
    return s;
}

}  // namespace penumbra
