// How strong a light may be: the lighting must stay finite in every target it passes through.
#pragma once

namespace penumbra {

// A light's intensity times its largest colour component is at most this: the largest finite
// RGBA16F value, the narrowest target light passes through (the RSM's flux). A stronger light
// overflows the lighting to infinity, and the image turns black. glTF lights above it are clamped
// with a warning; --light refuses them.
constexpr float kMaxLightStrength = 65504.0f;

}  // namespace penumbra
