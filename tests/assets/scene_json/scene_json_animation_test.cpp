// Scene JSON keeps a file object's animation and time (issue 19): "animation": {"name",
// "time"} poses the object's rig on load, is written back, and names what is wrong with it.
#include <gtest/gtest.h>

#include "assets/scene_json/scene_json.h"
#include "assets/scene_loader.h"
#include "support/load_scene.h"
#include "support/test_paths.h"

namespace pt {
namespace {

// tests/data/gltf/anim_slide.gltf: a quad sliding one unit along x in its first second.
std::string sceneWith(const std::string& objectExtra) {
    return R"({"version": 1, "objects": [{"file": ")" + test::testDataPath("gltf/anim_slide.gltf") + "\"" +
           objectExtra + "}]}";
}

TEST(SceneJsonAnimation, TheAnimationAndTimeArePosedOnLoadAndWrittenBack) {
    const std::string path =
        test::writeTempFile("animated.json", sceneWith(R"(, "animation": {"name": "slide", "time": 0.25})"));
    const Scene scene = test::loadSceneOrFail(path);
    ASSERT_EQ(scene.instances.size(), 1u);
    EXPECT_FLOAT_EQ(scene.instances[0].objectToWorld.translation().x, 0.25f);
    EXPECT_EQ(scene.objects[0].animation, "slide");
    EXPECT_FLOAT_EQ(scene.objects[0].animationTime, 0.25f);

    const std::string saved = test::tempDir() + "/animated_saved.json";
    writeSceneJson(scene, saved);
    EXPECT_NE(test::readTextFile(saved).find(R"("name": "slide")"), std::string::npos)
        << test::readTextFile(saved);
    const Scene again = test::loadSceneOrFail(saved);
    EXPECT_FLOAT_EQ(again.instances[0].objectToWorld.translation().x, 0.25f);
    EXPECT_EQ(again.objects[0].animation, "slide");

    // Without the key: the rest pose, and nothing written.
    const Scene rest = test::loadSceneOrFail(test::writeTempFile("rest.json", sceneWith("")));
    EXPECT_FLOAT_EQ(rest.instances[0].objectToWorld.translation().x, 0.0f);
    writeSceneJson(rest, saved);
    EXPECT_EQ(test::readTextFile(saved).find("animation"), std::string::npos);
}

TEST(SceneJsonAnimation, ABadAnimationIsOneLineNamingIt) {
    const auto refused = [](const std::string& json, const std::string& words) {
        const LoadResult r = loadScene(test::writeTempFile("bad_animation.json", json));
        ASSERT_FALSE(r.ok());
        EXPECT_NE(r.error.find(words), std::string::npos) << r.error;
    };
    refused(sceneWith(R"(, "animation": {"name": "run"})"),
            "\"run\" is not an animation of anim_slide.gltf (its animations: \"slide\")");
    refused(sceneWith(R"(, "animation": {"name": "slide", "tme": 1})"), "tme");
    refused(R"({"version": 1, "objects": [{"shape": "box", "animation": {"name": "slide"}}]})",
            "shapes have no animations");
    refused(R"({"version": 1, "objects": [{"file": ")" + test::testDataPath("gltf/minimal.glb") +
                R"(", "animation": {"name": "slide"}}]})",
            "minimal.glb has no animations");
}

}  // namespace
}  // namespace pt
