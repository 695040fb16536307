// Integrator tests on scenes with exact or analytic answers.
#include "render/integrator/path_tracer.h"

#include <gtest/gtest.h>

#include <cmath>

#include "support/render_cpu.h"
#include "support/scene_builder.h"

namespace pt {
namespace {

using test::addMaterial;
using test::addShape;
using test::diffuse;
using test::trs;

Scene sphereInConstantSky(Material sphereMaterial, Vec3 sky) {
    Scene scene;
    scene.environment.color = sky;
    scene.render.width = 48;
    scene.render.height = 32;
    scene.render.maxDepth = 64;
    scene.camera.position = {0, 0, 4};
    scene.camera.lookAt = {0, 0, 0};
    scene.camera.verticalFovDegrees = 40;
    addShape(scene, ObjectKind::Sphere, trs({0, 0, 0}), addMaterial(scene, "s", sphereMaterial));
    return scene;
}

// BSDF sampling alone: with NEE the sky is also light-sampled and MIS-weighted, which is
// unbiased but no longer exact sample by sample.
const IntegratorToggles kBsdfSamplingOnly{false, false, true, false};

// A convex diffuse sphere under a uniform sky: one bounce always escapes, so every sample of
// a pixel on the sphere is exactly albedo x sky. A ray that re-hit its own surface (bad
// origin offsets) would return albedo^2 x sky.
TEST(PathTracer, ConvexDiffuseSphereUnderUniformSkyIsExact) {
    const Vec3 sky{0.8f, 0.6f, 0.4f};
    const Scene scene = sphereInConstantSky(diffuse({0.5f, 0.5f, 0.5f}), sky);
    const std::vector<float> image = test::renderCpu(scene, 8, kBsdfSamplingOnly);
    size_t onSphere = 0;
    for (size_t i = 0; i < image.size() / 4; ++i) {
        const float r = image[i * 4];
        const bool background = std::fabs(r - sky.x) < 1e-6f;
        const bool sphere = std::fabs(r - 0.5f * sky.x) < 1e-6f;
        // Edge pixels mix the two, in multiples of 1/8.
        const float fraction = (sky.x - r) / (0.5f * sky.x);
        ASSERT_NEAR(fraction * 8.0f, std::round(fraction * 8.0f), 1e-3f) << "pixel " << i << " = " << r;
        onSphere += sphere;
        (void)background;
    }
    EXPECT_GT(onSphere, 100u);
}

// The same exact answer 1e5 units from the origin and at a scale of 1e-4: ray origins are
// offset in proportion to the coordinates' magnitude, so there is no self-intersection
// (acne) far out and no light leak when small.
TEST(PathTracer, ConvexSphereStaysExactFarFromTheOriginAndAtTinyScale) {
    const Vec3 sky{0.8f, 0.6f, 0.4f};
    for (const auto& [offset, scale] : {std::pair<float, float>{1e5f, 1.0f}, {0.0f, 1e-4f}, {-3e4f, 50.0f}}) {
        Scene scene = sphereInConstantSky(diffuse({0.5f, 0.5f, 0.5f}), sky);
        scene.instances[0].objectToWorld = trs(Vec3(offset), {0, 0, 0}, Vec3(scale)).toAffine();
        scene.camera.position = Vec3(offset) + Vec3{0, 0, 4 * scale};
        scene.camera.lookAt = Vec3(offset);
        const std::vector<float> image = test::renderCpu(scene, 4, kBsdfSamplingOnly);
        size_t onSphere = 0;
        for (size_t i = 0; i < image.size() / 4; ++i) {
            const float fraction = (sky.x - image[i * 4]) / (0.5f * sky.x);
            ASSERT_NEAR(fraction * 4.0f, std::round(fraction * 4.0f), 1e-3f)
                << "offset " << offset << " scale " << scale << " pixel " << i << " = " << image[i * 4];
            onSphere += std::fabs(fraction - 1.0f) < 1e-4f;
        }
        EXPECT_GT(onSphere, 100u) << "offset " << offset << " scale " << scale;
    }
}

// IOR 1 glass is no interface at all: the sphere must vanish against the sky.
TEST(PathTracer, IndexMatchedGlassSphereVanishes) {
    Material glass;
    glass.baseColor = {1, 1, 1};
    glass.transmission = 1.0f;
    glass.roughness = 0.0f;
    glass.ior = 1.0f;
    const Vec3 sky{0.3f, 0.5f, 0.7f};
    const std::vector<float> image = test::renderCpu(sphereInConstantSky(glass, sky), 4);
    for (size_t i = 0; i < image.size() / 4; ++i) {
        ASSERT_NEAR(image[i * 4 + 0], sky.x, 1e-5f) << "pixel " << i;
        ASSERT_NEAR(image[i * 4 + 2], sky.z, 1e-5f) << "pixel " << i;
    }
}

// Form factor from a differential area to a parallel a x b rectangle whose corner lies
// straight above it at height h (Howell's catalogue, C-11).
double cornerFormFactor(double a, double b, double h) {
    const double x = a / h, y = b / h;
    const double sx = std::sqrt(1 + x * x), sy = std::sqrt(1 + y * y);
    return (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy)) / (2 * kPi);
}

// A diffuse floor point under a square light: L = albedo * Le * F. Direct lighting only, so
// NEE alone, BSDF sampling alone, and both with MIS must each converge to it.
TEST(PathTracer, DirectLightFromASquareEmitterMatchesTheFormFactor) {
    const float albedo = 0.7f, radiance = 5.0f, halfSize = 0.5f, height = 1.0f;
    Scene scene;
    scene.render = {8, 8, 1, 0, 0};
    scene.camera.position = {0, 0.5f, 0};
    scene.camera.lookAt = {0, 0, 0};
    scene.camera.up = {0, 0, -1};
    scene.camera.verticalFovDegrees = 0.01f;  // every pixel sees the floor point below the light
    addShape(scene, ObjectKind::Quad, trs({0, 0, 0}, {0, 0, 0}, {10, 1, 10}),
             addMaterial(scene, "floor", diffuse({albedo, albedo, albedo})));
    Material light = diffuse({0, 0, 0});
    light.emission = {radiance, radiance, radiance};
    addShape(scene, ObjectKind::Quad, trs({0, height, 0}, {180, 0, 0}, {halfSize, 1, halfSize}),
             addMaterial(scene, "light", light));
    const double expected = albedo * radiance * 4 * cornerFormFactor(halfSize, halfSize, height);

    struct Variant {
        const char* name;
        IntegratorToggles toggles;
        uint32_t spp;
        double tolerance;
    };
    const Variant variants[] = {{"nee+mis", {true, true, true, false}, 256, 0.005},
                                {"nee only", {true, false, true, false}, 256, 0.005},
                                {"bsdf only", {false, false, true, false}, 4096, 0.02}};
    for (const Variant& v : variants) {
        const std::vector<float> image = test::renderCpu(scene, v.spp, v.toggles);
        double mean = 0;
        for (size_t i = 0; i < image.size() / 4; ++i) mean += image[i * 4 + 1];
        mean /= double(image.size() / 4);
        EXPECT_NEAR(mean / expected, 1.0, v.tolerance) << v.name << ": " << mean << " vs " << expected;
    }
}

}  // namespace
}  // namespace pt
