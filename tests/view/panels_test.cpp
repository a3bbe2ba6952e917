// The viewer's panels (`penumbra view` on the test's own Xvfb, lavapipe, validation on): after `set`
// they show the frame of the new settings (pass table, pixel probe, option values), they cover at
// most a quarter of a 960x540 window, and `panels off` hides them. Read from `panels-state` files.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include "x_server.h"

namespace fs = std::filesystem;

namespace penumbra::view {
namespace {

// One `panels-state` file, parsed.
struct ShownState {
    float coverage = -1.0f;
    std::vector<std::string> windows, passes;
    std::map<std::string, std::string> options;
    std::map<std::string, std::vector<float>> probe;
};

ShownState readState(const fs::path& path) {
    ShownState s;
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        std::string kind, name;
        words >> kind >> name;
        if (kind == "coverage") s.coverage = std::stof(name);
        else if (kind == "window") s.windows.push_back(name);
        else if (kind == "pass") s.passes.push_back(name);
        else if (kind == "option") std::getline(words >> std::ws, s.options[name]);
        else if (kind == "probe")
            for (float v; words >> v;) s.probe[name].push_back(v);
    }
    return s;
}

bool anyPassStartsWith(const std::vector<std::string>& passes, const std::string& prefix) {
    return std::any_of(passes.begin(), passes.end(), [&](const std::string& p) { return p.rfind(prefix, 0) == 0; });
}

std::string joined(const std::vector<std::string>& words) {
    std::string out;
    for (const std::string& w : words) out += w + " ";
    return out;
}

TEST(ViewPanels, FollowSetAndCoverAQuarter) {
    ASSERT_TRUE(XServer::instance().error().empty()) << XServer::instance().error();
    const fs::path dir = fs::temp_directory_path() / fmt::format("penumbra_view_test_panels_{}", getpid());
    fs::remove_all(dir);
    fs::create_directories(dir);
    const auto state = [&](const char* name) { return (dir / name).string(); };
    std::ofstream(dir / "panels.txt") << "set width 960\nset height 540\nset gi rsm\nset shadow pcf\n"
                                      << "probe 480 300\nframes 2\npanels-state " << state("rsm.txt") << "\n"
                                      << "set gi lpv\nset shadow pcss\nframes 2\npanels-state " << state("lpv.txt")
                                      << "\nset gi none\nframes 2\npanels-state " << state("none.txt") << "\n"
                                      << "panels off\npanels-state " << state("off.txt") << "\n"
                                      << "panels on\npanels-state " << state("on.txt") << "\n";
    const std::string command = fmt::format("env DISPLAY={} {} view --validate --script {} --rsm-res 64 --lpv-res 16 "
                                            ">{} 2>&1",
                                            XServer::instance().display(), PENUMBRA_BIN, (dir / "panels.txt").string(),
                                            (dir / "out.txt").string());
    const int raw = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0) << command;

    const ShownState rsm = readState(dir / "rsm.txt"), lpv = readState(dir / "lpv.txt");
    const ShownState none = readState(dir / "none.txt"), off = readState(dir / "off.txt");
    const ShownState on = readState(dir / "on.txt");
    // The GI technique's passes come and go with `set gi`; the values are those of the settings.
    EXPECT_EQ(rsm.options.at("gi"), "rsm");
    EXPECT_TRUE(anyPassStartsWith(rsm.passes, "rsm.")) << joined(rsm.passes);
    EXPECT_EQ(lpv.options.at("gi"), "lpv");
    EXPECT_EQ(lpv.options.at("shadow"), "pcss");
    EXPECT_TRUE(anyPassStartsWith(lpv.passes, "lpv.")) << joined(lpv.passes);
    EXPECT_FALSE(anyPassStartsWith(lpv.passes, "rsm.flux-")) << joined(lpv.passes);
    EXPECT_EQ(none.options.at("gi"), "none");
    EXPECT_FALSE(none.passes.empty());
    EXPECT_FALSE(anyPassStartsWith(none.passes, "lpv.")) << joined(none.passes);
    EXPECT_FALSE(anyPassStartsWith(none.passes, "rsm.")) << joined(none.passes);
    // The probe reads the new frame: with GI on, the lit floor point gets indirect light; without, none.
    ASSERT_EQ(lpv.probe.count("indirect"), 1u);
    ASSERT_EQ(none.probe.count("indirect"), 1u);
    EXPECT_GT(lpv.probe.at("indirect")[0] + lpv.probe.at("indirect")[1] + lpv.probe.at("indirect")[2], 0.0f);
    for (float v : none.probe.at("indirect")) EXPECT_EQ(v, 0.0f);
    // All three windows (scene, timings, probe) at 960x540 cover at most a quarter; off hides them.
    EXPECT_EQ(lpv.windows.size(), 3u) << joined(lpv.windows);
    EXPECT_GT(lpv.coverage, 0.05f);
    EXPECT_LE(lpv.coverage, 0.25f);
    EXPECT_TRUE(off.windows.empty()) << joined(off.windows);
    EXPECT_EQ(off.coverage, 0.0f);
    EXPECT_EQ(on.windows.size(), 3u);
    if (!::testing::Test::HasFailure()) fs::remove_all(dir);
}

}  // namespace
}  // namespace penumbra::view
