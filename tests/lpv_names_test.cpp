// The LPV publishes its cascades' boxes by name (lpv/lpv_names.h), which the viewer's overlay draws
// without the technique's class: after a frame of the room-sized cornell box, three boxes, each
// holding the scene, centred on it, each twice as large as the one before, and none without LPV.
#include <gtest/gtest.h>

#include "gpu_fixture.h"
#include "lpv/lpv_names.h"
#include "scene/builders.h"
#include "test_renderer.h"

namespace penumbra::test {
namespace {

class LpvNamesTest : public GpuTest {};

TEST_F(LpvNamesTest, CascadeBoxesCoverTheRoomAndDoubleInSize) {
    GpuScene scene(ctx(), makeBuiltinScene("cornell"));
    const Bounds& bounds = scene.scene().bounds;
    RenderSettings s;
    s.width = 48;
    s.height = 32;
    s.shadow.resolution = 128;
    s.gi = GiMode::Lpv;
    s.lpv.resolution = 8;
    s.lpv.iterations = 2;
    s.lpv.rsmResolution = 64;
    s.lpv.vplResolution = 16;
    {
        TestRenderer r(ctx(), scene, s, 1);
        r.submit({scene.scene().cameras[0], scene.scene().lights});
        r.finish();
        const LpvCascadeBoxes* cascades = r.blackboard().get(names::kLpvCascadeBoxes);
        ASSERT_NE(cascades, nullptr);
        ASSERT_EQ(cascades->boxes.size(), 3u);  // automatic: three cascades
        for (size_t k = 0; k < cascades->boxes.size(); ++k) {
            const LpvCascadeBoxes::Box& b = cascades->boxes[k];
            for (int a = 0; a < 3; ++a) {
                EXPECT_LT(b.origin[a], bounds.min[a]) << "cascade " << k << " axis " << a;
                EXPECT_GT(b.origin[a] + b.side, bounds.max[a]) << "cascade " << k << " axis " << a;
                EXPECT_NEAR(b.origin[a] + 0.5f * b.side, bounds.center()[a], 1e-4f * b.side);
            }
            if (k > 0) {
                EXPECT_NEAR(b.side, 2.0f * cascades->boxes[k - 1].side, 1e-5f * b.side);
            }
        }
    }
    s.gi = GiMode::None;
    TestRenderer none(ctx(), scene, s, 1);
    none.submit({scene.scene().cameras[0], scene.scene().lights});
    none.finish();
    EXPECT_EQ(none.blackboard().get(names::kLpvCascadeBoxes), nullptr);
}

}  // namespace
}  // namespace penumbra::test
