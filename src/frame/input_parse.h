// Parsing of the frame inputs' compound values (a camera, a light, an AOV name), for the option rows
// and the viewer's script. Each throws std::invalid_argument with what was expected (the option row
// that calls it names the option).
#pragma once
#include <string>
#include <vector>

#include "renderer/renderer.h"
#include "scene/scene.h"

namespace penumbra {

// "ex,ey,ez,tx,ty,tz,ux,uy,uz,fovy_degrees"
Camera parseCamera(const std::string& value);

// "directional,dx,dy,dz,intensity[,r,g,b]"
// "spot,px,py,pz,dx,dy,dz,intensity,outer_deg[,inner_deg]"
// "point,px,py,pz,intensity"
Light parseLight(const std::string& value);

// "direct", "albedo", "normal", "depth", "shadow"
Aov parseAov(const std::string& value);
std::vector<std::string> aovNames();

}  // namespace penumbra
