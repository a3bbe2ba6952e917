// The technique registry: what the renderer may build, in frame order. Each entry says when it
// runs for the settings, what it needs built before it, which parts of a settings change rebuild
// it, how to make it and how to hand it new per-frame settings. The built-in modules register in
// renderer/builtin_techniques.cpp; a technique outside src/ (a test's) registers itself the same way
// (a static TechniqueRegistration in its own file) and keeps its settings in
// RenderSettings::extensions, without an edit to the assembly.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/technique.h"
#include "renderer/render_settings.h"

namespace penumbra {

struct OptionTable;  // core/options.h

struct TechniqueEntry {
    std::string name;
    // Frame order: techniques run (update, then each pass stage) by increasing order.
    int order = 0;
    // Entries built before this one (their build-time blackboard entries are there for it).
    std::vector<std::string> after;
    // FrameParts (renderer/settings_change.h) whose change rebuilds it.
    uint32_t parts = 0;
    std::function<bool(const RenderSettings&)> enabled = [](const RenderSettings&) { return true; };
    std::function<std::unique_ptr<Technique>(const TechniqueBuild&, const RenderSettings&)> create;
    // Per-frame values of new settings (no allocation); null: none besides the core's.
    std::function<void(Technique&, const RenderSettings&)> apply;
    // FrameParts that it takes in place instead of being rebuilt, and how (shadow filters).
    uint32_t adjustParts = 0;
    std::function<void(Technique&, const RenderSettings&, const std::vector<Light>&)> adjust;
    // Its settings' Auto choices replaced by what they stand for in `scene`; null: it has none.
    std::function<void(RenderSettings&, const Scene&)> resolve;
    // The module's option table and where in RenderSettings the struct its rows write lives: its
    // options join the CLI, --help, the JSON settings, the viewer and the settings-change classes.
    const OptionTable* options = nullptr;
    std::function<void*(const RenderSettings&)> settings;
};

class TechniqueRegistry {
public:
    // The process's registry, with the built-in modules.
    static TechniqueRegistry& instance();
    // Adds an entry (throws when its name is taken).
    void add(TechniqueEntry entry);
    // Every entry in build order: `after` first, else frame order.
    std::vector<const TechniqueEntry*> buildOrder() const;
    const TechniqueEntry* find(const std::string& name) const;
    const std::vector<TechniqueEntry>& entries() const { return entries_; }

private:
    std::vector<TechniqueEntry> entries_;
};

// Registers an entry when constructed: a static object of the technique's own file.
struct TechniqueRegistration {
    explicit TechniqueRegistration(TechniqueEntry entry) { TechniqueRegistry::instance().add(std::move(entry)); }
};

// `s` with every entry's Auto choices resolved for `scene` (the renderer's and the budget's view).
RenderSettings resolveForScene(RenderSettings s, const Scene& scene);

// The built-in modules' entries (renderer/builtin_techniques.cpp).
void addBuiltinTechniques(TechniqueRegistry& registry);
// Whether the occupancy volume is built: the RSM gather's visibility, what blocks LPV's propagation,
// or what hides the sky read it (the device budget counts it then).
bool occupancyUsed(const RenderSettings& s);

}  // namespace penumbra
