// The deep shadow maps' options on the command line (the penumbra executable run as a child process
// on lavapipe): bad input, a point light's maps that would not fit, a pool too small, a scene with
// nothing to cast.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "cli_run.h"

using namespace penumbra::test;
namespace fs = std::filesystem;

// Each bad DSM option or combination: one "penumbra: error:" line and a non-zero exit.
TEST(DsmCli, BadInputGivesOneErrorLine) {
    ScratchDir dir;
    const std::string out = dir.file("x.png");
    const std::vector<std::string> bad{
        "render hair --strands -1 -o " + out,
        "render hair --strands 0 -o " + out,
        "render hair --shadow dsmm -o " + out,
        "render hair --shadow dsm --dsm-nodes 99999999999 -o " + out,
        "render hair --shadow dsm --dsm-max-list 500 -o " + out,
        "render hair --aov transmittance -o " + out,
        "render hair --dsm-lights 3 --strands 10 --width 8 --height 8 -o " + out,
        "render hair --shadow dsm --dsm-filter 20 -o " + out,
        // Six cube faces of 2048^2 need 1152 MiB of heads, work list and buckets: more than lavapipe's half.
        "render hair --shadow dsm --light point,0.3,1,0.4,3 --dsm-res 2048 --strands 10 -o " + out,
    };
    for (const std::string& args : bad) expectRefused(dir, args);
}

// A point light's DSM at the shadow maps' resolution (2048^2, six faces) would not fit lavapipe's
// memory: taken by default, the resolution halves with one warning and the frame renders.
TEST(DsmCli, DefaultResolutionHalvesWhereTheMapsDoNotFit) {
    ScratchDir dir;
    const Cli r = runCli(dir, "render hair --strands 200 --shadow dsm --light point,0.3,1,0.4,3 --width 64 --height 48 "
                              "-o " + dir.file("hair.png"));
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("penumbra: warning: --shadow dsm: 6 deep shadow map(s) of 2048^2 would take 1152 MiB"),
              std::string::npos) << r.err;
    EXPECT_NE(r.out.find("dsm: 6 map(s) of 1024^2"), std::string::npos) << r.out;
    EXPECT_TRUE(fs::exists(dir.file("hair.png")));
}

// A pool far too small: the run succeeds, warns with the number of dropped fragments and reports.
TEST(DsmCli, SmallPoolWarnsAndReports) {
    ScratchDir dir;
    const Cli r = runCli(dir, "render hair --strands 200 --shadow pcf,dsm --dsm-nodes 1000 --width 64 --height 48 "
                              "--shadow-res 128 -o " + dir.file("hair.png"));
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("penumbra: warning: deep shadow map node pool overflow: "), std::string::npos) << r.err;
    EXPECT_NE(r.out.find("dsm: 1 map(s) of 128^2"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("dsm.resolve"), std::string::npos) << r.out;
    EXPECT_TRUE(fs::exists(dir.file("hair.png")));
}

// A deep shadow map with nothing to cast (cornell: no hair, no BLEND material) builds empty maps
// under both rasterizers: the build once bound a raster pipeline that did not exist and crashed.
TEST(DsmCli, SceneWithoutTranslucentCastersRenders) {
    ScratchDir dir;
    for (const char* raster : {"hardware", "compute"}) {
        const Cli r = runCli(dir, fmt::format("render cornell --shadow dsm --raster {} --width 32 --height 24 "
                                              "--shadow-res 64 -o {}", raster, dir.file("cornell.png")));
        EXPECT_EQ(r.status, 0) << raster << ": " << r.err;
        EXPECT_NE(r.out.find("dsm: 1 map(s) of 64^2: 0 light-space fragments"), std::string::npos) << r.out;
    }
}
