// scenes/extensions.json: the glTF models this project wrote for the material extensions no
// shared sample asset shows (scenes/models/make_extension_samples.py). Each loads without a
// warning, its extension honoured, and the scene renders finite on the CPU (CUDA against the
// CPU: tests/cuda/cuda_backend_test.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "render/backend/cpu/cpu_backend.h"
#include "render/scene/scene_features.h"
#include "support/load_scene.h"
#include "support/test_paths.h"

namespace pt {
namespace {

TEST(ExtensionSamples, LoadWithTheirExtensionsHonouredAndRenderFinite) {
    Scene scene = test::loadSceneOrFail(test::projectPath("scenes/extensions.json"));
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
    for (const char* extension : {"KHR_materials_sheen", "KHR_materials_diffuse_transmission"}) {
        ASSERT_EQ(scene.gltfExtensions.count(extension), 1u) << extension;
        EXPECT_TRUE(scene.gltfExtensions.at(extension)) << extension;
    }
    const Material& velvet = scene.materials[size_t(scene.findMaterial("velvet"))].params;
    EXPECT_TRUE(velvet.sheenColorTexture.present());
    EXPECT_EQ(velvet.sheenRoughnessTexture.texture, velvet.sheenColorTexture.texture);
    scene.render.width = 80;
    scene.render.height = 50;
    CpuBackend backend;
    backend.sync(scene, SceneChanges::All, {});
    backend.render(8);
    const uint32_t features = backend.stats().features;
    EXPECT_NE(features & feature::kSheen, 0u);
    EXPECT_NE(features & feature::kDiffuseTransmission, 0u);
    EXPECT_EQ(backend.stats().nonfiniteSamples, 0u);
    std::vector<float> rgba;
    backend.readBeauty(rgba);
    double sum = 0.0;
    for (float v : rgba) {
        ASSERT_TRUE(std::isfinite(v));
        sum += v;
    }
    EXPECT_GT(sum, 0.0);
}

}  // namespace
}  // namespace pt
