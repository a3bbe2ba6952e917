#include "app/bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <map>

#include <unistd.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/sky.h"
#include "app/option_cli.h"
#include "frame/frame_setup.h"
#include "renderer/render_options.h"
#include "app/option_checks.h"
#include "io/file_write.h"

namespace penumbra {
namespace {

// A series with no samples (one measured frame leaves no wall-clock interval; a pass that ran in no
// measured frame) has NaN statistics: printed as "-", written to JSON as null.
struct Stats {
    double median, p5, p95;
};

Stats stats(std::vector<double> v) {
    if (v.empty()) return {std::nan(""), std::nan(""), std::nan("")};
    std::sort(v.begin(), v.end());
    auto at = [&](double q) { return v[std::min(v.size() - 1, size_t(q * double(v.size() - 1) + 0.5))]; };
    return {at(0.5), at(0.05), at(0.95)};
}

// Device-to-device copy of a large buffer: the bandwidth floor the memory-bound passes are held to.
// GB/s counts bytes read plus bytes written.
double copyBandwidth(vk::Context& ctx) {
    vk::Allocator alloc(ctx);
    vk::CommandContext cmd(alloc);
    vk::GpuTimer timer(ctx, 4);
    const bool cpu = ctx.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
    const VkDeviceSize size = VkDeviceSize(cpu ? 64 : 1024) << 20;
    vk::Buffer a(alloc, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, false, "copy-src");
    vk::Buffer b(alloc, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT, false, "copy-dst");
    std::vector<double> gbps;
    for (int i = 0; i < 6; ++i) {
        timer.reset();
        cmd.submitAndWait([&](VkCommandBuffer c) {
            uint32_t s = timer.begin(c, "copy");
            VkBufferCopy region{0, 0, size};
            vkCmdCopyBuffer(c, a.handle(), b.handle(), 1, &region);
            timer.end(c, s);
        });
        if (i > 0) gbps.push_back(2.0 * double(size) / (timer.results()[0].ms * 1e-3) * 1e-9);
    }
    return stats(gbps).median;
}

nlohmann::json settingsJson(const RenderSettings& s, const FrameOptions& f) {
    nlohmann::json j = renderSettingsJson(s);
    j["scene"] = f.scene;
    j["inputs"] = optionsJson(frameInputOptions(), &f);
    j["motion"] = optionsJson(motionOptions(), &f);
    return j;
}

std::string cell(double v) { return std::isnan(v) ? "-" : fmt::format("{:.3f}", v); }

void printRow(const std::string& label, const Stats& s, const std::string& tail = "") {
    fmt::print("{:<24} {:>9} {:>9} {:>9}{}\n", label, cell(s.median), cell(s.p5), cell(s.p95), tail);
}

std::string today() {
    std::time_t t = std::time(nullptr);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%d", std::gmtime(&t));
    return buf;
}

}  // namespace

namespace {

OptionTable makeBenchTable() {
    using B = BenchOptions;
    using change::kCommand;
    OptionTableBuilder<B> t("bench", "Bench");
    t.integer("--frames", "frames", [](B& b) -> auto& { return b.frames; }, 1, 1000000, kCommand, "Measured frames");
    t.integer("--warmup", "warmup", [](B& b) -> auto& { return b.warmup; }, 0, 1000000, kCommand,
              "Frames rendered first and not measured");
    t.text("--json", "json", [](B& b) -> auto& { return b.json; },
           [](const B& b) { return b.json.empty() ? std::vector<std::string>{} : std::vector<std::string>{b.json}; },
           [](B& b, const std::string& v) { b.json = v; }, kCommand, "Write the results as JSON to this file")
        .placeholder = "FILE";
    t.integer("--frames-in-flight", "frames_in_flight", [](B& b) -> auto& { return b.framesInFlight; }, 1,
              vk::kMaxFramesInFlight, kCommand, "Frames recorded ahead of the GPU (1 waits for each frame)");
    return t.build();
}

}  // namespace

const OptionTable& benchCommandOptions() {
    static const OptionTable table = makeBenchTable();
    return table;
}

CLI::App* addBenchCommand(CLI::App& app, BenchOptions& o, RenderSettings& rs) {
    CLI::App* cmd = app.add_subcommand("bench", "Time every pass over many frames (GPU timestamps), write JSON");
    addFrameOptions(*cmd, o.frame, rs);
    addOptionRows(*cmd, benchCommandOptions(), &o);
    return cmd;
}

// Renders the warm-up and measured frames with `framesInFlight` frames ahead of the GPU (1: each frame
// waited for, the old loop). Returns the measured frames' timings and the wall-clock ms per frame.
struct BenchRun {
    std::vector<FrameTimings> frames;
    std::vector<double> wallMs;  // host time from one frame's submission to the next's
};

// Frame i shows the scene at --time + i / 30 s (warm-up frames included), so a scene that moves
// (animation, motion paths, a built-in default motion) is measured moving; `poseMs` collects the host
// time spent evaluating the motion of each measured frame. Cold frames (`cold`): the caches are dropped
// before each frame, so every pass runs (the targets are cold); warm frames keep them (cached shadow
// layers are not drawn again unless what they show moved).
static BenchRun runFrames(Renderer& renderer, const SceneMotion& motion, const BenchOptions& o, bool cold,
                          std::vector<double>& poseMs) {
    int index = 0;
    auto next = [&]() {
        const auto t0 = std::chrono::steady_clock::now();
        FrameInputs in = frameInputs(motion, o.frame.time + index++ / 30.0);
        poseMs.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
        if (cold) renderer.invalidateCaches();
        return in;
    };
    for (int i = 0; i < o.warmup; ++i) {
        renderer.submit(next());
        if (o.framesInFlight == 1) renderer.finish();
    }
    renderer.finish();
    renderer.takeCompletedTimings();
    BenchRun run;
    poseMs.clear();
    const bool progress = isatty(fileno(stderr));
    auto last = std::chrono::steady_clock::now();
    for (int i = 0; i < o.frames; ++i) {
        renderer.submit(next());
        if (o.framesInFlight == 1) renderer.finish();
        const auto now = std::chrono::steady_clock::now();
        run.wallMs.push_back(std::chrono::duration<double, std::milli>(now - last).count());
        last = now;
        if (progress) fmt::print(stderr, "\rbench: frame {}/{}   ", i + 1, o.frames);
    }
    renderer.finish();
    if (progress) fmt::print(stderr, "\n");
    run.frames = renderer.takeCompletedTimings();
    if (!run.wallMs.empty()) run.wallMs.erase(run.wallMs.begin());  // the first includes the warm-up's drain
    return run;
}

// Four series of the same frames. The frame's time comes from frames timed as a whole: a timestamp
// waits for the work before it, so scopes around every pass run the passes one after another
// (Renderer::setPassScopes). The per-pass times come from the same frames with scopes.
struct BenchTimings {
    std::map<std::string, std::vector<double>> perPass;  // scoped cold frames
    std::vector<std::string> order;                     // the passes in the order they ran
    std::vector<double> frameMs, serialMs, scopeSumMs, cpuMs, warmFrameMs;
    std::map<std::string, std::vector<double>> warmPerPass;
};
struct BenchSeries {
    BenchRun whole;  // cold frames timed whole (wall clock)
    BenchTimings timings;
};

static BenchSeries measureSeries(Renderer& renderer, const SceneMotion& motion, const BenchOptions& o,
                                 std::vector<double>& poseMs) {
    std::vector<double> unused;
    BenchSeries out;
    out.whole = runFrames(renderer, motion, o, true, poseMs);
    const BenchRun warm = runFrames(renderer, motion, o, false, unused);
    renderer.setPassScopes(true);
    const BenchRun scoped = runFrames(renderer, motion, o, true, unused);
    const BenchRun warmScoped = runFrames(renderer, motion, o, false, unused);
    BenchTimings& t = out.timings;
    for (const FrameTimings& f : warmScoped.frames)
        for (const vk::ScopeTiming& p : f.passes) t.warmPerPass[p.name].push_back(p.ms);
    for (const FrameTimings& f : warm.frames) t.warmFrameMs.push_back(f.gpuMs);
    for (const FrameTimings& f : scoped.frames) {
        double sum = 0.0;
        for (const vk::ScopeTiming& p : f.passes) {
            if (!t.perPass.count(p.name)) t.order.push_back(p.name);
            t.perPass[p.name].push_back(p.ms);
            sum += p.ms;
        }
        t.serialMs.push_back(f.gpuMs);
        t.scopeSumMs.push_back(sum);
    }
    for (const FrameTimings& f : out.whole.frames) {
        t.frameMs.push_back(f.gpuMs);
        t.cpuMs.push_back(f.cpuMs);
    }
    return out;
}

int runBench(const BenchOptions& o, const vk::ContextOptions& vkOptions, RenderSettings settings, bool dryRun) {
    if (!o.json.empty()) checkWritable(o.json, benchCommandOptions().flagOf<BenchOptions>([](BenchOptions& b) -> auto& { return b.json; }));
    if (dryRun) return prepareFrame(o.frame, settings), 0;
    OptionsDeviceFrame device(o.frame, settings, vkOptions);
    vk::Context& ctx = device.ctx;
    const PreparedFrame& f = device.frame;
    const double copyGbps = copyBandwidth(ctx);
    GpuScene scene(ctx, f.scene);
    resolveAutoSky(settings.lighting.sky, f.scene.lights);
    Renderer renderer(ctx, scene, settings, uint32_t(o.framesInFlight));
    for (const std::string& w : renderer.warnings()) printWarning(w);
    const SceneMotion& motion = frameMotion(o.frame, device);
    std::vector<double> poseMs;
    const BenchSeries series = measureSeries(renderer, motion, o, poseMs);
    const BenchRun& run = series.whole;
    const auto& [perPass, order, frameMs, serialMs, scopeSumMs, cpuMs, warmFrameMs, warmPerPass] = series.timings;

    std::map<std::string, uint64_t> bytes;
    for (const PassDesc& p : renderer.passes()) bytes[p.name] = p.bytes;

    nlohmann::json passes = nlohmann::json::array();
    fmt::print("{:<24} {:>9} {:>9} {:>9} {:>10} {:>8} {:>7}\n", "pass", "median ms", "p5", "p95", "MB moved", "GB/s",
               "/copy");
    for (const std::string& name : order) {
        Stats s = stats(perPass.at(name));
        nlohmann::json j{{"name", name}, {"median_ms", s.median}, {"p5_ms", s.p5}, {"p95_ms", s.p95}};
        std::string mb, gbps, ratio;
        if (bytes[name]) {
            const double g = double(bytes[name]) / (s.median * 1e-3) * 1e-9;
            j["bytes"] = bytes[name];
            j["gbps"] = g;
            j["fraction_of_copy_bandwidth"] = g / copyGbps;
            mb = fmt::format("{:.2f}", bytes[name] / 1e6), gbps = fmt::format("{:.0f}", g);
            ratio = fmt::format("{:.2f}", g / copyGbps);
        }
        printRow(name, s, fmt::format(" {:>10} {:>8} {:>7}", mb, gbps, ratio));
        passes.push_back(j);
    }
    const Stats fs = stats(frameMs), sum = stats(scopeSumMs), cpu = stats(cpuMs), wall = stats(run.wallMs);
    const Stats ws = stats(warmFrameMs), serial = stats(serialMs);
    printRow("frame (GPU, whole)", fs);
    printRow("frame, pass scopes", serial);
    printRow("warm frame (cached)", ws);
    nlohmann::json warmPasses = nlohmann::json::array();
    for (const std::string& name : order)
        if (warmPerPass.count(name)) warmPasses.push_back({{"name", name}, {"median_ms", stats(warmPerPass.at(name)).median}});
    printRow("sum of pass scopes", sum);
    printRow("wall clock per frame", wall);
    printRow("CPU (record + submit)", cpu);
    const Stats pose = stats(poseMs);
    if (motion.moves())
        printRow("CPU (motion at t)", pose, fmt::format("   (geometry uploads: {})", scene.geometryUploads()));
    fmt::print("device {} | copy bandwidth {:.0f} GB/s | GPU memory {:.1f} MiB | {} triangles, {} strands\n",
               ctx.info().name, copyGbps, renderer.allocator().bytesReserved() / 1048576.0,
               f.scene.drawnTriangleCount(), f.scene.strands.size());
    if (!o.json.empty()) {
        nlohmann::json out{{"command", o.command}, {"date", today()}, {"device", ctx.info().name},
                           {"driver", ctx.info().driver}, {"frames", o.frames}, {"warmup", o.warmup},
                           {"settings", settingsJson(settings, o.frame)},
                           {"scene", {{"name", f.scene.name}, {"triangles", f.scene.drawnTriangleCount()}, {"instances", f.scene.instances.size()},
                                      {"strands", f.scene.strands.size()}}},
                           {"gpu_memory_bytes", renderer.allocator().bytesReserved()},
                           {"copy_bandwidth_gbps", copyGbps},
                           {"frames_in_flight", o.framesInFlight},
                           {"geometry_uploads", scene.geometryUploads()},
                           // GPU time between timestamps before the first pass and after the last,
                           // frames timed as a whole (independent passes overlap, RenderSettings::overlapPasses)
                           {"frame_ms", {{"median", fs.median}, {"p5", fs.p5}, {"p95", fs.p95}}},
                           // the same frames with a scope per pass (the passes one after another; `passes`)
                           {"frame_ms_pass_scopes", {{"median", serial.median}, {"p5", serial.p5}, {"p95", serial.p95}}},
                           {"scope_sum_ms", {{"median", sum.median}, {"p5", sum.p5}, {"p95", sum.p95}}},
                           {"wall_ms", {{"median", wall.median}, {"p5", wall.p5}, {"p95", wall.p95}}},
                           {"cpu_ms", {{"median", cpu.median}, {"p5", cpu.p5}, {"p95", cpu.p95}}},
                           {"motion", {{"moves", motion.moves()}, {"fps", 30}, {"start_time", o.frame.time},
                                       {"pose_cpu_ms", {{"median", pose.median}, {"p5", pose.p5}, {"p95", pose.p95}}}}},
                           {"passes", passes},
                           // the same frames again with the caches kept (cached shadow layers not drawn)
                           {"warm", {{"frame_ms", {{"median", ws.median}, {"p5", ws.p5}, {"p95", ws.p95}}},
                                     {"passes", warmPasses}}}};
        writeTextFile(o.json, out.dump(2));
    }
    device.checkValidation();
    return 0;
}

}  // namespace penumbra
