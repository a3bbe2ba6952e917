// The viewer's session headless (no window): `set` goes through the render command's parser and
// rules, and cycling through the same settings leaves the renderer's memory and the host's RSS flat.
#include <fstream>
#include <numeric>
#include <string>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "frame/input_parse.h"
#include "view/session.h"

namespace penumbra::view {
namespace {

std::unique_ptr<vk::Context> validatingContext() {
    vk::ContextOptions o;
    o.validate = true;
    o.quiet = true;
    o.syncValidation = true;
    return std::make_unique<vk::Context>(o);
}

std::string validationLog(const vk::Context& ctx) {
    std::string log;
    for (const std::string& m : ctx.validationLog()) log += m + "\n";
    return log;
}

double rssMiB() {
    std::ifstream statm("/proc/self/statm");
    size_t pages = 0, resident = 0;
    statm >> pages >> resident;
    return double(resident) * double(sysconf(_SC_PAGESIZE)) / double(1 << 20);
}

TEST(ViewSession, SetUsesTheRenderParserAndRules) {
    auto ctx = validatingContext();
    ViewSession s(*ctx, {{"--width", {"64"}}, {"--height", {"48"}}});
    s.set("shadow", "pcss");
    EXPECT_EQ(s.settings().shadow.filter, ShadowFilter::Pcss);
    s.set("rsm-per-cascade", "on");
    EXPECT_TRUE(s.settings().rsm.perCascade);
    s.set("rsm-per-cascade", "off");
    EXPECT_FALSE(s.settings().rsm.perCascade);
    EXPECT_THROW(s.set("aov", "lpv-slice"), std::invalid_argument);  // needs --gi lpv
    EXPECT_EQ(s.settings().aov, Aov::Final);                          // and nothing changed
    EXPECT_THROW(s.set("shadow-res", "8"), std::invalid_argument);    // the CLI's range
    s.set("shadow", "vsm");
    // The device budget, as `render` checks it: the moment maps beyond the device's allocation size.
    EXPECT_THROW(s.set("shadow-res", "16384"), std::invalid_argument);
    EXPECT_EQ(s.settings().shadow.resolution, 2048u);
    EXPECT_THROW(s.set("no-such-option", "1"), std::invalid_argument);
    s.set("shadow", "pcf,dsm");
    EXPECT_TRUE(s.settings().dsm.enabled);
    s.set("shadow", "pcf");  // replaces the earlier value as on a command line: no DSM any more
    EXPECT_FALSE(s.settings().dsm.enabled);
    s.set("light-shadow", "0=vsm");
    EXPECT_EQ(s.lights().at(0).shadowFilter, ShadowFilter::Vsm);
    s.renderAndWait();
    EXPECT_EQ(ctx->validationMessages(), 0u) << validationLog(*ctx);
}

// The A/B split view: a second renderer over the same GpuScene with one option changed renders what
// a renderer of those settings alone renders, and leaves A's image as it was.
TEST(ViewSession, SplitViewRendersBWithItsOneOption) {
    auto ctx = validatingContext();
    // Each frame its own GI, so that B's frame after A's equals a one-shot render.
    ViewSession s(*ctx, {{"--width", {"64"}}, {"--height", {"48"}}, {"--shadow-res", {"256"}}, {"--gi-temporal", {"off"}}});
    s.renderAndWait();
    const std::vector<uint8_t> a = s.renderer().readLdr();
    s.setSplit("shadow", "pcss");
    ASSERT_NE(s.rendererB(), nullptr);
    EXPECT_EQ(&s.rendererB()->gpuScene(), &s.renderer().gpuScene());
    s.renderAndWait();
    EXPECT_EQ(s.renderer().readLdr(), a);
    RenderSettings pcss = s.settings();
    pcss.shadow.filter = ShadowFilter::Pcss;
    Renderer alone(*ctx, s.renderer().gpuScene(), pcss);
    alone.render({s.camera(), s.lights()});
    const std::vector<uint8_t> b = s.rendererB()->readLdr();
    EXPECT_EQ(b, alone.readLdr());
    EXPECT_NE(b, a);
    s.set("exposure", "2");  // A's options reach B, which keeps its own
    EXPECT_EQ(s.rendererB()->settings().exposure, 2.0f);
    EXPECT_EQ(s.rendererB()->settings().shadow.filter, ShadowFilter::Pcss);
    EXPECT_THROW(s.setSplit("width", "32"), std::invalid_argument);
    s.clearSplit();
    EXPECT_EQ(s.rendererB(), nullptr);
    EXPECT_EQ(ctx->validationMessages(), 0u) << validationLog(*ctx);
}

struct CycleMemory {
    std::vector<double> rss;     // MiB after each cycle
    double unchangedGrowth = 0;  // MiB over as many frames as ten cycles, with no change
};

// 10 settings states (per-frame values, filters, GI on and off, resolutions, a moved light), cycled
// 30 times, then as many frames as ten cycles without a change. Checks the device-side counters as it
// goes: per state the first cycle's bytes and blocks, and no live pipeline added after the first cycle.
CycleMemory cycleSettings(vk::Context& ctx) {
    // Explicit GI and filter: the cycle returns to where it started whatever the defaults are. The GI
    // history off: lavapipe's resident memory grows with every dispatch of a frame (3.2 MiB a frame
    // at 64x48 with RSM, 3.7 with the history's four more passes, in `penumbra render --frames`), so
    // the frames with GI would outgrow the unchanged frames (without GI) by that alone.
    ViewSession s(ctx, {{"--width", {"64"}}, {"--height", {"48"}}, {"--shadow-res", {"256"}}, {"--gi", {"none"}},
                        {"--shadow", {"hard"}}, {"--gi-temporal", {"off"}}});
    const Light moved = parseLight("spot,0.3,1.9,0,0,-1,0,4,50");
    const Light original = s.lights().at(0);
    using Sets = std::vector<std::pair<const char*, const char*>>;
    const std::vector<Sets> states = {
        {{"shadow", "pcf"}},
        {{"shadow", "pcss"}, {"pcss-light-size", "0.2"}},
        {{"exposure", "2"}},
        {{"gi", "rsm"}, {"rsm-res", "64"}, {"rsm-samples", "16"}},
        {{"aov", "indirect"}},
        {{"aov", "final"}, {"gi", "none"}},
        {{"shadow-res", "512"}, {"shadow", "vsm"}},
        {},  // the light moved
        {{"shadow", "msm"}, {"pcss-light-size", "0.1"}},
        {{"shadow", "hard"}, {"shadow-res", "256"}, {"exposure", "1"}},  // back to the start
    };
    struct Counters {
        VkDeviceSize reserved, inUse;
        uint32_t blocks;
        VkDeviceSize sceneBytes;
        bool operator==(const Counters&) const = default;
    };
    std::vector<Counters> first;
    CycleMemory memory;
    int64_t pipelines = 0;  // live after the first cycle
    for (int cycle = 0; cycle < 30; ++cycle) {
        for (size_t i = 0; i < states.size(); ++i) {
            for (const auto& [option, value] : states[i]) s.set(option, value);
            s.setLight(0, i == 7 ? moved : original);
            s.renderAndWait();
            vk::Allocator& a = s.renderer().allocator();
            const Counters c{a.bytesReserved(), a.bytesInUse(), a.blockCount(), s.renderer().gpuScene().bytes()};
            if (cycle == 0) first.push_back(c);
            else EXPECT_EQ(c, first[i]) << "cycle " << cycle << ", state " << i;
        }
        memory.rss.push_back(rssMiB());
        if (cycle == 0) pipelines = ctx.pipelinesAlive();
        EXPECT_EQ(ctx.pipelinesAlive(), pipelines) << "cycle " << cycle;
    }
    const double before = rssMiB();
    for (size_t i = 0; i < 10 * states.size(); ++i) s.renderAndWait();
    memory.unchangedGrowth = rssMiB() - before;
    return memory;
}

// After each state the renderer's and the scene's device memory (bytes, blocks) equal the first
// cycle's at that state, no pipeline is added after the first cycle, and the host's resident memory
// grows over the last ten cycles no more than over as many frames without a change (plus 1 MiB):
// lavapipe (Mesa 22.3) itself adds about 0.77 MiB of RSS per frame, changes or not, in `penumbra
// render --frames N` as well (not on NVIDIA's driver).
TEST(ViewSession, CyclingSettingsLeavesMemoryFlat) {
    auto ctx = validatingContext();
    const CycleMemory m = cycleSettings(*ctx);
#if !defined(__SANITIZE_ADDRESS__)  // AddressSanitizer's quarantine holds freed memory: its RSS is no measure
    const double changing = m.rss.back() - m.rss[19];
    EXPECT_LE(changing, m.unchangedGrowth + 1.0)
        << "RSS grew " << changing << " MiB over ten cycles, " << m.unchangedGrowth << " MiB without changes";
#endif
    EXPECT_EQ(ctx->validationMessages(), 0u) << validationLog(*ctx);
}

}  // namespace
}  // namespace penumbra::view
