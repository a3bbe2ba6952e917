// VK_EXT_debug_utils: a capture tool (RenderDoc) sees one command-buffer label per frame-graph pass,
// named as the pass, and the frame's images and buffers under their names; without the extension
// the frame records the same work and gives the same image.
#include <cstring>
#include <set>
#include <string>

#include "gpu_fixture.h"

namespace penumbra::test {
namespace {

class DebugLabelTest : public GpuTest {
protected:
    RenderSettings settings(GiMode gi, ShadowFilter filter) {
        RenderSettings s;
        s.width = 96;
        s.height = 64;
        s.gi = gi;
        s.shadow.filter = filter;
        s.shadow.resolution = 256;
        s.rsm.resolution = 64;
        s.lpv.rsmResolution = 64;
        s.lpv.vplResolution = 16;
        s.lpv.resolution = 16;
        return s;
    }
};

// The validation layer offers the extension: every pass of a recorded frame begins one label (the
// layer checks that each is ended in the same command buffer), and no other command does; every
// image and buffer the renderers made carries a name.
TEST_F(DebugLabelTest, OneLabelPerFrameGraphPass) {
    ASSERT_TRUE(ctx().debugUtils().enabled()) << "the validation layer offers VK_EXT_debug_utils";
    GpuScene scene(ctx(), makeBuiltinScene("cornell"));
    const Camera camera = scene.scene().cameras[0];
    for (GiMode gi : {GiMode::None, GiMode::Rsm, GiMode::Lpv}) {
        Renderer renderer(ctx(), scene, settings(gi, ShadowFilter::Pcf));
        renderer.render(camera);  // the first frame also uploads; count the second
        const uint64_t before = ctx().debugUtils().labelsBegun();
        renderer.render(camera);
        const uint64_t labels = ctx().debugUtils().labelsBegun() - before;
        std::set<std::string> names;
        for (const PassDesc& p : renderer.passes()) names.insert(p.name);
        EXPECT_GT(renderer.passes().size(), 5u);
        EXPECT_EQ(labels, renderer.passes().size()) << "gi mode " << int(gi);
        EXPECT_EQ(names.size(), renderer.passes().size()) << "each label names one pass";
    }
    EXPECT_EQ(ctx().debugUtils().unnamedObjects(), 0u) << "every image and buffer has a name";
}

// Labels and names change no result: a context that records none renders the same bytes. (Not
// LPV: its injection adds floats atomically, in an order lavapipe's threads vary from run to run.)
TEST_F(DebugLabelTest, ImagesEqualWithoutTheExtension) {
    vk::ContextOptions plain;
    plain.debugLabels = false;
    vk::Context bare(plain);
    ASSERT_FALSE(bare.debugUtils().enabled());
    const Scene scene = makeBuiltinScene("cornell");
    const Camera camera = scene.cameras[0];
    for (GiMode gi : {GiMode::None, GiMode::Rsm}) {
        std::vector<float> labelled, unlabelled;
        {
            Renderer renderer(ctx(), scene, settings(gi, ShadowFilter::Pcss));
            renderer.render(camera);
            labelled = renderer.readHdr();
        }
        {
            Renderer renderer(bare, scene, settings(gi, ShadowFilter::Pcss));
            renderer.render(camera);
            unlabelled = renderer.readHdr();
            EXPECT_EQ(bare.debugUtils().labelsBegun(), 0u);
        }
        ASSERT_EQ(labelled.size(), unlabelled.size());
        EXPECT_EQ(std::memcmp(labelled.data(), unlabelled.data(), labelled.size() * sizeof(float)), 0)
            << "gi mode " << int(gi);
    }
    bare.waitIdle();
}

}  // namespace
}  // namespace penumbra::test
