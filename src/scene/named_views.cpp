#include "scene/named_views.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

namespace penumbra {

const std::vector<NamedView>& namedViews() {
    // The views the documentation, the benchmarks and the evaluation suite look through. Sponza's
    // default camera stands outside the building, so its views carry the sun that lights the nave.
    static const std::vector<NamedView> views{
        {"sponza", "nave", "-9,1.7,0.3,6,4.5,0,0,1,0,70", {"directional,0.1,-1,0.2,20"},
         "down the nave from its west end, the sun through the roof"},
        {"sponza", "aisle", "-11,1.6,-0.3,8,4.5,0.3,0,1,0,70", {"directional,-0.25,-1,-0.12,8"},
         "along the south aisle, a low sun across the floor"},
        {"vc", "overview", "14,9,16,0,1.5,0,0,1,0,50", {}, "the whole model from above, the file's own lights"},
    };
    return views;
}

std::string namedViewKey(const std::string& scene) {
    std::string key = std::filesystem::path(scene).stem().string();
    std::transform(key.begin(), key.end(), key.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return key;
}

namespace {

std::string viewsOf(const std::string& key) {
    std::string names;
    for (const NamedView& v : namedViews())
        if (v.scene == key) names += (names.empty() ? "" : ", ") + v.name;
    return names;
}

}  // namespace

std::string namedViewList() {
    std::string list;
    for (size_t i = 0; i < namedViews().size(); ++i) {
        const std::string& key = namedViews()[i].scene;
        if (i > 0 && namedViews()[i - 1].scene == key) continue;
        list += (list.empty() ? "" : "; ") + key + ": " + viewsOf(key);
    }
    return list;
}

const NamedView& findNamedView(const std::string& scene, const std::string& name) {
    const std::string key = namedViewKey(scene);
    for (const NamedView& v : namedViews())
        if (v.scene == key && v.name == name) return v;
    const std::string names = viewsOf(key);
    if (names.empty())
        throw std::invalid_argument(
            fmt::format("scene '{}' has no named views (the scenes that have: {})", key, namedViewList()));
    throw std::invalid_argument(fmt::format("'{}' is not a view of '{}' (its views: {})", name, key, names));
}

}  // namespace penumbra
