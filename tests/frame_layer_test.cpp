// The frame layer (docs/architecture.md): one long-lived GpuScene under every settings change, per-frame values
// applied without allocation or pipeline creation, structure and size changes rebuilding only what
// they own, frames in flight under synchronization validation, and a settings table that covers
// every render option. Every image is checked against a renderer built afresh for the same settings.
#include <cfloat>
#include <fstream>
#include <map>
#include <set>
#include <string>

#include <CLI/CLI.hpp>

#include "app/frame_cli.h"
#include "gpu_fixture.h"
#include "renderer/settings_change.h"

namespace penumbra::test {
namespace {

constexpr uint32_t kW = 48, kH = 32;

RenderSettings smallSettings() {
    RenderSettings s;
    s.width = kW;
    s.height = kH;
    s.shadow.resolution = 128;
    s.rsm.resolution = 32;
    s.rsm.samples = 16;
    s.lpv.resolution = 8;
    s.lpv.iterations = 2;
    s.lpv.rsmResolution = 64;
    s.lpv.vplResolution = 16;
    s.lpv.sliceIndex = 4;
    s.giTemporal = false;  // each frame its own GI: a frame after others equals a one-shot render
    return s;
}

// Resident process memory in KiB (Linux).
long residentKiB() {
    std::ifstream statm("/proc/self/statm");
    long pages = 0, resident = 0;
    statm >> pages >> resident;
    return resident * 4;
}

// Two renders of the same inputs are equal bit for bit, except with LPV: its injection sums SH
// coefficients with float atomics, whose order varies between runs on a multi-threaded device
// (lavapipe: 1 ulp on a few values; two one-shot renders differ alike), so LPV images are equal
// within 4 ulps of each value.
void expectSameImage(const std::vector<float>& got, const std::vector<float>& want, GiMode gi, const std::string& what) {
    if (gi != GiMode::Lpv) {
        EXPECT_EQ(got, want) << what;
        return;
    }
    ASSERT_EQ(got.size(), want.size()) << what;
    size_t outside = 0;
    for (size_t i = 0; i < got.size(); ++i)
        outside += std::abs(got[i] - want[i]) > 4.0f * FLT_EPSILON * std::abs(want[i]);
    EXPECT_EQ(outside, 0u) << what << ": values beyond 4 ulps";
}

class FrameLayerTest : public GpuTest {
protected:
    // What a fresh renderer with `s` renders of `scene` (the reference for a changed live one).
    std::vector<float> fresh(GpuScene& scene, const RenderSettings& s, const Camera& camera) {
        TestRenderer r(ctx(), scene, s, 1);
        r.render(camera);
        return r.readHdr();
    }
};

struct Change {
    const char* what;
    std::function<void(RenderSettings&)> apply;
    SettingsChange expected;
};

std::vector<Change> changes() {
    return {
        {"exposure", [](RenderSettings& s) { s.exposure = 2.0f; }, SettingsChange::PerFrame},
        {"aov normal", [](RenderSettings& s) { s.aov = Aov::Normal; }, SettingsChange::PerFrame},
        {"shadow pcf", [](RenderSettings& s) { s.shadow.filter = ShadowFilter::Pcf; }, SettingsChange::Structure},
        {"pcf radius", [](RenderSettings& s) { s.shadow.pcfRadius = 3.0f; }, SettingsChange::PerFrame},
        {"shadow msm", [](RenderSettings& s) { s.shadow.filter = ShadowFilter::Msm; }, SettingsChange::Structure},
        {"vsm blur", [](RenderSettings& s) { s.shadow.blurRadius = 5; }, SettingsChange::PerFrame},
        {"shadow bias", [](RenderSettings& s) { s.shadow.depthBiasSlope = 3.0f; }, SettingsChange::PerFrame},
        {"normal offset", [](RenderSettings& s) { s.shadow.normalOffset = 2.0f; }, SettingsChange::PerFrame},
        {"gi rsm", [](RenderSettings& s) { s.gi = GiMode::Rsm; }, SettingsChange::Structure},
        {"rsm samples", [](RenderSettings& s) { s.rsm.samples = 40; }, SettingsChange::PerFrame},
        {"rsm radius", [](RenderSettings& s) { s.rsm.radius = 0.5f; }, SettingsChange::PerFrame},
        {"rsm resolution", [](RenderSettings& s) { s.rsm.resolution = 64; }, SettingsChange::Sizes},
        {"gi lpv", [](RenderSettings& s) { s.gi = GiMode::Lpv; }, SettingsChange::Structure},
        {"lpv occlusion", [](RenderSettings& s) { s.lpv.occlusion = false; }, SettingsChange::PerFrame},
        {"lpv iterations", [](RenderSettings& s) { s.lpv.iterations = 3; }, SettingsChange::Structure},
        {"lpv camera geom.", [](RenderSettings& s) { s.lpv.cameraGeometry = false; }, SettingsChange::Structure},
        {"shadow resolution", [](RenderSettings& s) { s.shadow.resolution = 256; }, SettingsChange::Sizes},
        {"image size", [](RenderSettings& s) { s.width = 40, s.height = 24; }, SettingsChange::Sizes},
    };
}

// Each change applied to a live renderer (2 frames in flight) gives the image a renderer built for
// the new settings gives, and a per-frame change allocates nothing and creates no pipeline.
TEST_F(FrameLayerTest, EachChangeMatchesAFreshRendererAndPerFrameChangesAllocateNothing) {
    GpuScene scene(ctx(), makeBuiltinScene("cornell"));
    const Camera camera = scene.scene().cameras[0];
    RenderSettings s = smallSettings();
    TestRenderer live(ctx(), scene, s, 2);
    for (int i = 0; i < 3; ++i) live.submit({camera, scene.scene().lights});
    for (const Change& c : changes()) {
        c.apply(s);
        const uint64_t allocations = live.allocator().allocations(), pipelines = ctx().pipelinesCreated();
        const SettingsChange got = live.apply(s);
        EXPECT_EQ(got, c.expected) << c.what;
        for (int i = 0; i < 3; ++i) live.submit({camera, scene.scene().lights});
        if (got == SettingsChange::PerFrame) {
            EXPECT_EQ(live.allocator().allocations(), allocations) << c.what << " allocated";
            EXPECT_EQ(ctx().pipelinesCreated(), pipelines) << c.what << " created a pipeline";
        }
        std::printf("[ change   ] %-18s %-9s %3llu allocations %3llu pipelines\n", c.what, settingsChangeName(got),
                    (unsigned long long)(live.allocator().allocations() - allocations),
                    (unsigned long long)(ctx().pipelinesCreated() - pipelines));
        expectSameImage(live.readHdr(), fresh(scene, s, camera), s.gi, std::string("after ") + c.what);
    }
    EXPECT_EQ(scene.geometryUploads(), 1u);
}

// Moving the camera and the light frame after frame with frames in flight: no hazard (synchronization
// validation, checked by the fixture) and the last frame equals a one-shot render of its inputs.
TEST_F(FrameLayerTest, FramesInFlightWithMovingCameraAndLight) {
    GpuScene scene(ctx(), makeBuiltinScene("cornell"));
    RenderSettings s = smallSettings();
    s.gi = GiMode::Lpv;
    s.shadow.filter = ShadowFilter::Vsm;
    TestRenderer live(ctx(), scene, s, 2);
    FrameInputs in{scene.scene().cameras[0], scene.scene().lights};
    for (int i = 0; i < 6; ++i) {
        in.camera.eye.x = 0.05f * float(i);
        in.lights[0].position.x = -0.3f + 0.1f * float(i);
        live.submit(in);
    }
    const std::vector<float> last = live.readHdr();
    EXPECT_EQ(live.takeCompletedTimings().size(), 6u);
    TestRenderer once(ctx(), scene, s, 1);
    once.render(in);
    expectSameImage(last, once.readHdr(), s.gi, "last frame against a one-shot render");
    EXPECT_GT(live.frameTimings().gpuMs, 0.0);
}

// A moving light with a deep shadow map: the DSM is refitted per frame (no allocation) and the
// last frame equals a one-shot render.
TEST_F(FrameLayerTest, MovingLightWithDeepShadowMapAllocatesNothing) {
    BuiltinOptions hair;
    hair.hairStrands = 200;
    GpuScene scene(ctx(), makeBuiltinScene("hair", hair));
    RenderSettings s = smallSettings();
    s.dsm.enabled = true;
    s.dsm.resolution = 128;
    TestRenderer live(ctx(), scene, s, 2);
    FrameInputs in{scene.scene().cameras[0], scene.scene().lights};
    live.submit(in);
    live.finish();
    const uint64_t allocations = live.allocator().allocations();
    for (int i = 0; i < 4; ++i) {
        in.lights[0].position.x += 0.1f;
        live.submit(in);
    }
    EXPECT_EQ(live.allocator().allocations(), allocations);
    const std::vector<float> last = live.readHdr();
    TestRenderer once(ctx(), scene, s, 1);
    once.render(in);
    EXPECT_EQ(last, once.readHdr());
}

// Adding and removing lights re-creates the shadow resources; the image follows.
TEST_F(FrameLayerTest, AddingAndRemovingLightsRebuildsShadows) {
    GpuScene scene(ctx(), makeBuiltinScene("cornell"));
    RenderSettings s = smallSettings();
    TestRenderer live(ctx(), scene, s, 2);
    FrameInputs in{scene.scene().cameras[0], scene.scene().lights};
    Light sun;
    sun.direction = glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f));
    sun.intensity = 1.0f;
    in.lights.push_back(sun);
    live.submit(in);
    TestRenderer two(ctx(), scene, s, 1);
    two.render(in);
    EXPECT_EQ(live.readHdr(), two.readHdr());
    in.lights.pop_back();
    live.submit(in);
    EXPECT_EQ(live.readHdr(), fresh(scene, s, in.camera));
}

// 30 cycles through 10 settings states: the allocator's bytes and blocks and the live pipelines stay
// where the first cycle left them, and resident memory has no upward trend.
TEST_F(FrameLayerTest, CyclingSettingsLeavesNoResidue) {
    GpuScene scene(ctx(), makeBuiltinScene("cornell"));
    const Camera camera = scene.scene().cameras[0];
    std::vector<RenderSettings> states(10, smallSettings());
    states[1].shadow.filter = ShadowFilter::Pcf;
    states[2].shadow.filter = ShadowFilter::Msm;
    states[3].gi = GiMode::Rsm;
    states[4].gi = GiMode::Lpv;
    states[5].shadow.resolution = 256;
    states[6].width = 32;
    states[7].gi = GiMode::Rsm, states[7].rsm.mode = RsmMode::Full;
    states[8].shadow.cascades.count = 2, states[8].exposure = 3.0f;
    states[9].gi = GiMode::Lpv, states[9].lpv.resolution = 16;
    TestRenderer live(ctx(), scene, states[0], 2);
    struct Counters {
        VkDeviceSize bytes;
        uint32_t blocks;
        int64_t pipelines;
    };
    Counters first{};
    std::vector<long> rss;
    for (int cycle = 0; cycle < 30; ++cycle) {
        for (const RenderSettings& st : states) {
            live.apply(st);
            live.submit({camera, scene.scene().lights});
        }
        live.finish();
        const Counters now{live.allocator().bytesInUse(), live.allocator().blockCount(), ctx().pipelinesAlive()};
        if (cycle == 0) first = now;
        EXPECT_EQ(now.bytes, first.bytes) << "cycle " << cycle;
        EXPECT_EQ(now.blocks, first.blocks) << "cycle " << cycle;
        EXPECT_EQ(now.pipelines, first.pipelines) << "cycle " << cycle;
        rss.push_back(residentKiB());
    }
    // No trend from the changes: lavapipe's own resident memory grows with every frame (about 0.75 MiB
    // per frame in Mesa 22.3, with or without settings changes, in the old loop as in this one), so the
    // last ten cycles are compared with as many frames rendered without any change.
    const long before = residentKiB();
    for (int i = 0; i < 10 * int(states.size()); ++i) live.submit({camera, scene.scene().lights});
    live.finish();
    const long steady = residentKiB() - before, changing = rss.back() - rss[19];
    EXPECT_LE(changing, steady + 1024) << "10 cycles of changes grew resident memory by " << changing
                                       << " KiB, as many unchanged frames by " << steady << " KiB";
}

// Every option `render` takes is classified, except the frame inputs and the scene's own options.
TEST(SettingsTable, CoversEveryRenderOption) {
    CLI::App app;
    FrameOptions fo;
    RenderSettings rs;
    addFrameOptions(app, fo, rs);
    std::set<std::string> table;
    for (const SettingsOption& o : settingsOptionTable()) table.insert(o.flag);
    // Frame inputs (camera, lights, what moves and when), not settings.
    const std::set<std::string> inputs{"--help",      "--camera",      "--camera-index", "--view",
                                       "--light",     "--light-shadow", "--strands",     "--time",
                                       "--animation", "--clamp",       "--sun-path",     "--light-path",
                                       "--camera-keys", "--no-motion"};
    for (const CLI::Option* o : app.get_options()) {
        if (o->get_lnames().empty()) continue;  // the positional scene
        const std::string name = "--" + o->get_lnames().front();
        if (inputs.count(name)) continue;
        EXPECT_TRUE(table.count(name)) << name << " has no settings class";
    }
}

TEST(SettingsTable, SizesAndPassCountsAreNotPerFrame) {
    for (const char* flag : {"--shadow-res", "--rsm-res", "--lpv-res", "--dsm-res", "--cascades", "--width",
                             "--lpv-iterations", "--lpv-vpl-res", "--lpv-rsm-res"})
        for (const SettingsOption& o : settingsOptionTable())
            if (std::string(o.flag) == flag) {
                EXPECT_NE(o.change, SettingsChange::PerFrame) << flag;
            }
}

}  // namespace
}  // namespace penumbra::test

namespace penumbra::test {
namespace {

// The shadow-map debug view shows the map's texels: at the map's own resolution, pixel (x, y) of
// the AOV is texel (x, y) of the chosen layer, exactly.
TEST_F(FrameLayerTest, ShadowMapDebugViewShowsTheLayersTexels) {
    GpuScene scene(ctx(), makeBuiltinScene("cornell"));
    RenderSettings s = smallSettings();
    s.width = s.height = s.shadow.resolution = 64;
    s.aov = Aov::ShadowMap;
    TestRenderer r(ctx(), scene, s, 1);
    r.render(scene.scene().cameras[0]);
    const std::vector<float> view = r.readHdr();
    const std::vector<uint8_t> bytes = r.commands().readImage(r.shadow().shadowMap(), 4, 0);
    size_t mismatches = 0;
    for (size_t i = 0; i < size_t(64) * 64; ++i) {
        float depth;
        std::memcpy(&depth, bytes.data() + 4 * i, 4);
        mismatches += view[4 * i] != depth;
    }
    EXPECT_EQ(mismatches, 0u);
}

// The viewer's pixel probe reads, at one pixel, what each AOV image holds there, and leaves the
// image unchanged.
TEST_F(FrameLayerTest, PixelProbeEqualsEveryAovImageAtItsPixel) {
    GpuScene scene(ctx(), makeBuiltinScene("cornell"));
    RenderSettings s = smallSettings();
    s.gi = GiMode::Rsm;
    s.shadow.filter = ShadowFilter::Pcf;
    const Camera camera = scene.scene().cameras[0];
    TestRenderer live(ctx(), scene, s, 2);
    const auto texel = [](const std::vector<float>& image, glm::uvec2 p) {
        const float* v = &image[4 * (size_t(p.y) * kW + p.x)];
        return glm::vec4(v[0], v[1], v[2], v[3]);
    };
    // Two pixels on the box, one on the background beside it (alpha 0 in every AOV image). The previous
    // frame's camera stood elsewhere, so that the velocity is not zero.
    Camera before = camera;
    before.eye += glm::vec3(0.05f, -0.02f, 0.03f);
    FrameInputs plainIn{camera, scene.scene().lights};
    plainIn.previous = FrameInputs::Previous{before, {}};
    int backgrounds = 0;
    for (const glm::uvec2 pixel : {glm::uvec2(kW / 3, kH / 2), glm::uvec2(kW / 2, 3), glm::uvec2(0, 0)}) {
        FrameInputs in = plainIn;
        in.probePixel = pixel;
        std::map<Aov, glm::vec4> image;
        for (Aov aov : {Aov::Final, Aov::Direct, Aov::Indirect, Aov::Albedo, Aov::Normal, Aov::Depth, Aov::Shadow,
                        Aov::Velocity}) {
            s.aov = aov;
            live.apply(s);
            live.submit(plainIn);
            const std::vector<float> plain = live.readHdr();
            live.submit(in);
            EXPECT_EQ(live.readHdr(), plain) << "the probe changed the image";
            image[aov] = texel(plain, pixel);
        }
        ASSERT_TRUE(live.probe().has_value());
        const gpu::PixelProbe& p = *live.probe();
        const bool surface = image[Aov::Depth].w == 1.0f;
        EXPECT_EQ(p.surface, surface ? 1u : 0u) << pixel.x << "," << pixel.y;
        EXPECT_EQ(p.eyeDistance, image[Aov::Depth].x);
        backgrounds += !surface;
        if (!surface) continue;
        EXPECT_EQ(glm::vec3(p.finalRadiance), glm::vec3(image[Aov::Final]));
        EXPECT_EQ(glm::vec3(p.direct), glm::vec3(image[Aov::Direct]));
        EXPECT_EQ(glm::vec3(p.indirect), glm::vec3(image[Aov::Indirect]));
        EXPECT_EQ(glm::vec3(p.albedo), glm::vec3(image[Aov::Albedo]));
        EXPECT_EQ(glm::vec3(p.normal), glm::vec3(image[Aov::Normal]));
        EXPECT_EQ(p.shadowVisibility, image[Aov::Shadow].x);
        EXPECT_EQ(glm::vec2(p.velocity), glm::vec2(image[Aov::Velocity]));
        EXPECT_GT(glm::length(glm::vec2(p.velocity)), 0.1f) << "the camera moved";
        EXPECT_GT(glm::length(glm::vec3(p.irradiance)), 0.0f) << "RSM gives cornell's walls indirect light";
    }
    EXPECT_EQ(backgrounds, 1);
}

// The depth AOV's PNG divides by the distance to the scene's farthest bound corner, not by a camera's
// far plane (a glTF camera's zfar of 1000 made VC's depth PNG nearly black): surfaces span the range.
TEST_F(FrameLayerTest, DepthPngScalesToTheSceneNotTheCameraFarPlane) {
    GpuScene scene(ctx(), makeBuiltinScene("cornell"));
    Camera camera = scene.scene().cameras[0];
    camera.zfar = 1000.0f;
    const Bounds& b = scene.scene().bounds;
    double far = 0.0;  // the farthest corner, computed here
    for (glm::vec3 corner : {b.min, b.max, glm::vec3(b.min.x, b.min.y, b.max.z), glm::vec3(b.min.x, b.max.y, b.min.z),
                             glm::vec3(b.max.x, b.min.y, b.min.z), glm::vec3(b.max.x, b.max.y, b.min.z),
                             glm::vec3(b.max.x, b.min.y, b.max.z), glm::vec3(b.min.x, b.max.y, b.max.z)})
        far = std::max(far, double(glm::length(corner - camera.eye)));
    RenderSettings s = smallSettings();
    s.aov = Aov::Depth;
    TestRenderer r(ctx(), scene, s, 1);
    r.render(camera);
    const std::vector<float> depth = r.readHdr();
    const std::vector<uint8_t> png = r.readLdr();
    int brightest = 0;
    for (size_t i = 0; i < size_t(kW) * kH; ++i) {
        if (depth[4 * i + 3] == 0.0f) continue;  // background
        const double expected = 255.0 * std::min(1.0, depth[4 * i] / far);
        EXPECT_NEAR(png[4 * i], expected, 0.51) << "pixel " << i;
        brightest = std::max(brightest, int(png[4 * i]));
    }
    EXPECT_GT(brightest, 128) << "cornell's back wall is more than half the farthest corner's distance away";
}

}  // namespace
}  // namespace penumbra::test
