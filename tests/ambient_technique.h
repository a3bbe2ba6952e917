// A technique written outside src/, as an engine or a contributor would add one: a constant ambient
// irradiance published under the shared irradiance-contribution name, with its own settings struct
// (kept in RenderSettings::extensions), its option table and its registry entry. Nothing in src/
// names it. The registration is a static object in this header (an inline variable), so every test
// binary that includes it has the technique registered before main: the CLI, --help, the JSON
// settings, the settings-change classes and the viewer's `set` all see it.
#pragma once
#include <memory>

#include "core/names.h"
#include "core/options.h"
#include "renderer/settings_change.h"
#include "renderer/technique_registry.h"

namespace penumbra::test {

struct AmbientSettings {
    bool enabled = false;
    float irradiance = 0.0f;
};

inline constexpr const char* kAmbientName = "test-ambient";

class AmbientTechnique : public Technique {
public:
    AmbientTechnique(const TechniqueBuild& b, const AmbientSettings& s)
        : settings_(s),
          image_(b.alloc, {VK_FORMAT_R32G32B32A32_SFLOAT, b.core.width, b.core.height, 1,
                           VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, "test-ambient"}) {}
    const char* name() const override { return kAmbientName; }
    bool contributesIrradiance() const override { return true; }
    void setSettings(const AmbientSettings& s) { settings_ = s; }  // per frame: nothing is allocated
    void addPasses(const FrameContext& f) override {
        const ImageHandle h = f.graph.import(image_);
        const float e = settings_.irradiance;
        f.graph.pass("test.ambient", PassKind::Transfer).use(h, Use::TransferDst).record([h, e](PassContext& c) {
            const VkClearColorValue value{{e, e, e, 1.0f}};
            const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
            vkCmdClearColorImage(c.cmd, c.image(h).handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &value, 1, &range);
        });
        f.graph.contribute(names::kIrradianceContribution, h);
    }

private:
    AmbientSettings settings_;
    vk::Image image_;
};

inline const OptionTable& ambientOptions() {
    static const OptionTable table = [] {
        using A = AmbientSettings;
        OptionTableBuilder<A> t(kAmbientName, "Constant ambient (a test technique)");
        t.boolean("--ambient", "enabled", [](A& a) -> auto& { return a.enabled; }, SettingsChange::Structure,
                  "A constant ambient irradiance added to the indirect light");
        t.real("--ambient-irradiance", "irradiance", [](A& a) -> auto& { return a.irradiance; }, 0.0, 1000.0,
               SettingsChange::PerFrame, "The ambient irradiance (W/m^2)");
        return t.build();
    }();
    return table;
}

inline AmbientSettings& ambientSettings(const RenderSettings& s) {
    // The store is mutable: the settings are default-made on first read.
    return const_cast<RenderSettings&>(s).extension<AmbientSettings>(kAmbientName);
}

inline const TechniqueRegistration ambientRegistration{[] {
    TechniqueEntry e{kAmbientName, 65};  // after the built-in GI, before the temporal GI and the lighting
    e.parts = kPartCamera;
    e.enabled = [](const RenderSettings& s) { return ambientSettings(s).enabled; };
    e.create = [](const TechniqueBuild& b, const RenderSettings& s) {
        return std::make_unique<AmbientTechnique>(b, ambientSettings(s));
    };
    e.apply = [](Technique& t, const RenderSettings& s) {
        static_cast<AmbientTechnique&>(t).setSettings(ambientSettings(s));
    };
    e.options = &ambientOptions();
    e.settings = [](const RenderSettings& s) -> void* { return &ambientSettings(s); };
    return e;
}()};

}  // namespace penumbra::test
