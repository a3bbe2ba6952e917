// The commands' option tables: each command's own options are rows (ranges checked, the flag in
// every refusal), help texts refer to other options through their rows, and the compound motion
// values are parsed once, when their row is set.
#include <set>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "app/bench.h"
#include "app/cli_app.h"
#include "app/ground_truth_cli.h"
#include "app/option_cli.h"
#include "app/stability.h"
#include "frame/frame_options.h"

namespace penumbra::test {
namespace {

struct CommandTable {
    const OptionTable* table;
    std::vector<const OptionTable*> alongside;  // the other tables of the same command
};

std::vector<CommandTable> commandTables() {
    const OptionTable* global = &globalOptions();
    const OptionTable* scene = &referenceSceneOptions();
    const OptionTable* inputs = &frameInputOptions();
    const OptionTable* motion = &motionOptions();
    return {{&renderCommandOptions(), {global, inputs, motion}},
            {&benchCommandOptions(), {global, inputs, motion}},
            {&referenceCommandOptions(), {global, scene, inputs, motion}},
            {&evalCommandOptions(), {global, scene, inputs, motion}},
            {&compareCommandOptions(), {global}},
            {&stabilityCommandOptions(), {global, inputs, motion}},
            {global, {}}};
}

TEST(OptionTablesCommands, FlagsAreUniqueWithinEachCommand) {
    for (const CommandTable& c : commandTables()) {
        std::set<std::string> flags;
        for (const OptionTable* t : c.alongside)
            for (const OptionRow& row : t->rows) flags.insert(row.flag);
        for (const OptionRow& row : c.table->rows) {
            EXPECT_TRUE(flags.insert(row.flag).second) << c.table->module << ": " << row.flag << " is in two rows";
            EXPECT_FALSE(row.help.empty()) << row.flag;
        }
    }
}

// Every whole-number and real row refuses a value just outside its range, naming its flag first.
TEST(OptionTablesCommands, NumbersOutsideTheRangeAreRefusedWithTheFlag) {
    RenderCliOptions render;
    ReferenceCliOptions reference;
    EvalCliOptions eval;
    StabilityOptions stability;
    CompareCliOptions compare;
    const std::vector<std::pair<const OptionTable*, void*>> bound{
        {&renderCommandOptions(), &render},       {&referenceSceneOptions(), &reference},
        {&referenceCommandOptions(), &reference}, {&evalCommandOptions(), &eval},
        {&stabilityCommandOptions(), &stability}, {&compareCommandOptions(), &compare}};
    int checked = 0;
    for (const auto& [table, settings] : bound)
        for (const OptionRow& row : table->rows) {
            if (row.kind != OptionKind::Integer && row.kind != OptionKind::Real) continue;
            EXPECT_LT(row.max, 1e300) << row.flag << " has no bound";
            const std::string above = formatOptionNumber(row.max * 2.0 + 1.0);
            try {
                row.set(settings, above);
                ADD_FAILURE() << row.flag << " " << above << " was accepted";
            } catch (const std::invalid_argument& e) {
                EXPECT_EQ(std::string(e.what()).rfind(row.flag + " " + above + ": ", 0), 0u) << e.what();
                ++checked;
            }
        }
    EXPECT_GE(checked, 15);
}

TEST(OptionTablesCommands, HelpReferencesExpandToTheFlag) {
    EXPECT_EQ(expandOptionReferences("frames per second of {render.sequence}"), "frames per second of --sequence");
    EXPECT_EQ(expandOptionReferences("{eval.suite}: the folder"), "--suite: the folder");
    EXPECT_EQ(expandOptionReferences("a set {1, 2} stays"), "a set {1, 2} stays");
    EXPECT_THROW(expandOptionReferences("{render.no_such_option}"), std::logic_error);
    for (const CommandTable& c : commandTables())
        for (const OptionRow& row : c.table->rows) {
            const std::string help = expandOptionReferences(row.help);
            EXPECT_EQ(help.find("{eval."), std::string::npos) << row.flag << ": " << help;
            EXPECT_EQ(help.find("{render."), std::string::npos) << row.flag << ": " << help;
        }
}

// The motion rows parse their value as it is given: the frame takes the typed keys, and a bad
// value is refused naming the row's flag.
TEST(OptionTablesCommands, MotionPathsAreParsedWhenTheirRowIsSet) {
    const OptionTable& t = motionOptions();
    FrameOptions f;
    const OptionRow* lightPath = t.find(t.flagOf<FrameOptions>([](FrameOptions& o) -> auto& { return o.motion.lights; }));
    const OptionRow* sun = t.find(t.flagOf<FrameOptions>([](FrameOptions& o) -> auto& { return o.motion.sun; }));
    const OptionRow* keys = t.find(t.flagOf<FrameOptions>([](FrameOptions& o) -> auto& { return o.motion.camera; }));
    ASSERT_TRUE(lightPath && sun && keys);
    lightPath->set(&f, "2:0,0,1,0;1.5,0,2,0");
    ASSERT_EQ(f.parsedMotion.lights.size(), 1u);
    EXPECT_EQ(f.parsedMotion.lights[0].light, 2u);
    EXPECT_EQ(f.parsedMotion.lights[0].positions.times, (std::vector<float>{0.0f, 1.5f}));
    EXPECT_EQ(f.parsedMotion.lights[0].positions.at(0.75).y, 1.5f);
    sun->set(&f, "0,30,90,60,4");
    ASSERT_TRUE(f.parsedMotion.sun);
    EXPECT_EQ(f.parsedMotion.sun->to.y, 60.0f);
    keys->set(&f, "0,0,1,3,0,1,0;2,0,1,4,0,1,0");
    ASSERT_TRUE(f.parsedMotion.camera);
    EXPECT_EQ(f.parsedMotion.camera->eye.at(1.0).z, 3.5f);
    try {
        lightPath->set(&f, "0:1,0,0,0;1,0,0,0");
        ADD_FAILURE() << "equal key times were accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_EQ(std::string(e.what()), lightPath->flag + " 0:1,0,0,0;1,0,0,0: key times must increase");
    }
    EXPECT_EQ(f.parsedMotion.lights.size(), 1u) << "a refused value adds no path";
}

}  // namespace
}  // namespace penumbra::test
