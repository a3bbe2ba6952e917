// Named views: the documented cameras of a scene (and the sun the view is lit by, where it names
// one), reachable by a short name (`--view nave`) instead of a ten-number camera string.
#pragma once
#include <string>
#include <vector>

namespace penumbra {

struct NamedView {
    std::string scene;                // the scene's key: a built-in name or a file's lower-case stem
    std::string name;                 // "nave"
    std::string camera;               // ex,ey,ez,tx,ty,tz,ux,uy,uz,fovy (the --camera form)
    std::vector<std::string> lights;  // the --light form; empty: the scene's own lights
    std::string about;                // one line for the help
};

// Every named view, grouped by scene.
const std::vector<NamedView>& namedViews();

// The key a scene's views are filed under: a built-in scene's name, or the lower-case file name
// without its extension ("../shared/assets/sponza/glTF/Sponza.gltf" -> "sponza").
std::string namedViewKey(const std::string& scene);

// The view `name` of `scene`; throws std::invalid_argument naming the views there are.
const NamedView& findNamedView(const std::string& scene, const std::string& name);

// "sponza: nave, aisle; vc: overview": the views by scene, for messages and the help.
std::string namedViewList();

}  // namespace penumbra
