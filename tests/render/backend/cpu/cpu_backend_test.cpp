// CpuBackend's scene features: recomputed at every sync, whichever path the edit takes (the
// materials alone for materials, no compile for camera and environment), plus the AOVs it
// accumulates and the brute-force toggle. The CPU runs one generic kernel: no variant to report.
#include "render/backend/cpu/cpu_backend.h"

#include <gtest/gtest.h>

#include "render/compile/scene_features.h"
#include "support/scene_builder.h"

namespace pt {
namespace {

using namespace feature;

// A small quad lit by a point light; a smooth dielectric (no features).
Scene litQuad() {
    Scene scene;
    scene.render = {8, 8, 2, 1, 0};
    scene.camera.position = {0, 2, 0};
    scene.camera.up = {0, 0, -1};
    Material smooth;
    smooth.roughness = 0.0f;  // the default 0.5 would be a glossy specular layer
    const uint32_t m = test::addMaterial(scene, "quad", smooth);
    test::addShape(scene, ObjectKind::Quad, test::trs({0, 0, 0}), m, "quad");
    test::addLight(scene, LightType::Point, {1, 1, 1}, 5.0f, {0, 1, 0});
    return scene;
}

#define EXPECT_FEATURES(backend, expected) \
    EXPECT_EQ(describeFeatures((backend).stats().features), describeFeatures(expected))

TEST(CpuBackendFeatures, FollowEveryEdit) {
    Scene scene = litQuad();
    CpuBackend backend;
    backend.sync(scene, SceneChanges::All, {});
    EXPECT_FEATURES(backend, kPunctualLights);
    EXPECT_EQ(backend.stats().kernelVariant, "");
    EXPECT_EQ(backend.stats().kernelFeatures, 0u);

    scene.materials[0].params.clearcoat = 1.0f;
    backend.sync(scene, SceneChanges::Materials, {});
    EXPECT_FEATURES(backend, kPunctualLights | kClearcoat);

    // Camera and environment edits reset without recompiling: the features must follow anyway.
    scene.camera.apertureRadius = 0.05f;
    backend.sync(scene, SceneChanges::Camera, {});
    EXPECT_FEATURES(backend, kPunctualLights | kClearcoat | kThinLens);
    scene.environment.color = {0.1f, 0.1f, 0.1f};
    backend.sync(scene, SceneChanges::Environment, {});
    EXPECT_FEATURES(backend, kPunctualLights | kClearcoat | kThinLens | kConstantEnvironment);
    scene.lights.clear();
    backend.sync(scene, SceneChanges::Lights, {});
    EXPECT_FEATURES(backend, kClearcoat | kThinLens | kConstantEnvironment);

    // Removing a feature removes its bit.
    scene.materials[0].params.clearcoat = 0.0f;
    scene.camera.apertureRadius = 0.0f;
    backend.sync(scene, SceneChanges::Materials | SceneChanges::Camera, {});
    EXPECT_FEATURES(backend, kConstantEnvironment);
    EXPECT_EQ(backend.stats().kernelVariant, "");
}

TEST(CpuBackendFeatures, AovsCountOnceAReset) {
    CpuBackend backend;
    backend.sync(litQuad(), SceneChanges::All, {});
    EXPECT_FEATURES(backend, kPunctualLights);
    backend.setAovs(aovBit(Aov::Albedo) | aovBit(Aov::Depth));
    EXPECT_FEATURES(backend, kPunctualLights);  // not accumulated before the reset
    backend.resetAccumulation();
    EXPECT_FEATURES(backend, kPunctualLights | kAovs);
    backend.render(1);
    EXPECT_FEATURES(backend, kPunctualLights | kAovs);
    // The variance alone is an AOV too (not a path AOV, but a buffer all the same).
    backend.setAovs(aovBit(Aov::Variance));
    backend.resetAccumulation();
    EXPECT_FEATURES(backend, kPunctualLights | kAovs);
    backend.setAovs(0);
    backend.resetAccumulation();
    EXPECT_FEATURES(backend, kPunctualLights);
}

TEST(CpuBackendFeatures, BruteForceToggle) {
    const Scene scene = litQuad();
    CpuBackend backend;
    IntegratorToggles toggles;
    toggles.bruteForce = true;
    backend.setToggles(toggles);
    backend.sync(scene, SceneChanges::All, {});
    EXPECT_FEATURES(backend, kPunctualLights | kBruteForce);
    toggles.bruteForce = false;
    backend.setToggles(toggles);
    backend.sync(scene, SceneChanges::Settings, {});
    EXPECT_FEATURES(backend, kPunctualLights);
}

}  // namespace
}  // namespace pt
