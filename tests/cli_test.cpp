// End-to-end tests of the penumbra executable (PENUMBRA_BIN) run as a child process on lavapipe:
// successful PNG/EXR renders read back from disk, help and info, and for every bad input exactly one
// "penumbra: error:" line on stderr with a non-zero exit status (never a crash or a hang).
#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <stb_image.h>
#include <tinyexr.h>

#include "dsm/dsm_options.h"
#include "renderer/render_options.h"

extern char** environ;

namespace fs = std::filesystem;

namespace {

constexpr int kTimeoutSeconds = 60;

struct ProcessResult {
    bool started = false;
    bool timedOut = false;
    bool signaled = false;  // terminated by a signal (crash)
    int signal = 0;
    int exitCode = -1;
    std::string out, err;
};

std::string describe(const ProcessResult& r) {
    std::string s;
    if (!r.started) return "could not start the process";
    if (r.timedOut) s += "TIMED OUT; ";
    if (r.signaled) s += "killed by signal " + std::to_string(r.signal) + " (" + strsignal(r.signal) + "); ";
    else s += "exit code " + std::to_string(r.exitCode) + "; ";
    return s + "stdout:\n" + r.out + "\nstderr:\n" + r.err;
}

// Runs PENUMBRA_BIN with `args`, the current environment plus lavapipe and `extraEnv`, capturing both
// output streams; kills the child and reports a timeout after kTimeoutSeconds.
ProcessResult runPenumbra(const std::vector<std::string>& args, const std::vector<std::string>& extraEnv = {}) {
    ProcessResult r;
    // Everything the child needs is built before fork(): after it only async-signal-safe calls follow.
    std::vector<std::string> env;
    for (char** e = environ; *e; ++e) {
        const std::string kv = *e;
        if (kv.rfind("VK_DRIVER_FILES=", 0) == 0 || kv.rfind("VK_ICD_FILENAMES=", 0) == 0 ||
            kv.rfind("PENUMBRA_HIDE_FEATURES=", 0) == 0)
            continue;
        env.push_back(kv);
    }
    env.push_back("VK_DRIVER_FILES=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json");
    for (const std::string& kv : extraEnv) env.push_back(kv);
    std::vector<char*> envp;
    for (std::string& kv : env) envp.push_back(kv.data());
    envp.push_back(nullptr);
    std::vector<std::string> argStrings{PENUMBRA_BIN};
    argStrings.insert(argStrings.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : argStrings) argv.push_back(a.data());
    argv.push_back(nullptr);

    int outPipe[2], errPipe[2];
    if (pipe2(outPipe, O_CLOEXEC) != 0) return r;
    if (pipe2(errPipe, O_CLOEXEC) != 0) {
        close(outPipe[0]), close(outPipe[1]);
        return r;
    }
    const pid_t pid = fork();
    if (pid < 0) {
        for (int fd : {outPipe[0], outPipe[1], errPipe[0], errPipe[1]}) close(fd);
        return r;
    }
    if (pid == 0) {
        dup2(outPipe[1], STDOUT_FILENO);
        dup2(errPipe[1], STDERR_FILENO);
        const int devnull = open("/dev/null", O_RDONLY);
        if (devnull >= 0) dup2(devnull, STDIN_FILENO);
        execve(argv[0], argv.data(), envp.data());
        _exit(127);
    }
    r.started = true;
    close(outPipe[1]);
    close(errPipe[1]);

    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(kTimeoutSeconds);
    pollfd fds[2] = {{outPipe[0], POLLIN, 0}, {errPipe[0], POLLIN, 0}};
    std::string* sinks[2] = {&r.out, &r.err};
    int openStreams = 2;
    while (openStreams > 0) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            r.timedOut = true;
            break;
        }
        const int n = poll(fds, 2, int(left.count()));
        if (n < 0) {
            if (errno == EINTR) continue;
            break;
        }
        for (int i = 0; i < 2; ++i) {
            if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
            char buf[4096];
            const ssize_t got = read(fds[i].fd, buf, sizeof(buf));
            if (got > 0) {
                sinks[i]->append(buf, size_t(got));
            } else if (got == 0 || errno != EINTR) {
                close(fds[i].fd);
                fds[i].fd = -1;
                --openStreams;
            }
        }
    }
    for (pollfd& f : fds)
        if (f.fd >= 0) close(f.fd);

    int status = 0;
    if (r.timedOut) {
        kill(pid, SIGKILL);
        waitpid(pid, &status, 0);
        return r;
    }
    // Streams are closed; the child exits right after, but keep the deadline for the wait as well.
    while (true) {
        const pid_t w = waitpid(pid, &status, WNOHANG);
        if (w == pid) break;
        if (std::chrono::steady_clock::now() > deadline) {
            r.timedOut = true;
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            return r;
        }
        usleep(1000);
    }
    if (WIFSIGNALED(status)) {
        r.signaled = true;
        r.signal = WTERMSIG(status);
    } else if (WIFEXITED(status)) {
        r.exitCode = WEXITSTATUS(status);
    }
    return r;
}

struct TempDir {
    fs::path path;
    TempDir() {
        static std::atomic<int> counter{0};
        path = fs::temp_directory_path() /
               ("penumbra_cli_test_" + std::to_string(getpid()) + "_" + std::to_string(counter++));
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    std::string file(const std::string& name) const { return (path / name).string(); }
};

void expectCleanExit(const ProcessResult& r) {
    ASSERT_TRUE(r.started);
    EXPECT_FALSE(r.timedOut) << describe(r);
    EXPECT_FALSE(r.signaled) << describe(r);
    EXPECT_EQ(r.exitCode, 0) << describe(r);
}

}  // namespace

TEST(Cli, RendersPngOfRequestedSize) {
    TempDir tmp;
    const std::string out = tmp.file("cornell.png");
    const ProcessResult r = runPenumbra({"render", "cornell", "-o", out, "--width", "64", "--height", "48", "--validate"});
    expectCleanExit(r);
    EXPECT_EQ(r.err, "") << "nothing on stderr with --validate: " << describe(r);
    int w = 0, h = 0, channels = 0;
    unsigned char* pixels = stbi_load(out.c_str(), &w, &h, &channels, 4);
    ASSERT_NE(pixels, nullptr) << "cannot read back " << out << ": " << stbi_failure_reason();
    EXPECT_EQ(w, 64);
    EXPECT_EQ(h, 48);
    size_t lit = 0;
    for (int i = 0; i < w * h; ++i) lit += pixels[i * 4] > 0 || pixels[i * 4 + 1] > 0 || pixels[i * 4 + 2] > 0;
    stbi_image_free(pixels);
    EXPECT_GT(lit, size_t(w * h / 4)) << "too little of the Cornell box is lit";
}

// A deep shadow map of 4096^2 (the size the 16384 refusal once recommended): its work list is 16
// bytes over lavapipe's storage-buffer range, so it is refused before any work, and the size the
// refusal suggests renders under validation with nothing on stderr.
TEST(Cli, DsmResAdviceRendersUnderValidation) {
    TempDir tmp;
    const std::string out = tmp.file("dsm.png");
    using namespace penumbra;
    const OptionTable& frame = frameOptionTable();
    using S = RenderSettings;
    const std::string dsmRes = dsmOptions().flagOf<DsmSettings>([](DsmSettings& x) -> auto& { return x.resolution; });
    const std::vector<std::string> base = {"render", "cornell", "-o", out,
                                           frame.flagOf<S>([](S& x) -> auto& { return x.shadow.filter; }), "pcf,dsm",
                                           frame.flagOf<S>([](S& x) -> auto& { return x.width; }), "32",
                                           frame.flagOf<S>([](S& x) -> auto& { return x.height; }), "24", "--validate"};
    std::vector<std::string> args = base;
    args.insert(args.end(), {dsmRes, "4096"});
    const ProcessResult refused = runPenumbra(args);
    ASSERT_TRUE(refused.started);
    EXPECT_NE(refused.exitCode, 0) << describe(refused);
    EXPECT_EQ(refused.err.rfind("penumbra: error:", 0), 0u) << describe(refused);
    EXPECT_FALSE(fs::exists(out)) << "refused before any work";
    std::smatch m;
    ASSERT_TRUE(std::regex_search(refused.err, m, std::regex("the largest " + dsmRes + " that fits is ([0-9]+)")))
        << describe(refused);
    EXPECT_LT(std::stoi(m[1].str()), 4096);
    args = base;
    args.insert(args.end(), {dsmRes, m[1].str()});
    const ProcessResult r = runPenumbra(args);
    expectCleanExit(r);
    EXPECT_EQ(r.err, "") << "nothing on stderr with --validate: " << describe(r);
    EXPECT_TRUE(fs::exists(out));
}

TEST(Cli, RendersExrWithFiniteNonNegativeValues) {
    TempDir tmp;
    const std::string out = tmp.file("cornell.exr");
    const ProcessResult r = runPenumbra({"render", "cornell", "-o", out, "--width", "64", "--height", "48", "--validate"});
    expectCleanExit(r);
    EXPECT_EQ(r.err, "") << describe(r);
    float* rgba = nullptr;
    int w = 0, h = 0;
    const char* err = nullptr;
    const int rc = LoadEXR(&rgba, &w, &h, out.c_str(), &err);
    ASSERT_EQ(rc, TINYEXR_SUCCESS) << (err ? err : "LoadEXR failed");
    EXPECT_EQ(w, 64);
    EXPECT_EQ(h, 48);
    size_t bad = 0, positive = 0;
    for (int i = 0; i < w * h; ++i) {
        for (int c = 0; c < 3; ++c) bad += !std::isfinite(rgba[i * 4 + c]) || rgba[i * 4 + c] < 0.0f;
        positive += rgba[i * 4] > 0.0f;
    }
    free(rgba);
    EXPECT_EQ(bad, 0u);
    EXPECT_GT(positive, size_t(w * h / 4));
}

TEST(Cli, HelpPrintsUsage) {
    for (const std::vector<std::string>& args : {std::vector<std::string>{"--help"}, {"render", "--help"}}) {
        SCOPED_TRACE(args.back() + " after " + args.front());
        const ProcessResult r = runPenumbra(args);
        expectCleanExit(r);
        EXPECT_NE(r.out.find("Usage:"), std::string::npos) << describe(r);
    }
    const ProcessResult r = runPenumbra({"render", "--help"});
    for (const char* option : {"--width", "--height", "--output", "--aov", "--camera", "--light"})
        EXPECT_NE(r.out.find(option), std::string::npos) << option << " missing from render --help";
}

// Outputs are checked before the work: eval would otherwise path-trace its reference first.
TEST(Cli, UnwritableEvalOutputsFailBeforeTheWork) {
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"eval", "cornell", "--images", "/proc/penumbra-figure"},
          {"eval", "cornell", "--json", "/proc/penumbra.json"}, {"bench", "cornell", "--json", "/proc/p.json"}}) {
        SCOPED_TRACE(args[2]);
        const auto start = std::chrono::steady_clock::now();
        const ProcessResult r = runPenumbra(args);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        EXPECT_NE(r.exitCode, 0) << describe(r);
        EXPECT_EQ(r.err.rfind("penumbra: error: " + args[2] + " /proc/", 0), 0u) << describe(r);
        EXPECT_LT(seconds, 5.0) << "the error came after the work";
    }
}

// 200000 nodes (400000 triangles over two materials) rendered at 64^2: the draws are merged at load
// time (GltfScale tests the structure). CPU time of the child (lavapipe's threads included), so that a
// busy machine does not decide; the target is under 10 s.
TEST(Cli, TwoHundredThousandNodesRenderFast) {
    TempDir tmp;
    const std::string file = tmp.file("many.gltf");
    {
        std::ofstream f(file);
        f << R"({"asset":{"version":"2.0"},"scene":0,"materials":[{},{"doubleSided":true}],)"
          << R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0},)"
          << R"({"attributes":{"POSITION":0},"material":1}]}],)"
          << R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}],)"
          << R"("bufferViews":[{"buffer":0,"byteLength":36}],"buffers":[{"byteLength":36,"uri":)"
          << R"("data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],"nodes":[)";
        for (int i = 0; i < 200000; ++i)
            f << (i ? "," : "") << R"({"mesh":0,"translation":[)" << (i % 448) * 1.5 << ",0," << (i / 448) * 1.5 << "]}";
        f << R"(],"scenes":[{"nodes":[)";
        for (int i = 0; i < 200000; ++i) f << (i ? "," : "") << i;
        f << "]}]}";
    }
    rusage before{}, after{};
    getrusage(RUSAGE_CHILDREN, &before);
    const ProcessResult r = runPenumbra({"render", file, "-o", tmp.file("many.png"), "--width", "64", "--height", "64"});
    getrusage(RUSAGE_CHILDREN, &after);
    expectCleanExit(r);
    EXPECT_NE(r.out.find("400000 triangles"), std::string::npos) << r.out;
    auto seconds = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
    const double cpu = seconds(after.ru_utime) + seconds(after.ru_stime) - seconds(before.ru_utime) -
                       seconds(before.ru_stime);
    std::printf("200000 nodes at 64x64: %.2f s CPU\n", cpu);
#if !defined(__SANITIZE_ADDRESS__)
    EXPECT_LT(cpu, 10.0);
#endif
}

// More timed scopes than one query pool holds (LPV: one per propagation step).
TEST(Cli, LpvWithManyIterationsRenders) {
    TempDir tmp;
    const ProcessResult r = runPenumbra({"render", "cornell", "-o", tmp.file("lpv.png"), "--gi", "lpv",
                                         "--lpv-iterations", "256", "--width", "16", "--height", "16", "--validate"});
    expectCleanExit(r);
    size_t steps = 0;
    for (size_t at = r.out.find("lpv.propagate"); at != std::string::npos; at = r.out.find("lpv.propagate", at + 1))
        ++steps;
    EXPECT_EQ(steps, 256u) << r.out;
}

TEST(Cli, InfoListsADevice) {
    const ProcessResult r = runPenumbra({"info"});
    expectCleanExit(r);
    EXPECT_NE(r.out.find("device 0:"), std::string::npos) << describe(r);
    EXPECT_NE(r.out.find("usable"), std::string::npos) << describe(r);
}

// ---- Bad inputs: exit status != 0, exactly one stderr line "penumbra: error: ...", no output file ----

struct BadInput {
    std::string name;
    std::vector<std::string> args;  // "{out}" is the output path in a temp dir, "{dir}" the temp dir
    std::string mentions;           // a word the error line must contain
    std::vector<std::string> env;
};

// gtest prints parameters on failure and in the CTest names: the case name is enough.
void PrintTo(const BadInput& c, std::ostream* os) { *os << c.name; }

class CliBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(CliBadInput, OneErrorLineAndNonZeroExit) {
    const BadInput& c = GetParam();
    TempDir tmp;
    const std::string out = tmp.file("out.png");
    {  // Inputs some cases refer to.
        std::ofstream garbage(tmp.file("garbage.gltf"), std::ios::binary);
        garbage << "\x89this is { not [ a glTF \x01\x02\x03 file at all";
        std::ofstream truncated(tmp.file("truncated.exr"), std::ios::binary);
        truncated << "v/1\x01\x02\x00\x00\x00channels\x00chlist\x00";  // an EXR header cut short
        fs::create_directories(tmp.path / "subdir");
        fs::create_directories(tmp.path / "image.png");
    }
    std::vector<std::string> args;
    for (std::string a : c.args) {
        if (a == "{out}") a = out;
        else if (a.rfind("{dir}", 0) == 0) a = tmp.path.string() + a.substr(5);
        args.push_back(a);
    }
    const ProcessResult r = runPenumbra(args, c.env);
    ASSERT_TRUE(r.started);
    EXPECT_FALSE(r.timedOut) << describe(r);
    EXPECT_FALSE(r.signaled) << describe(r);
    EXPECT_NE(r.exitCode, 0) << describe(r);
    EXPECT_EQ(r.err.rfind("penumbra: error:", 0), 0u) << describe(r);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "expected exactly one line:\n" << r.err;
    EXPECT_EQ(r.err.back(), '\n') << r.err;
    EXPECT_NE(r.err.find(c.mentions), std::string::npos) << "the error should mention '" << c.mentions
                                                         << "':\n" << r.err;
    EXPECT_FALSE(fs::exists(out)) << "an output file was written despite the error";
}

INSTANTIATE_TEST_SUITE_P(
    Cli, CliBadInput,
    ::testing::Values(
        BadInput{"MissingSceneFile", {"render", "{dir}/no-such-scene.gltf", "-o", "{out}"}, "no-such-scene.gltf"},
        BadInput{"MalformedGltf", {"render", "{dir}/garbage.gltf", "-o", "{out}"}, "garbage.gltf"},
        BadInput{"UnknownBuiltinScene", {"render", "nosuchscene", "-o", "{out}"}, "nosuchscene"},
        BadInput{"UnknownOption", {"render", "cornell", "-o", "{out}", "--frobnicate"}, "--frobnicate"},
        BadInput{"WidthZero", {"render", "cornell", "-o", "{out}", "--width", "0"}, "--width"},
        BadInput{"HeightNegative", {"render", "cornell", "-o", "{out}", "--height", "-5"}, "--height"},
        BadInput{"WidthNotANumber", {"render", "cornell", "-o", "{out}", "--width", "abc"}, "--width"},
        BadInput{"JpgOutput", {"render", "cornell", "-o", "{dir}/out.jpg"}, ".jpg"},
        BadInput{"UnwritableOutput",
                 {"render", "cornell", "-o", "/nonexistent-dir/x.png", "--width", "32", "--height", "24"},
                 "/nonexistent-dir/x.png"},
        BadInput{"BadCamera", {"render", "cornell", "-o", "{out}", "--camera", "0,1,5,0,1"}, "--camera"},
        BadInput{"BadCameraNumber", {"render", "cornell", "-o", "{out}", "--camera", "0,1,5,0,1,0,0,1,0,x"},
                 "--camera"},
        BadInput{"BadLight", {"render", "cornell", "-o", "{out}", "--light", "laser,1,2,3"}, "--light"},
        BadInput{"BadLightNumber", {"render", "cornell", "-o", "{out}", "--light", "directional,0,-1,0,bright"},
                 "--light"},
        BadInput{"UnknownAov", {"render", "cornell", "-o", "{out}", "--aov", "specular"}, "specular"},
        BadInput{"UnknownGiMode", {"render", "cornell", "-o", "{out}", "--gi", "photons"}, "photons"},
        BadInput{"LpvSliceWithoutLpv", {"render", "cornell", "-o", "{out}", "--aov", "lpv-slice"}, "lpv-slice"},
        BadInput{"AllTexelsOnLargeRsm",
                 {"render", "cornell", "-o", "{out}", "--gi", "rsm", "--rsm-mode", "all-texels", "--rsm-res", "512"},
                 "--rsm-res"},
        BadInput{"BenchZeroFrames", {"bench", "cornell", "--frames", "0"}, "--frames"},
        BadInput{"BenchUnknownShadowMode", {"bench", "cornell", "--shadow", "blurry"}, "blurry"},
        BadInput{"BenchUnknownGiMode", {"bench", "cornell", "--gi", "magic"}, "magic"},
        // Numbers that are not finite, for every kind of float option (CLI11's Range lets NaN through).
        BadInput{"ExposureNaN", {"render", "cornell", "-o", "{out}", "--exposure", "nan"}, "--exposure"},
        BadInput{"RsmRadiusInf", {"render", "cornell", "-o", "{out}", "--rsm-radius", "inf"}, "--rsm-radius"},
        BadInput{"ShadowBiasNaN", {"render", "cornell", "-o", "{out}", "--shadow-bias-constant", "NaN"},
                 "--shadow-bias-constant"},
        BadInput{"NormalOffsetInf", {"render", "cornell", "-o", "{out}", "--shadow-normal-offset", "-inf"},
                 "--shadow-normal-offset"},
        BadInput{"DsmBiasNaN", {"render", "cornell", "-o", "{out}", "--dsm-bias", "nan"}, "--dsm-bias"},
        BadInput{"ReferenceExposureNaN", {"reference", "cornell", "-o", "{dir}/r.exr", "--exposure", "nan"},
                 "--exposure"},
        BadInput{"EvalExposureInf", {"eval", "cornell", "--exposure", "inf"}, "--exposure"},
        BadInput{"EvalIndirectExposureNaN", {"eval", "cornell", "--indirect-exposure", "nan"}, "--indirect-exposure"},
        BadInput{"EvalHairWithoutStrands", {"eval", "cornell", "--hair"}, "no hair strands"},
        BadInput{"EvalHairAndSuite", {"eval", "hair", "--hair", "--suite"}, "one evaluation at a time"},
        BadInput{"ReferenceStrandsZero", {"reference", "hair", "-o", "{dir}/r.exr", "--strands", "0"}, "--strands"},
        BadInput{"CameraAlongUp", {"render", "cornell", "-o", "{out}", "--camera", "0,5,0,0,0,0,0,1,0,40"}, "up"},
        BadInput{"TwoOpaqueFilters", {"render", "cornell", "-o", "{out}", "--shadow", "pcf,vsm"}, "pcf,vsm"},
        BadInput{"NegativeLightColour", {"render", "cornell", "-o", "{out}", "--light", "directional,0,-1,0,3,1,-1,1"},
                 "colour"},
        BadInput{"SpotInnerWiderThanOuter", {"render", "cornell", "-o", "{out}", "--light", "spot,0,1,0,0,-1,0,5,30,40"},
                 "inner"},
        BadInput{"IndirectWithoutGi", {"render", "cornell", "-o", "{out}", "--gi", "none", "--aov", "indirect"},
                 "--gi"},
        BadInput{"SceneIsDirectory", {"render", "{dir}/subdir", "-o", "{out}"}, "is a directory"},
        BadInput{"OutputIsDirectory", {"render", "cornell", "-o", "{dir}/image.png"}, "is a directory"},
        BadInput{"CompareTruncatedExr", {"compare", "{dir}/truncated.exr", "{dir}/truncated.exr"}, "truncated.exr"},
        BadInput{"UnknownCommand", {"frobnicate", "cornell"}, "unknown command 'frobnicate'"},
        BadInput{"NoCommand", {"--validate"}, "no command"},
        // Sizes the device cannot hold: refused with the option, the limit and the largest value that fits.
        BadInput{"LpvVplBeyondDispatchAndBuffer",
                 {"render", "cornell", "-o", "{out}", "--gi", "lpv", "--lpv-rsm-res", "8192", "--lpv-vpl-res", "8192"},
                 "the largest --lpv-vpl-res that fits"},
        BadInput{"ImageBeyondAllocation", {"render", "cornell", "-o", "{out}", "--width", "16384", "--height", "16384"},
                 "the largest --width that fits"},
        BadInput{"VsmMapBeyondAllocation", {"render", "cornell", "-o", "{out}", "--shadow", "vsm", "--shadow-res", "16384"},
                 "the largest --shadow-res that fits"},
        // A point light's 6 RSM layers at 2048^2 in the compute rasterizer's 64-bit depth-and-ID buffer:
        // 192 MiB, beyond lavapipe's 128 MiB storage-buffer range (it rendered with a validation error).
        BadInput{"ComputeRasterIdsBeyondStorageBuffer",
                 {"render", "cornell", "-o", "{out}", "--light", "point,0.75,0.9,0.6,2", "--gi", "lpv", "--raster",
                  "compute"},
                 "the largest --shadow-res that fits"},
        // The flux draws' CDF of an 8192^2 RSM: 256 MiB in one buffer, beyond lavapipe's 128 MiB range.
        BadInput{"RsmFluxCdfBeyondStorageBuffer",
                 {"render", "cornell", "-o", "{out}", "--gi", "rsm", "--rsm-res", "8192"},
                 "the largest --rsm-res that fits is 4096"},
        BadInput{"RsmVisibilityPointsZero",
                 {"render", "cornell", "-o", "{out}", "--rsm-visibility-points", "0"}, "--rsm-visibility-points"},
        BadInput{"StrandsBeyondStorageBuffer",
                 {"render", "hair", "-o", "{out}", "--strands", "2000000", "--shadow", "dsm"},
                 "the largest --strands that fits"},
        BadInput{"NoSuchDevice", {"render", "cornell", "-o", "{out}", "--device", "99", "--validate"}, "99"},
        BadInput{"DeviceMissingFeature",
                 {"render", "cornell", "-o", "{out}", "--width", "32", "--height", "24", "--validate"},
                 "dynamicRendering",
                 {"PENUMBRA_HIDE_FEATURES=dynamicRendering"}}),
    [](const ::testing::TestParamInfo<BadInput>& info) { return info.param.name; });
