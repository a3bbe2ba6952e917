// The viewer's session headless (no window): `set` goes through the render command's parser and
// rules, and cycling through the same settings leaves the renderer's memory and the host's RSS flat.
#include <fstream>
#include <numeric>
#include <string>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "app/cli_parse.h"
#include "view/session.h"

namespace penumbra::view {
namespace {

std::unique_ptr<vk::Context> validatingContext() {
    vk::ContextOptions o;
    o.validate = true;
    o.quiet = true;
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

// 10 settings states (per-frame values, filters, GI on and off, resolutions, a moved light), cycled
// 30 times: after each state the renderer's device memory equals the first cycle's at that state,
// and the host's RSS shows no upward trend.
TEST(ViewSession, CyclingSettingsLeavesMemoryFlat) {
    auto ctx = validatingContext();
    ViewSession s(*ctx, {{"--width", {"64"}}, {"--height", {"48"}}, {"--shadow-res", {"256"}}});
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
        bool operator==(const Counters&) const = default;
    };
    std::vector<Counters> first;
    std::vector<double> rss;
    for (int cycle = 0; cycle < 30; ++cycle) {
        for (size_t i = 0; i < states.size(); ++i) {
            for (const auto& [option, value] : states[i]) s.set(option, value);
            s.setLight(0, i == 7 ? moved : original);
            s.renderAndWait();
            vk::Allocator& a = s.frame().renderer().allocator();
            const Counters c{a.bytesReserved(), a.bytesInUse()};
            if (cycle == 0) first.push_back(c);
            else ASSERT_EQ(c, first[i]) << "cycle " << cycle << ", state " << i;
        }
        rss.push_back(rssMiB());
    }
    // No upward trend: the last ten cycles' mean RSS within 2% of cycles 2-11's (lavapipe and the
    // validation layer keep caches that settle in the first cycle).
    const double early = std::accumulate(rss.begin() + 1, rss.begin() + 11, 0.0) / 10.0;
    const double late = std::accumulate(rss.end() - 10, rss.end(), 0.0) / 10.0;
    EXPECT_LE(late, early * 1.02) << "RSS " << early << " MiB -> " << late << " MiB";
    EXPECT_EQ(ctx->validationMessages(), 0u) << validationLog(*ctx);
}

}  // namespace
}  // namespace penumbra::view
