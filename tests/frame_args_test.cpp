// Options given as (flag, values) pairs (frame/frame_args.h, the viewer's way) parse to exactly what
// the command line's CLI11 parser makes of the same arguments, and fail with the same message.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/frame_cli.h"
#include "frame/frame_args.h"

namespace penumbra {
namespace {

// The arguments through CLI11 and the frame rows' registration, as `penumbra render` parses them.
ParsedFrame parseWithCli(const std::vector<FrameArg>& args) {
    ParsedFrame p;
    CLI::App app;
    addFrameOptions(app, p.options, p.settings);
    std::vector<std::string> argv;
    for (const FrameArg& a : args)
        for (const std::string& v : a.values) argv.push_back(a.name == "scene" ? v : a.name + "=" + v);
    std::reverse(argv.begin(), argv.end());  // CLI11 takes its vector last argument first
    try {
        app.parse(argv);
    } catch (const CLI::ParseError& e) {
        throw std::invalid_argument(e.what());
    }
    checkFrameSettings(p.options, p.settings);
    return p;
}

// Every option's value as its row writes it, and the parsed inputs beside their text.
void expectSameFrame(const ParsedFrame& a, const ParsedFrame& b) {
    const std::vector<FrameOptionRef> ra = frameOptionRefs(a), rb = frameOptionRefs(b);
    ASSERT_EQ(ra.size(), rb.size());
    EXPECT_EQ(a.options.scene, b.options.scene);
    for (size_t i = 0; i < ra.size(); ++i)
        if (ra[i].row) EXPECT_EQ(ra[i].row->value(ra[i].settings), rb[i].row->value(rb[i].settings)) << ra[i].name;
    EXPECT_EQ(a.options.parsedCamera.has_value(), b.options.parsedCamera.has_value());
    ASSERT_EQ(a.options.parsedLights.size(), b.options.parsedLights.size());
    for (size_t i = 0; i < a.options.parsedLights.size(); ++i)
        EXPECT_EQ(a.options.parsedLights[i].intensity, b.options.parsedLights[i].intensity);
    EXPECT_EQ(a.options.parsedMotion.sun.has_value(), b.options.parsedMotion.sun.has_value());
    EXPECT_EQ(a.options.parsedMotion.builtinDefault, b.options.parsedMotion.builtinDefault);
    EXPECT_EQ(a.settings.dsm.enabled, b.settings.dsm.enabled);
}

TEST(FrameArgs, ParseAsTheCommandLineDoes) {
    const std::vector<std::vector<FrameArg>> cases{
        {},
        {{"scene", {"street"}}, {"--width", {"320"}}, {"--shadow", {"pcf,dsm"}}, {"--gi", {"lpv"}}},
        {{"--light", {"directional,0,-1,0,3", "point,0,1,0,5"}}, {"--light-shadow", {"1=pcss"}},
         {"--clamp", {"true"}}, {"--no-motion", {"true"}}, {"--time", {"2.5"}}},
        {{"--clamp", {"off"}}, {"--camera", {"0,1,3,0,1,0,0,1,0,45"}}, {"--sun-path", {"0,10,90,40,5"}},
         {"--rsm-per-cascade", {"on"}}, {"--aov", {"shadow"}}, {"scene", {"cornell"}}},
        {{"scene", {"street"}}, {"--exposure", {"0.5"}}, {"--camera-index", {"0"}}},
    };
    for (const std::vector<FrameArg>& args : cases) {
        SCOPED_TRACE(args.empty() ? std::string("defaults") : args.front().name);
        const ParsedFrame rows = parseFrameArgs(args);
        expectSameFrame(rows, parseWithCli(args));
        // Given in another order, the rows still run in the command line's order.
        const std::vector<FrameArg> reversed(args.rbegin(), args.rend());
        expectSameFrame(parseFrameArgs(reversed), rows);
    }
}

TEST(FrameArgs, RefuseAsTheCommandLineDoes) {
    for (const std::vector<FrameArg>& args : std::vector<std::vector<FrameArg>>{
             {{"--shadow-res", {"8"}}},
             {{"--light", {"directional,0,0,0,1"}}},
             {{"--aov", {"lpv-slice"}}},  // a rule between options: needs --gi lpv
             {{"--camera-index", {"-1"}}}}) {
        std::string rowsError, cliError;
        try {
            parseFrameArgs(args);
        } catch (const std::invalid_argument& e) {
            rowsError = e.what();
        }
        try {
            parseWithCli(args);
        } catch (const std::invalid_argument& e) {
            cliError = e.what();
        }
        EXPECT_FALSE(rowsError.empty()) << args.front().name;
        EXPECT_EQ(rowsError, cliError) << args.front().name;
    }
    EXPECT_THROW(parseFrameArgs({{"--no-such-option", {"1"}}}), std::invalid_argument);
    EXPECT_THROW(parseFrameArgs({{"--width", {"64", "32"}}}), std::invalid_argument);  // one value
}

}  // namespace
}  // namespace penumbra
