// Every model in ../shared/assets renders (small, few samples) without a NaN or Inf sample,
// with its own lights (the DepthOfFieldExample sun, emissive materials) or the fallback sky;
// and every HDR environment there lights a scene through importance sampling. Skips where
// the shared assets are absent.
#include <gtest/gtest.h>

#include <cmath>

#include "assets/image/image_read.h"
#include "assets/scene_loader.h"
#include "render/compile/compile_scene.h"
#include "support/render_cpu.h"
#include "support/scene_builder.h"
#include "support/test_paths.h"

namespace pt {
namespace {

void expectFiniteAndLit(const std::vector<float>& image, const std::string& what) {
    double sum = 0.0;
    for (float v : image) {
        ASSERT_TRUE(std::isfinite(v)) << what;
        sum += v;
    }
    EXPECT_GT(sum, 0.0) << what << " rendered black";
}

class SharedModelRender : public testing::TestWithParam<const char*> {};

TEST_P(SharedModelRender, RendersWithoutNonFiniteSamples) {
    PT_REQUIRE_SHARED_ASSET(GetParam());
    const LoadResult loaded = loadScene(test::sharedAsset(GetParam()));
    ASSERT_TRUE(loaded.ok()) << loaded.error;
    Scene scene = *loaded.scene;
    scene.render.width = 32;
    scene.render.height = 24;
    scene.render.maxDepth = 6;
    expectFiniteAndLit(test::renderCpu(scene, 4), GetParam());
}

INSTANTIATE_TEST_SUITE_P(Shared, SharedModelRender,
                         testing::Values("CornellBox/CornellBox.glb", "GolfBall/GolfBall.glb",
                                         "DepthOfFieldExample/DepthOfFieldExample.glb",
                                         "TonemappingTest/TonemappingTest.gltf", "Fox/Fox.glb",
                                         "SimpleSkin/SimpleSkin.gltf",
                                         "AnisotropyBarnLamp/AnisotropyBarnLamp.gltf", "Balloon/scene.gltf",
                                         "CornellBoxObj/cornell_box.obj"),
                         [](const testing::TestParamInfo<const char*>& param) {
                             const std::string path = param.param;
                             return path.substr(0, path.find('/'));
                         });

TEST(SharedModelRender, DepthOfFieldExampleSunLightsTheScene) {
    PT_REQUIRE_SHARED_ASSET("DepthOfFieldExample/DepthOfFieldExample.glb");
    const LoadResult loaded = loadScene(test::sharedAsset("DepthOfFieldExample/DepthOfFieldExample.glb"));
    ASSERT_TRUE(loaded.ok()) << loaded.error;
    ASSERT_EQ(loaded.scene->lights.size(), 1u);
    const CompiledScene compiled = compileRenderScene(*loaded.scene);
    EXPECT_EQ(compiled.stats.punctualLightCount, 1u);
    EXPECT_GT(compiled.stats.emitterCount, 0u) << "the lava emits too";
}

class SharedEnvironmentRender : public testing::TestWithParam<const char*> {};

// A glossy sphere on a diffuse floor under each HDR map.
TEST_P(SharedEnvironmentRender, LightsASceneThroughImportanceSampling) {
    const std::string path = std::string("environments/") + GetParam();
    PT_REQUIRE_SHARED_ASSET(path);
    Scene scene;
    scene.render = {32, 24, 6, 0, 0};
    scene.camera.position = {0, 1, 4};
    scene.camera.lookAt = {0, 0.5f, 0};
    scene.textures.push_back(readTextureFile(test::sharedAsset(path)));
    scene.environment.texture = 0;
    scene.environment.rotationDegrees = 30;
    Material metal;
    metal.metallic = 1.0f;
    metal.roughness = 0.2f;
    test::addShape(scene, ObjectKind::Quad, test::trs({0, 0, 0}, {0, 0, 0}, {3, 1, 3}),
                   test::addMaterial(scene, "floor", test::diffuse(Vec3(0.6f))));
    test::addShape(scene, ObjectKind::Sphere, test::trs({0, 0.5f, 0}, {0, 0, 0}, Vec3(0.5f)),
                   test::addMaterial(scene, "metal", metal));
    const CompiledScene compiled = compileRenderScene(scene);
    EXPECT_TRUE(compiled.stats.environmentSampled);
    EXPECT_EQ(compiled.environment.distWidth, scene.textures[0].width);
    expectFiniteAndLit(test::renderCpu(scene, 8), path);
}

INSTANTIATE_TEST_SUITE_P(Shared, SharedEnvironmentRender,
                         testing::Values("studio_small_03_1k.hdr", "venice_sunset_1k.hdr",
                                         "empty_warehouse_01_1k.hdr", "spiaggia_di_mondello_1k.hdr"),
                         [](const testing::TestParamInfo<const char*>& param) {
                             std::string name = param.param;
                             name = name.substr(0, name.find('_'));
                             return name;
                         });

}  // namespace
}  // namespace pt
