// The device budget against the resources: what it admits is what is allocated and bound, and every
// value it suggests ("the largest X that fits is N") passes the whole check when applied.
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dsm/dsm_options.h"
#include "dsm/dsm_resources.h"
#include "lpv/lpv_options.h"
#include "renderer/device_budget.h"
#include "renderer/render_options.h"
#include "sky_light/sky_light_options.h"
#include "rsm/rsm_options.h"
#include "scene/scene.h"
#include "shadow/shadow_options.h"

namespace penumbra {
namespace {

// Lavapipe's limits (Mesa 22.3): a 128 MiB storage-buffer range, 2 GiB of memory.
vk::DeviceLimits lavapipeLimits() {
    vk::DeviceLimits lim;
    lim.storageBufferRange = uint64_t(1) << 27;
    lim.allocationSize = uint64_t(1) << 31;
    lim.deviceMemory = uint64_t(1) << 31;
    lim.imageDimension2D = 16384;
    lim.imageArrayLayers = 2048;
    lim.sampledImagesPerStage = 32;
    lim.workGroupCount[0] = lim.workGroupCount[1] = lim.workGroupCount[2] = 65535;
    return lim;
}

// The budget's answer: "" when it admits the settings, else its message.
std::string refusal(const RenderSettings& s, const Scene& scene, const std::vector<Light>& lights, bool computeRaster) {
    try {
        checkDeviceBudget(lavapipeLimits(), s, scene, lights, computeRaster);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

// Follows the advice from `s` until the budget admits the settings: each suggestion must be a value
// the option accepts and strictly smaller than the one refused; returns the steps taken.
int followAdvice(RenderSettings s, const Scene& scene, const std::vector<Light>& lights, bool computeRaster,
                 const std::string& flag) {
    int steps = 0;
    for (std::string why = refusal(s, scene, lights, computeRaster); !why.empty();
         why = refusal(s, scene, lights, computeRaster), ++steps) {
        std::smatch m;
        EXPECT_TRUE(std::regex_search(why, m, std::regex("the largest (--[a-z0-9-]+) that fits is ([0-9]+)"))) << why;
        if (m.empty() || steps > 8) return -1;
        EXPECT_EQ(m[1].str(), flag) << why;
        const FoundOption option = findRenderOption(m[1].str());
        const std::string before = option.row->value(option.table->at(s));
        EXPECT_LT(std::stoull(m[2].str()), std::stoull(before)) << why;
        option.row->set(option.table->at(s), m[2].str());
        EXPECT_NO_THROW(validateSettings(s)) << "the suggested " << m[1].str() << " " << m[2].str();
    }
    return steps;
}

Scene cornell() { return loadScene("cornell"); }

const std::string& shadowResFlag() {
    return shadowOptions().flagOf<ShadowSettings>([](ShadowSettings& s) -> auto& { return s.resolution; });
}

// The buffers the budget names are the ones DsmResources allocates: at 4096^2 the work list (a
// uvec4 header and a uvec2 per texel) is 16 bytes over lavapipe's range, where the heads alone fit.
TEST(DeviceBudget, DsmWorkListIsCheckedAsAllocated) {
    const uint64_t texels = 4096ull * 4096;
    EXPECT_EQ(DsmResources::headBytes(texels, false), lavapipeLimits().storageBufferRange);
    EXPECT_EQ(DsmResources::workBytes(texels, false), lavapipeLimits().storageBufferRange + 16);
    RenderSettings s;
    s.dsm.enabled = true;
    s.dsm.resolution = 4096;
    const Scene scene = cornell();
    const std::string why = refusal(s, scene, scene.lights, false);
    EXPECT_NE(why.find("work list"), std::string::npos) << why;
    s.dsm.resolution = 16384;
    EXPECT_EQ(followAdvice(s, scene, scene.lights, false,
                           dsmOptions().flagOf<DsmSettings>([](DsmSettings& x) -> auto& { return x.resolution; })),
              1);
}

// 200 point lights: every --shadow-res suggested is one that then fits (no dead end while a smaller
// value renders), with cube maps and the compute rasterizer, and with paraboloids.
TEST(DeviceBudget, TwoHundredPointLightsShadowResAdviceFits) {
    const Scene scene = cornell();
    std::vector<Light> lights;
    for (int i = 0; i < 200; ++i) {
        Light l;
        l.type = LightType::Point;
        l.position = {0.1f + 0.004f * float(i), 0.9f, 0.5f};
        l.intensity = 0.01f;
        lights.push_back(l);
    }
    for (bool computeRaster : {true, false}) {
        RenderSettings s;
        s.shadow.resolution = 2048;
        const int steps = followAdvice(s, scene, lights, computeRaster, shadowResFlag());
        EXPECT_EQ(steps, 1) << "compute raster " << computeRaster;
        // With LPV, 1200 RSM layers leave no --lpv-vpl-res: the refusal names the option to change.
        s.gi = GiMode::Lpv;
        const std::string why = refusal(s, scene, lights, computeRaster);
        EXPECT_NE(why.find("no " + lpvOptions().flagOf<LpvSettings>([](LpvSettings& x) -> auto& {
                      return x.vplResolution;
                  }) + " fits"),
                  std::string::npos)
            << why;
        EXPECT_NE(why.find("at " + lpvOptions().flagOf<LpvSettings>([](LpvSettings& x) -> auto& {
                      return x.vplResolution;
                  }) + " 1: " + shadowResFlag()),
                  std::string::npos)
            << why;
    }
}

// A suggested --lpv-vpl-res divides --lpv-rsm-res (the option's own rule) and fits.
TEST(DeviceBudget, LpvVplResAdviceDividesTheRsm) {
    const Scene scene = cornell();
    RenderSettings s;
    s.gi = GiMode::Lpv;
    s.lpv.rsmResolution = 8192;
    s.lpv.vplResolution = 8192;
    const std::string& flag = lpvOptions().flagOf<LpvSettings>([](LpvSettings& x) -> auto& { return x.vplResolution; });
    EXPECT_EQ(followAdvice(s, scene, scene.lights, false, flag), 1);
}

// Every other demand with an option: refused at the option's largest value, the advice then fits.
TEST(DeviceBudget, EveryDemandsAdviceFits) {
    const Scene scene = cornell();
    struct Case {
        const char* what;
        std::function<void(RenderSettings&)> set;
        std::string flag;
        bool computeRaster = false;
    };
    using L = LpvSettings;
    const OptionTable& frame = frameOptionTable();
    const std::vector<Case> cases = {
        {"image", [](RenderSettings& s) { s.width = s.height = 16384; },
         frame.flagOf<RenderSettings>([](RenderSettings& x) -> auto& { return x.width; })},
        {"moments", [](RenderSettings& s) { s.shadow.filter = ShadowFilter::Vsm, s.shadow.resolution = 16384; },
         shadowResFlag()},
        {"compute raster IDs", [](RenderSettings& s) { s.gi = GiMode::Lpv, s.shadow.resolution = 16384; },
         shadowResFlag(), true},
        {"rsm flux", [](RenderSettings& s) { s.gi = GiMode::Rsm, s.rsm.far = RsmFar::Flux, s.rsm.resolution = 8192; },
         rsmOptions().flagOf<RsmSettings>([](RsmSettings& x) -> auto& { return x.resolution; })},
        {"lpv volumes", [](RenderSettings& s) { s.gi = GiMode::Lpv, s.lpv.resolution = 256; },
         lpvOptions().flagOf<L>([](L& x) -> auto& { return x.resolution; })},
    };
    for (const Case& c : cases) {
        RenderSettings s;
        c.set(s);
        ASSERT_NO_THROW(validateSettings(s)) << c.what;
        ASSERT_FALSE(refusal(s, scene, scene.lights, c.computeRaster).empty()) << c.what;
        EXPECT_GE(followAdvice(s, scene, scene.lights, c.computeRaster, c.flag), 1) << c.what;
    }
}

// The occupancy volume under a sky, on a scene of single-sided walls: the voxel bits and the sky's
// four facing bits a voxel, one storage buffer, which at 1024 voxels a side (640 MiB) exceeds
// lavapipe's storage-buffer range; the suggested --rsm-voxel-res fits.
TEST(DeviceBudget, OccupancyVolumeWithFacingBitsAdviceFits) {
    const Scene scene = cornell();
    RenderSettings s;
    s.lighting.sky.kind = SkyKind::Uniform;
    s.skyLight.visibility = SkyVisibility::Voxels;
    s.rsm.voxelResolution = 1024;
    ASSERT_NO_THROW(validateSettings(s));
    const std::string why = refusal(s, scene, scene.lights, false);
    EXPECT_NE(why.find("the sky's facing bits"), std::string::npos) << why;
    EXPECT_GE(followAdvice(s, scene, scene.lights, false,
                           rsmOptions().flagOf<RsmSettings>([](RsmSettings& x) -> auto& { return x.voxelResolution; })),
              1);
}

TEST(DeviceBudget, SkyMapsAdviceFits) {
    const Scene scene = cornell();
    RenderSettings s;
    s.lighting.sky.kind = SkyKind::Uniform;
    s.skyLight.mapCount = 256;
    s.skyLight.mapResolution = 2048;
    ASSERT_NO_THROW(validateSettings(s));
    const std::string why = refusal(s, scene, scene.lights, false);
    EXPECT_NE(why.find("the sky visibility maps"), std::string::npos) << why;
    EXPECT_GE(followAdvice(s, scene, scene.lights, false,
                           skyLightOptions().flagOf<SkyLightSettings>([](SkyLightSettings& x) -> auto& { return x.mapResolution; })),
              1);
}

}  // namespace
}  // namespace penumbra
