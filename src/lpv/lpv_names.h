// What the LPV module publishes beyond the shared names of core/names.h.
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "core/blackboard.h"

namespace penumbra {

// The world-space boxes the LPV's cascades cover this frame (from its addPasses on), cascade 0
// first: each its lowest corner and its side. A viewer draws them over the image.
struct LpvCascadeBoxes {
    struct Box {
        glm::vec3 origin{0.0f};
        float side = 0.0f;
    };
    std::vector<Box> boxes;
};

namespace names {
inline constexpr HostName<LpvCascadeBoxes> kLpvCascadeBoxes{"lpv.cascade-boxes"};
}  // namespace names

}  // namespace penumbra
