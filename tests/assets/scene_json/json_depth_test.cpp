// Deeply nested JSON must end in one clean error before any recursive parser sees it (issue 17:
// 20,000 '[' in a glTF's extras, a 100,000-deep value the glTF check would have quoted, and a
// 74,000-deep value in scene JSON overflowed the stack). The inputs are generated here.
#include "assets/scene_json/json_depth.h"

#include <gtest/gtest.h>

#include <string>

#include "assets/input_error.h"
#include "assets/model_import.h"
#include "assets/scene_json/scene_json.h"
#include "support/input_error_of.h"
#include "support/test_paths.h"

namespace pt {
namespace {

std::string nested(uint32_t depth, const std::string& inner = "") {
    return std::string(depth, '[') + inner + std::string(depth, ']');
}

std::string depthError(const std::string& text, uint32_t limit = kMaxJsonDepth) {
    try {
        checkJsonDepth(text, "f.json", limit);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(JsonDepth, AcceptsTheLimitAndRejectsOneLevelMore) {
    EXPECT_EQ(depthError(nested(kMaxJsonDepth)), "");
    EXPECT_EQ(depthError("{\"a\": " + nested(kMaxJsonDepth - 1) + "}"), "");
    EXPECT_EQ(depthError(nested(kMaxJsonDepth + 1)),
              "f.json: JSON nested deeper than 256 levels (at byte 256)");
    // Siblings do not add up: depth is nesting, not count.
    std::string wide = "[";
    for (int i = 0; i < 1000; ++i) wide += nested(200) + ",";
    EXPECT_EQ(depthError(wide + "0]"), "");
}

TEST(JsonDepth, BracketsInStringsDoNotCount) {
    const std::string brackets(300, '[');
    EXPECT_EQ(depthError("[\"" + brackets + "\"]", 2), "");
    // An escaped quote does not end the string; an escaped backslash before the quote does.
    EXPECT_EQ(depthError("[\"\\\"" + brackets + "\"]", 2), "");
    EXPECT_NE(depthError("[\"\\\\\"" + brackets + "\"]", 2), "");
}

TEST(JsonDepth, DeepGltfExtrasEndInAnErrorNamingTheFile) {
    const std::string path = test::writeTempFile(
        "deep_extras.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"extras\": " + nested(20000) + "}");
    Scene scene;
    const std::string message = test::inputErrorOf([&] { importGltf(path, 0, scene); });
    EXPECT_EQ(message.rfind("deep_extras.gltf: JSON nested deeper than 256 levels", 0), 0u) << message;
}

TEST(JsonDepth, ADeepGltfValueIsNeverQuoted) {
    const std::string path = test::writeTempFile(
        "deep_value.gltf",
        "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [{\"mesh\": " + nested(100000) + "}]}");
    Scene scene;
    const std::string message = test::inputErrorOf([&] { importGltf(path, 0, scene); });
    EXPECT_EQ(message.rfind("deep_value.gltf: JSON nested deeper than 256 levels", 0), 0u) << message;
    EXPECT_LT(message.size(), 200u);
}

TEST(JsonDepth, ADeepSceneJsonValueFollowedByAKeyEndsInAnError) {
    const std::string path = test::writeTempFile(
        "deep_scene.json",
        "{\"version\": 1, \"camera\": {\"position\": " + nested(74000) + "}, \"objects\": []}");
    const std::string message = test::inputErrorOf([&] { readSceneJson(path); });
    EXPECT_EQ(message.rfind("deep_scene.json: JSON nested deeper than 256 levels", 0), 0u) << message;
}

}  // namespace
}  // namespace pt
