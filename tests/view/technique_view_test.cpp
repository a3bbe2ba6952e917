// The viewer sees a technique registered from outside src/ (tests/ambient_technique.h) through its
// option table alone: a panel control in the technique's group, and a script's `set` that reaches
// the renderer, which runs the technique's pass under validation and synchronization validation.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "../ambient_technique.h"
#include "view/script.h"
#include "view/session.h"

namespace penumbra::view {
namespace {

TEST(TechniqueView, OutsideTechniqueHasAControlAndAScriptSet) {
    vk::ContextOptions o;
    o.validate = o.syncValidation = o.quiet = true;
    vk::Context ctx(o);
    ViewSession session(ctx, {{"--width", {"64"}}, {"--height", {"48"}}});
    bool listed = false;
    for (const OptionInfo& info : session.options())
        if (info.name == "ambient-irradiance") {
            listed = true;
            EXPECT_EQ(info.group, test::ambientOptions().title);
            EXPECT_EQ(info.value, "0");
        }
    EXPECT_TRUE(listed) << "no viewer control for --ambient-irradiance";

    const std::filesystem::path script = std::filesystem::temp_directory_path() / "penumbra_technique_view.txt";
    std::ofstream(script) << "set ambient on\nset ambient-irradiance 0.75\nframes 2\n";
    Script runner(script.string());
    EXPECT_EQ(runner.run(session).kind, ScriptStep::Frames);
    EXPECT_TRUE(test::ambientSettings(session.settings()).enabled);
    EXPECT_FLOAT_EQ(test::ambientSettings(session.settings()).irradiance, 0.75f);
    for (int i = 0; i < 2; ++i) session.submit({});
    session.renderer().finish();
    bool ran = false;
    for (const PassDesc& p : session.renderer().passes()) ran |= p.name == "test.ambient";
    EXPECT_TRUE(ran) << session.renderer().describePasses();
    for (const OptionInfo& info : session.options()) {
        if (info.name == "ambient-irradiance") {
            EXPECT_EQ(info.value, "0.75");
        }
    }
    EXPECT_TRUE(ctx.validationLog().empty()) << ctx.validationLog().front();
    std::filesystem::remove(script);
}

}  // namespace
}  // namespace penumbra::view
