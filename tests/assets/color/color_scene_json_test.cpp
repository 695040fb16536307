// The scene JSON "color" block: read (config relative to the scene file), written back
// relative and only when set, and bad values named by file and key.
#include <gtest/gtest.h>

#include <filesystem>

#include "assets/input_error.h"
#include "assets/scene_json/scene_json.h"
#include "assets/scene_test_helpers.h"
#include "support/load_scene.h"

namespace pt {
namespace {

namespace fs = std::filesystem;

std::string sceneWithColor(const std::string& color) {
    return R"({"version": 1, "color": )" + color + R"(, "objects": [{"shape": "sphere"}]})";
}

TEST(SceneJsonColor, ReadsAndWritesTheColorBlockWithARelativeConfig) {
    const std::string folder = test::testFolder() + "/color_block";
    fs::create_directories(folder + "/ocio");
    fs::create_directories(folder + "/out");
    test::writeFile(folder + "/ocio", "studio.ocio", "ocio_profile_version: 2.1\n");  // never parsed here
    const std::string path = test::writeFile(
        folder, "scene.json",
        sceneWithColor(
            R"({"config": "ocio/studio.ocio", "display": "sRGB", "view": "AgX", "look": "Exposure +1"})"));
    const Scene scene = test::loadSceneOrFail(path);
    EXPECT_EQ(scene.color.config, fs::path(folder + "/ocio/studio.ocio").lexically_normal().string());
    EXPECT_EQ(scene.color.display, "sRGB");
    EXPECT_EQ(scene.color.view, "AgX");
    EXPECT_EQ(scene.color.look, "Exposure +1");

    const std::string again = folder + "/out/again.json";
    writeSceneJson(scene, again);
    const std::string text = test::readFile(again);
    EXPECT_NE(text.find(R"("color": {)"), std::string::npos) << text;
    EXPECT_NE(text.find(R"("config": "../ocio/studio.ocio")"), std::string::npos)
        << "relative to the output: " << text;
    const Scene reread = test::loadSceneOrFail(again);
    EXPECT_EQ(reread.color.config, scene.color.config);
    EXPECT_EQ(reread.color.display, scene.color.display);
    EXPECT_EQ(reread.color.view, scene.color.view);
    EXPECT_EQ(reread.color.look, scene.color.look);
    EXPECT_EQ(sceneToJson(reread, again), text) << "stable";
}

TEST(SceneJsonColor, DefaultsAreLeftOutAndPartialBlocksKeepTheirKeys) {
    const std::string folder = test::testFolder();
    const Scene plain = test::loadSceneOrFail(test::writeFile(folder, "plain.json", sceneWithColor("{}")));
    EXPECT_EQ(plain.color.config, "");
    EXPECT_EQ(plain.color.view, "");
    EXPECT_EQ(sceneToJson(plain, folder + "/plain_out.json").find("color"), std::string::npos);

    const Scene viewOnly = test::loadSceneOrFail(
        test::writeFile(folder, "view_only.json", sceneWithColor(R"({"view": "Raw"})")));
    EXPECT_EQ(viewOnly.color.view, "Raw");
    const std::string text = sceneToJson(viewOnly, folder + "/view_only_out.json");
    EXPECT_NE(text.find("\"color\": {\n    \"view\": \"Raw\"\n  }"), std::string::npos) << text;
}

TEST(SceneJsonColor, BadValuesNameTheFileAndTheKey) {
    const std::string folder = test::testFolder();
    struct Case {
        std::string color, needle;
    };
    const Case cases[] = {
        {R"({"view": 3})", "color.view"},     {R"({"display": ""})", "color.display"},
        {R"({"look": ["a"]})", "color.look"}, {R"({"config": "missing.ocio"})", "color.config"},
        {R"({"veiw": "AgX"})", "veiw"},       {R"("AgX")", "color"},
    };
    for (const Case& c : cases) {
        const std::string path = test::writeFile(folder, "bad_color.json", sceneWithColor(c.color));
        const LoadResult result = loadScene(path);
        ASSERT_FALSE(result.ok()) << c.color;
        EXPECT_NE(result.error.find("bad_color.json"), std::string::npos) << result.error;
        EXPECT_NE(result.error.find(c.needle), std::string::npos) << c.color << ": " << result.error;
    }
}

}  // namespace
}  // namespace pt
