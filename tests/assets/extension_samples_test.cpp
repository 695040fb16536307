// scenes/extensions.json: the glTF models this project wrote for the material extensions no
// shared sample asset shows (sheen, diffuse transmission, anisotropy, iridescence, dispersion;
// scenes/models/make_extension_samples.py). Each loads without a warning, its extension
// honoured, and the scene renders finite on the CPU (CUDA against the CPU:
// tests/render/backend/cuda/cuda_backend_test.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "render/backend/cpu/cpu_backend.h"
#include "render/compile/scene_features.h"
#include "support/load_scene.h"
#include "support/test_paths.h"

namespace pt {
namespace {

TEST(ExtensionSamples, LoadWithTheirExtensionsHonouredAndRenderFinite) {
    Scene scene = test::loadSceneOrFail(test::projectPath("scenes/extensions.json"));
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
    for (const char* extension :
         {"KHR_materials_sheen", "KHR_materials_diffuse_transmission", "KHR_materials_anisotropy",
          "KHR_materials_iridescence", "KHR_materials_dispersion"}) {
        ASSERT_EQ(scene.gltfExtensions.count(extension), 1u) << extension;
        EXPECT_TRUE(scene.gltfExtensions.at(extension)) << extension;
    }
    const Material& velvet = scene.materials[size_t(scene.findMaterial("velvet"))].params;
    EXPECT_TRUE(velvet.sheenColorTexture.present());
    EXPECT_EQ(velvet.sheenRoughnessTexture.texture, velvet.sheenColorTexture.texture);
    const Material& steel = scene.materials[size_t(scene.findMaterial("brushed steel"))].params;
    EXPECT_EQ(steel.anisotropyStrength, 0.8f);
    EXPECT_TRUE(steel.anisotropyTexture.present());
    const Material& film = scene.materials[size_t(scene.findMaterial("soap film"))].params;
    EXPECT_EQ(film.iridescence, 1.0f);
    EXPECT_EQ(film.iridescenceThicknessMin, 200.0f);
    EXPECT_EQ(film.iridescenceThicknessMax, 600.0f);
    EXPECT_TRUE(film.iridescenceThicknessTexture.present());
    const Material& flint = scene.materials[size_t(scene.findMaterial("flint glass"))].params;
    EXPECT_EQ(flint.dispersion, 1.0f);
    EXPECT_EQ(flint.transmission, 1.0f);
    EXPECT_GT(flint.thickness, 0.0f) << "dispersion acts in a volume";
    scene.render.width = 80;
    scene.render.height = 50;
    CpuBackend backend;
    backend.sync(scene, SceneChanges::All, {});
    backend.render(8);
    const FeatureSet features = backend.stats().features;
    EXPECT_NE(features & feature::kSheen, 0u);
    EXPECT_NE(features & feature::kDiffuseTransmission, 0u);
    EXPECT_NE(features & feature::kAnisotropy, 0u);
    EXPECT_NE(features & feature::kIridescence, 0u);
    EXPECT_NE(features & feature::kDispersion, 0u);
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
