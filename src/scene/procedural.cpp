// Built-in scenes that need no asset files: the default Cornell box and a plane for unit tests.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "scene/builders.h"
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

}  // namespace

std::vector<std::string> builtinSceneNames() { return {"cornell", "plane"}; }

Scene makeBuiltinScene(const std::string& name) {
    Scene s;
    if (name == "cornell") {
        s = makeCornell();
    } else if (name == "plane") {
        s = makePlane();
    } else {
        throw SceneError(fmt::format("unknown scene '{}': not a file and not a built-in scene ({})", name,
                                     fmt::join(builtinSceneNames(), ", ")));
    }
    s.computeBounds();
    addDefaultsIfMissing(s);  // derives zfar from the bounds
    return s;
}

}  // namespace penumbra
