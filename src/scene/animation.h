// The scene at a time: glTF animation sampling, node world transforms, instance transforms, lights
// and cameras carried by their nodes, and the world-space copy the path tracer traces.
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace penumbra {

struct AnimationOptions {
    int animation = -1;  // -1: all animations play; else only this one (--animation N)
    bool clamp = false;  // hold the last key (--clamp) instead of looping
};

// A channel's value at time t (seconds on the channel's own clock, no looping): xyz for translation
// and scale, a unit quaternion (x, y, z, w) for rotation. Before the first key: the first value;
// after the last: the last. LINEAR slerps rotations along the shorter arc; CUBICSPLINE is the glTF
// Hermite spline with tangents scaled by the key interval.
glm::vec4 sampleChannel(const AnimationChannel& channel, float t);

// The time an animation shows at scene time t: looping over its duration, or held at its end.
float animationLocalTime(const Animation& animation, double t, bool clamp);

// World transform of every Scene::nodes entry at time t (rest transforms where nothing animates).
std::vector<glm::mat4> nodeWorldTransforms(const Scene& scene, double t, const AnimationOptions& options);

// World transform of every Scene::instances entry, from the nodes' world transforms.
std::vector<glm::mat4> instanceTransforms(const Scene& scene, const std::vector<glm::mat4>& nodeWorld);

// Moves the lights and cameras that hang from nodes to where those nodes are.
void placeOnNodes(const Scene& scene, const std::vector<glm::mat4>& nodeWorld, std::vector<Light>& lights);
void placeOnNodes(const Scene& scene, const std::vector<glm::mat4>& nodeWorld, Camera& camera);

// True when the scene has an animation that moves something.
bool isAnimated(const Scene& scene);

// A copy of the scene with every instance's geometry in world space (at `transforms`, one per
// instance) as mesh 0 drawn once: what the CPU path tracer traces at a time.
Scene worldSpaceScene(const Scene& scene, const std::vector<glm::mat4>& transforms);

// World bounds of the scene's geometry over its animations (sampled; the rest pose included).
Bounds animatedBounds(const Scene& scene);

}  // namespace penumbra
