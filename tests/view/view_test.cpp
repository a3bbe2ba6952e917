// The viewer (`penumbra view`) on an Xvfb of the test's own (x_server.h) on lavapipe with validation
// on: a scripted session whose every screenshot equals the headless `penumbra render` of the same
// options, script errors and the missing display as one error line (penumbra's stderr alone).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <fmt/format.h>
#include <stb_image.h>
#include <sys/wait.h>
#include <unistd.h>

#include "view/script.h"
#include "view/session.h"
#include "x_server.h"

namespace fs = std::filesystem;

namespace penumbra::view {
namespace {

struct ShellResult {
    int status = -1;
    std::string out, err;
};

std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Runs a shell command line (lavapipe pinned by the test's environment), capturing both streams.
ShellResult shell(const std::string& command, const fs::path& dir) {
    const fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
    const int raw = std::system((command + " >" + out.string() + " 2>" + err.string()).c_str());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(out), slurp(err)};
}

::testing::AssertionResult haveDisplay() {
    const XServer& x = XServer::instance();
    return x.error().empty() ? ::testing::AssertionSuccess() : ::testing::AssertionFailure() << x.error();
}

// penumbra alone on the test's X server: its stderr is all that the tests read.
std::string viewCommand(const fs::path& script, const std::string& extra = "") {
    return "env DISPLAY=" + XServer::instance().display() + " " + PENUMBRA_BIN + " view --validate --script " +
           script.string() + " " + extra;
}

// A directory per process (a second checkout's tests may run at the same time), removed when the
// test passed and kept with a failure's files.
struct Scratch {
    fs::path dir;
    explicit Scratch(const std::string& name)
        : dir(fs::temp_directory_path() / fmt::format("penumbra_view_test_{}_{}", name, getpid())) {
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    ~Scratch() {
        if (!::testing::Test::HasFailure()) fs::remove_all(dir);
    }
};

// Largest per-channel difference between two PNGs of the same size (RGB), in 1/255 steps.
int maxDifference(const fs::path& a, const fs::path& b, std::string& why) {
    int wa, ha, wb, hb, n;
    stbi_uc* pa = stbi_load(a.c_str(), &wa, &ha, &n, 4);
    stbi_uc* pb = stbi_load(b.c_str(), &wb, &hb, &n, 4);
    int worst = 256;
    if (!pa || !pb) why = "cannot read " + (pa ? b : a).string();
    else if (wa != wb || ha != hb) why = fmt::format("sizes differ: {}x{} vs {}x{}", wa, ha, wb, hb);
    else {
        worst = 0;
        for (int i = 0; i < wa * ha * 4; ++i)
            if (i % 4 != 3) worst = std::max(worst, std::abs(int(pa[i]) - int(pb[i])));
    }
    stbi_image_free(pa);
    stbi_image_free(pb);
    return worst;
}

// One state of the scripted session: the lines that reach it and the options `render` gets for it.
struct State {
    std::vector<std::pair<std::string, std::string>> sets;  // `set OPTION VALUE`
    std::string extraLines;                                   // other script lines (camera, light)
    std::vector<std::string> extraArgs;                       // their render options
};

TEST(ViewScript, EveryScreenshotEqualsTheHeadlessRender) {
    const Scratch scratch("session");
    const fs::path& dir = scratch.dir;
    const std::string camera = "0.3,1.2,3.2,0,0.9,0,0,1,0,50";
    const std::string light = "spot,0.2,1.9,0.1,0,-1,0,4,50";
    const std::vector<State> states = {
        {{{"width", "96"}, {"height", "64"}}},
        {{{"shadow", "pcf"}, {"pcf-radius", "2.5"}}},
        {{{"shadow", "pcss"}}},
        {{{"shadow", "vsm"}}},
        {{{"shadow", "evsm"}, {"shadow-res", "256"}}},
        {{{"shadow", "msm"}, {"vsm-blur", "2"}}},
        {{{"gi", "rsm"}, {"rsm-res", "128"}, {"rsm-samples", "64"}}},
        {{{"aov", "indirect"}, {"rsm-mode", "full"}, {"rsm-res", "64"}}},
        {{{"gi", "lpv"}, {"lpv-vpl-res", "64"}, {"lpv-rsm-res", "256"}, {"lpv-res", "16"}}},
        {{{"lpv-slice", "8"}, {"aov", "lpv-slice"}}},
        {{{"aov", "gv-slice"}, {"lpv-slice-axis", "2"}}},
        {{{"aov", "normal"}, {"width", "80"}, {"height", "48"}}},
        {{{"aov", "depth"}, {"gi", "none"}}},
        {{{"aov", "shadow"}}},
        {{{"aov", "cascade"}}},
        {{{"aov", "albedo"}}, "probe 40 30\n"},  // the pinned pixel probe leaves the image alone
        // cornell's default motion (the spot light sweeps) at t = 0.4 s, as `render --time 0.4`
        {{{"aov", "final"}}, "time 0.4\n", {"--time", "0.4"}},
        {{{"aov", "final"}, {"exposure", "1.7"}}, "time 0\ncamera " + camera + "\nlight 0 " + light + "\n",
         {"--camera", camera, "--light", light}},
        {{{"scene", "hair"}, {"strands", "200"}, {"shadow", "dsm"}, {"exposure", "1"}}},
        {{{"aov", "dsm-lists"}, {"dsm-res", "256"}}},
    };
    std::string script;
    // Options on the view's command line hold until a `set` replaces them. The GI without its history:
    // a screenshot after some frames equals a one-frame render.
    // A fixed exposure: the viewer's auto exposure adapts over frames, a one-frame render takes its target at once.
    std::map<std::string, std::string> options = {
        {"shadow-res", "512"}, {"pcf-radius", "1"}, {"gi-temporal", "off"}, {"exposure", "1"}};
    std::vector<std::vector<std::string>> renderArgs;
    std::vector<std::string> extra;
    for (size_t i = 0; i < states.size(); ++i) {
        for (const auto& [option, value] : states[i].sets) {
            script += fmt::format("set {} {}\n", option, value);
            options[option] = value;
        }
        script += states[i].extraLines + fmt::format("screenshot {}\n", (dir / fmt::format("view{}.png", i)).string());
        if (options.count("scene")) extra.clear();  // the camera and light belonged to cornell
        if (!states[i].extraArgs.empty()) extra = states[i].extraArgs;
        std::vector<std::string> args;
        for (const auto& [option, value] : options)
            if (option == "scene") args.insert(args.begin(), value);
            else args.insert(args.end(), {"--" + option, value});
        args.insert(args.end(), extra.begin(), extra.end());
        renderArgs.push_back(args);
    }
    std::ofstream(dir / "session.txt") << script;
    ASSERT_TRUE(haveDisplay());
    const ShellResult view = shell(viewCommand(dir / "session.txt", "--shadow-res 512 --pcf-radius 1 --gi-temporal off --exposure 1"), dir);
    ASSERT_EQ(view.status, 0) << view.out << view.err;

    for (size_t i = 0; i < states.size(); ++i) {
        std::string cmd = std::string(PENUMBRA_BIN) + " render -q -o " + (dir / fmt::format("render{}.png", i)).string();
        for (const std::string& a : renderArgs[i]) cmd += " '" + a + "'";
        const ShellResult render = shell(cmd, dir);
        ASSERT_EQ(render.status, 0) << cmd << "\n" << render.err;
        std::string why;
        const int diff = maxDifference(dir / fmt::format("view{}.png", i), dir / fmt::format("render{}.png", i), why);
        EXPECT_LE(diff, 2) << "state " << i << " (" << cmd << ") " << why;
    }
}

// A bad line stops the viewer with one error line naming the file and the line.
TEST(ViewScript, BadLineIsOneErrorWithFileAndLine) {
    const Scratch scratch("bad");
    const fs::path& dir = scratch.dir;
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"set shadow bogus", "--shadow"},
        {"set aov lpv-slice", "need --gi lpv"},  // a cross-option rule, checked when the set applies
        {"set lpv-res 3", "lpv-res"},
        {"warp 9", "unknown command 'warp'"},
        {"set rsm-per-cascade maybe", "on or off"},
        {"probe 12", "probe X Y"},
        {"time nan", "a time in seconds"},
        {"time inf", "a time in seconds"},
        {"time 1e7", "out of range"},
        {"frames 100001", "out of range [0, 100000]"},
        {"panels maybe", "panels on|off"},
        {"panels-state", "panels-state PATH"},
        {"light 0 directional,0,-1,0,1e9,3,3,3", "65504"},
    };
    ASSERT_TRUE(haveDisplay());
    for (const auto& [line, expected] : cases) {
        const fs::path script = dir / "bad.txt";
        std::ofstream(script) << "set width 64\nset height 48\n" << line << "\nscreenshot " << (dir / "x.png").string()
                              << "\n";
        const ShellResult r = shell(viewCommand(script), dir);
        EXPECT_NE(r.status, 0) << line;
        EXPECT_EQ(r.err.rfind("penumbra: error: " + script.string() + ":3: ", 0), 0u) << line << ": " << r.err;
        EXPECT_NE(r.err.find(expected), std::string::npos) << line << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << line << ": " << r.err;
        EXPECT_FALSE(fs::exists(dir / "x.png")) << line;
    }
}

// A screenshot the disk cannot hold stops the viewer with one error naming the file.
TEST(ViewScript, ScreenshotToAFullDiskIsOneError) {
    const Scratch scratch("full");
    const fs::path& dir = scratch.dir;
    ASSERT_TRUE(haveDisplay());
    fs::create_symlink("/dev/full", dir / "full.png");
    const fs::path script = dir / "full.txt";
    std::ofstream(script) << "set width 64\nset height 48\nscreenshot " << (dir / "full.png").string() << "\n";
    const ShellResult r = shell(viewCommand(script), dir);
    EXPECT_NE(r.status, 0);
    EXPECT_EQ(r.err.rfind("penumbra: error: cannot write " + (dir / "full.png").string(), 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(ViewScript, NoDisplayIsOneError) {
    const Scratch scratch("nodisplay");
    const fs::path& dir = scratch.dir;
    const ShellResult r = shell(std::string("env -u DISPLAY -u WAYLAND_DISPLAY ") + PENUMBRA_BIN + " view", dir);
    EXPECT_NE(r.status, 0);
    EXPECT_EQ(r.err.rfind("penumbra: error: no display", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("penumbra render"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

}  // namespace
}  // namespace penumbra::view
