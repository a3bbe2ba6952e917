// Named views (`--view NAME`): the documented views resolve by the scene's file name, match the
// evaluation suite's cameras and lights, and an unknown name is refused naming the views there are.
#include <map>

#include <gtest/gtest.h>

#include "cli_run.h"
#include "eval/suite.h"
#include "frame/frame_options.h"
#include "frame/input_parse.h"
#include "scene/named_views.h"

namespace penumbra {
namespace {

void expectSameCamera(const Camera& a, const Camera& b) {
    EXPECT_EQ(a.eye, b.eye);
    EXPECT_EQ(a.target, b.target);
    EXPECT_EQ(a.up, b.up);
    EXPECT_EQ(a.fovy, b.fovy);
}

TEST(NamedViews, KeyIsTheLowerCaseFileStemOrTheBuiltinName) {
    EXPECT_EQ(namedViewKey("../shared/assets/sponza/glTF/Sponza.gltf"), "sponza");
    EXPECT_EQ(namedViewKey("/x/VC.glb"), "vc");
    EXPECT_EQ(namedViewKey("cornell"), "cornell");
    EXPECT_EQ(findNamedView("elsewhere/Sponza.gltf", "nave").camera, "-9,1.7,0.3,6,4.5,0,0,1,0,70");
    EXPECT_THROW(findNamedView("cornell", "nave"), std::invalid_argument);
    EXPECT_THROW(findNamedView("Sponza.gltf", "overview"), std::invalid_argument);
}

// The suite's Sponza and VC views (src/eval/suite.cpp) are the documented views: --view gives the
// frame the suite's camera and lights, through the same path --camera and --light take.
TEST(NamedViews, ViewsAreTheEvaluationSuitesCamerasAndLights) {
    const std::map<std::string, std::string> viewOfSuiteScene{{"sponza", "nave"}, {"vc", "overview"}};
    for (const SuiteScene& s : suiteScenes("assets", {"sponza", "vc"})) {
        SCOPED_TRACE(s.name);
        FrameOptions o;
        o.scene = s.scene;
        o.view = viewOfSuiteScene.at(s.name);
        RenderSettings settings;
        checkFrameSettings(o, settings);
        Scene loaded;
        loaded.lights.push_back(parseLight("point,0,1,0,5"));  // the file's own light
        expectSameCamera(frameCamera(o, loaded), parseCamera(s.camera));
        const std::vector<Light> lights = frameLights(o, loaded);
        if (s.lights.empty()) {
            ASSERT_EQ(lights.size(), 1u);
            EXPECT_EQ(lights[0].type, LightType::Point);
        } else {
            ASSERT_EQ(lights.size(), s.lights.size());
            EXPECT_EQ(lights[0].direction, parseLight(s.lights[0]).direction);
            EXPECT_EQ(lights[0].intensity, parseLight(s.lights[0]).intensity);
        }
        // --camera and --light given beside --view replace the view's.
        o.parsedCamera = parseCamera("0,0,5,0,0,0,0,1,0,45");
        o.parsedLights = {parseLight("point,0,2,0,3")};
        expectSameCamera(frameCamera(o, loaded), *o.parsedCamera);
        EXPECT_EQ(frameLights(o, loaded)[0].intensity, 3.0f);
    }
}

TEST(NamedViews, UnknownNamesAreRefusedListingTheViews) {
    test::ScratchDir dir("named_views");
    // A name no scene has: refused while the options are parsed, listing every scene's views.
    test::expectRefused(dir, "render cornell --view bogus --dry-run -o " + dir.file("a.png"), "sponza: nave, aisle");
    // A name of another scene's view: refused before the scene loads, naming this scene's.
    test::expectRefused(dir, "render somewhere/Sponza.gltf --view overview --dry-run -o " + dir.file("b.png"),
                        "its views: nave, aisle");
    test::expectRefused(dir, "render cornell --view nave --dry-run -o " + dir.file("c.png"), "no named views");
}

}  // namespace
}  // namespace penumbra
