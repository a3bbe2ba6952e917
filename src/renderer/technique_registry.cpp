#include "renderer/technique_registry.h"

#include <algorithm>
#include <stdexcept>

namespace penumbra {

TechniqueRegistry& TechniqueRegistry::instance() {
    static TechniqueRegistry registry = [] {
        TechniqueRegistry r;
        addBuiltinTechniques(r);
        return r;
    }();
    return registry;
}

void TechniqueRegistry::add(TechniqueEntry entry) {
    if (find(entry.name)) throw std::logic_error("technique registry: '" + entry.name + "' registered twice");
    if (!entry.create) throw std::logic_error("technique registry: '" + entry.name + "' has no factory");
    entries_.push_back(std::move(entry));
    std::stable_sort(entries_.begin(), entries_.end(),
                     [](const TechniqueEntry& a, const TechniqueEntry& b) { return a.order < b.order; });
}

const TechniqueEntry* TechniqueRegistry::find(const std::string& name) const {
    for (const TechniqueEntry& e : entries_)
        if (e.name == name) return &e;
    return nullptr;
}

// Depth-first over `after`, in frame order otherwise; an unknown name in `after` is ignored (that
// module is not linked), a cycle throws.
std::vector<const TechniqueEntry*> TechniqueRegistry::buildOrder() const {
    std::vector<const TechniqueEntry*> out;
    std::vector<const TechniqueEntry*> visiting;
    std::function<void(const TechniqueEntry&)> visit = [&](const TechniqueEntry& e) {
        if (std::find(out.begin(), out.end(), &e) != out.end()) return;
        if (std::find(visiting.begin(), visiting.end(), &e) != visiting.end())
            throw std::logic_error("technique registry: '" + e.name + "' depends on itself");
        visiting.push_back(&e);
        for (const std::string& name : e.after)
            if (const TechniqueEntry* dep = find(name)) visit(*dep);
        visiting.pop_back();
        out.push_back(&e);
    };
    for (const TechniqueEntry& e : entries_) visit(e);
    return out;
}

RenderSettings resolveForScene(RenderSettings s, const Scene& scene) {
    for (const TechniqueEntry& e : TechniqueRegistry::instance().entries())
        if (e.resolve) e.resolve(s, scene);
    return s;
}

}  // namespace penumbra
