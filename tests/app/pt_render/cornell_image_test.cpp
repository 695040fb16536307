// The default scene against a stored high-sample reference (tests/data/reference), and the
// scene JSON round trip rendering bit-identically.
#include <gtest/gtest.h>

#include <cstring>

#include "app/render_test_support.h"
#include "assets/image/image_write.h"
#include "assets/scene_json/scene_json.h"
#include "support/test_paths.h"

namespace pt {
namespace {

constexpr uint32_t kSize = 128;
// The reference: `pt-render render scenes/cornell.json --size 128x128 --spp 16384 --seed 1`.
// Measured on 2026-11-21 with 16x16 blocks: 256 spp of the unchanged renderer 0.0045; cut to
// two bounces 0.218; 5% darker 0.039. The bound sits between with a margin of 2.5 or more.
constexpr uint32_t kSpp = 256;
constexpr uint32_t kBlock = 16;
constexpr double kErrorBound = 0.015;

TEST(CornellImage, MatchesTheReferenceWithinANoiseBound) {
    PT_REQUIRE_OIIO();  // the reference is an EXR
    Scene scene = test::loadSceneOrFail(test::projectPath("scenes/cornell.json"));
    scene.render.width = scene.render.height = kSize;
    uint32_t w = 0, h = 0;
    const std::vector<float> reference = readImageRgba(test::testDataPath("reference/cornell_128.exr"), w, h);
    ASSERT_EQ(w, kSize);
    ASSERT_EQ(h, kSize);
    const std::vector<float> image = test::renderCpu(scene, kSpp);
    const double error = test::blockRelativeError(image, reference, kSize, kSize, kBlock);
    RecordProperty("blockRelativeError", std::to_string(error));
    EXPECT_LT(error, kErrorBound);

    // The bound must catch real regressions: the same render cut to two bounces, or 5% darker
    // everywhere, fails it.
    Scene shallow = scene;
    shallow.render.maxDepth = 2;
    const double shallowError =
        test::blockRelativeError(test::renderCpu(shallow, kSpp), reference, kSize, kSize, kBlock);
    RecordProperty("shallowBlockRelativeError", std::to_string(shallowError));
    EXPECT_GT(shallowError, kErrorBound);
    std::vector<float> darker = image;
    for (float& v : darker) v *= 0.95f;
    const double darkerError = test::blockRelativeError(darker, reference, kSize, kSize, kBlock);
    RecordProperty("darkerBlockRelativeError", std::to_string(darkerError));
    EXPECT_GT(darkerError, kErrorBound);
}

TEST(CornellImage, LoadSaveLoadRendersBitIdentically) {
    const Scene original = test::loadSceneOrFail(test::projectPath("scenes/cornell.json"));
    const std::string saved = test::tempDir() + "/cornell-roundtrip.json";
    writeSceneJson(original, saved);
    const Scene reloaded = test::loadSceneOrFail(saved);
    Scene a = original, b = reloaded;
    a.render.width = b.render.width = 64;
    a.render.height = b.render.height = 48;
    const std::vector<float> imageA = test::renderCpu(a, 4), imageB = test::renderCpu(b, 4);
    ASSERT_EQ(imageA.size(), imageB.size());
    EXPECT_EQ(std::memcmp(imageA.data(), imageB.data(), imageA.size() * sizeof(float)), 0);
}

}  // namespace
}  // namespace pt
