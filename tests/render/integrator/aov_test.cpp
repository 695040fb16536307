// AOVs on the CPU backend: values against an analytic sphere, ids, misses, the sample count,
// variance against a direct computation, a beauty left bit-identical, and memory that exists
// only for the AOVs enabled.
#include "render/integrator/aov.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "render/backend/aov.h"
#include "render/backend/cpu/cpu_backend.h"
#include "render/backend/toggle_states.h"
#include "render/compile/compile_scene.h"
#include "render/integrator/path_tracer.h"
#include "support/aov_scenes.h"
#include "support/scene_builder.h"

namespace pt {
namespace {

using test::addMaterial;
using test::addShape;
using test::trs;

IntegratorToggles noJitter() {
    IntegratorToggles t;
    t.pixelJitter = false;
    return t;
}

// Renders `spp` samples with `aovs` enabled.
void renderWithAovs(Backend& backend, const Scene& scene, uint32_t spp, AovMask aovs,
                    const IntegratorToggles& toggles = {}) {
    backend.setToggles(toggles);
    backend.setAovs(aovs);
    backend.sync(scene, SceneChanges::All, {});
    backend.render(spp);
}

std::vector<float> readAov(const Backend& backend, Aov aov) {
    std::vector<float> rgba;
    backend.readAov(aov, rgba);
    EXPECT_EQ(rgba.size(), size_t(backend.width()) * backend.height() * 4) << aovName(aov);
    return rgba;
}

TEST(Aov, NamesRoundTrip) {
    for (uint32_t i = 0; i < kAovCount; ++i) {
        Aov parsed = Aov::Count;
        ASSERT_TRUE(parseAov(aovName(Aov(i)), parsed)) << aovName(Aov(i));
        EXPECT_EQ(parsed, Aov(i));
    }
    Aov unused;
    EXPECT_FALSE(parseAov("normals", unused));
    EXPECT_STREQ(aovName(Aov::ShadingNormal), "shading_normal");
    EXPECT_STREQ(aovName(Aov::BvhCost), "bvh_cost");
}

TEST(Aov, SphereMatchesTheAnalyticHit) {
    const Scene scene = test::analyticSphereScene();
    const uint32_t spp = 4;
    CpuBackend backend;
    renderWithAovs(backend, scene, spp, kAllAovs, noJitter());
    const std::vector<float> albedo = readAov(backend, Aov::Albedo),
                             shading = readAov(backend, Aov::ShadingNormal),
                             geometric = readAov(backend, Aov::GeometricNormal),
                             depth = readAov(backend, Aov::Depth), position = readAov(backend, Aov::Position),
                             uv = readAov(backend, Aov::Uv), roughness = readAov(backend, Aov::Roughness),
                             metallic = readAov(backend, Aov::Metallic),
                             emission = readAov(backend, Aov::Emission),
                             instance = readAov(backend, Aov::InstanceId),
                             material = readAov(backend, Aov::MaterialId),
                             cost = readAov(backend, Aov::BvhCost),
                             count = readAov(backend, Aov::SampleCount), alpha = readAov(backend, Aov::Alpha);
    const Material m = test::aovSphereMaterial();
    const Vec3 emitted = m.emission * m.emissionStrength;
    uint32_t hits = 0, misses = 0;
    for (uint32_t y = 0; y < scene.render.height; ++y) {
        for (uint32_t x = 0; x < scene.render.width; ++x) {
            const size_t i = (size_t(y) * scene.render.width + x) * 4;
            SCOPED_TRACE(testing::Message() << "pixel " << x << ", " << y);
            EXPECT_EQ(count[i], float(spp));
            const test::AnalyticSphereHit a = test::analyticSphereHit(scene, x, y);
            if (a.graze) continue;
            if (!a.hit) {
                ++misses;
                for (const std::vector<float>* img :
                     {&albedo, &shading, &geometric, &depth, &position, &uv, &roughness, &metallic}) {
                    for (int c = 0; c < 3; ++c) ASSERT_EQ((*img)[i + c], 0.0f);
                }
                // The sky is what the camera sees emitted there.
                for (int c = 0; c < 3; ++c) ASSERT_FLOAT_EQ(emission[i + c], scene.environment.color[c]);
                ASSERT_EQ(instance[i], -1.0f);
                ASSERT_EQ(material[i], -1.0f);
                ASSERT_EQ(alpha[i], 0.0f);
                continue;
            }
            ++hits;
            for (int c = 0; c < 3; ++c) {
                ASSERT_NEAR(shading[i + c], a.n[c], 1e-5);
                ASSERT_NEAR(geometric[i + c], a.n[c], 1e-5);
                ASSERT_NEAR(position[i + c], a.p[c], 1e-5 * 4.0);
                ASSERT_FLOAT_EQ(albedo[i + c], m.baseColor[c]);
                ASSERT_FLOAT_EQ(emission[i + c], emitted[c]);
                ASSERT_FLOAT_EQ(roughness[i + c], m.roughness);
                ASSERT_FLOAT_EQ(metallic[i + c], m.metallic);
                ASSERT_NEAR(depth[i + c], a.t, 1e-5 * a.t);
            }
            const double fromCentre = std::sqrt(std::pow(position[i] - test::kAovSphereCentre.x, 2) +
                                                std::pow(position[i + 1] - test::kAovSphereCentre.y, 2) +
                                                std::pow(position[i + 2] - test::kAovSphereCentre.z, 2));
            ASSERT_NEAR(fromCentre, test::kAovSphereRadius, 1e-5);
            const Vec2 expectedUv = sphereUv(Vec3(float(a.n[0]), float(a.n[1]), float(a.n[2])));
            if (expectedUv.x > 0.01f && expectedUv.x < 0.99f) {  // away from the seam, where u wraps
                ASSERT_NEAR(uv[i], expectedUv.x, 1e-4);
                ASSERT_NEAR(uv[i + 1], expectedUv.y, 1e-4);
            }
            ASSERT_EQ(uv[i + 2], 0.0f);
            ASSERT_EQ(instance[i], 0.0f);
            ASSERT_EQ(material[i], 0.0f);
            ASSERT_EQ(alpha[i], 1.0f);
            ASSERT_GT(cost[i], 0.0f) << "nodes visited";
            ASSERT_GT(cost[i + 1], 0.0f) << "primitives tested";
            ASSERT_EQ(cost[i], std::round(cost[i])) << "every sample traces the same ray";
        }
    }
    EXPECT_GT(hits, 300u);
    EXPECT_GT(misses, 100u);
}

// The camera segment passes an alpha-masked (here fully transparent) quad: the AOVs describe
// the sphere behind it, and bvh_cost counts both traversals.
TEST(Aov, TransparentSurfacesAreSeenThrough) {
    Scene scene = test::analyticSphereScene();
    Material glassPane = test::diffuse({1, 0, 0});
    glassPane.alphaMode = AlphaMode::Mask;
    glassPane.alpha = 0.0f;
    const uint32_t pane = addMaterial(scene, "pane", glassPane);
    addShape(scene, ObjectKind::Quad, trs({0, 0.5f, 3.0f}, {90, 0, 0}, {10, 1, 10}), pane, "pane");
    CpuBackend backend;
    renderWithAovs(backend, scene, 2, kAllAovs, noJitter());
    const std::vector<float> instance = readAov(backend, Aov::InstanceId),
                             depth = readAov(backend, Aov::Depth), albedo = readAov(backend, Aov::Albedo),
                             cost = readAov(backend, Aov::BvhCost);
    CpuBackend alone;
    renderWithAovs(alone, test::analyticSphereScene(), 2, kAllAovs, noJitter());
    const std::vector<float> costAlone = readAov(alone, Aov::BvhCost);
    uint32_t checked = 0;
    for (uint32_t y = 0; y < scene.render.height; ++y) {
        for (uint32_t x = 0; x < scene.render.width; ++x) {
            const test::AnalyticSphereHit a = test::analyticSphereHit(scene, x, y);
            const size_t i = (size_t(y) * scene.render.width + x) * 4;
            if (a.graze || !a.hit) continue;
            ++checked;
            ASSERT_EQ(instance[i], 0.0f) << "pixel " << x << ", " << y;
            // The ray goes on from an origin offset off the pane, a little off the camera's line.
            ASSERT_NEAR(depth[i], a.t, 1e-4 * a.t);
            ASSERT_FLOAT_EQ(albedo[i], 0.25f);
            ASSERT_GT(cost[i + 1], costAlone[i + 1]) << "the pane's traversal counts too";
        }
    }
    EXPECT_GT(checked, 300u);
}

TEST(Aov, VarianceIsZeroForAConstantAndMatchesADirectComputation) {
    Scene sky;
    sky.render = {8, 8, 4, 1, 0};
    sky.environment.color = {0.7f, 0.3f, 0.1f};
    CpuBackend constant;
    renderWithAovs(constant, sky, 64, aovBit(Aov::Variance));
    const std::vector<float> zero = readAov(constant, Aov::Variance);
    for (size_t i = 0; i < zero.size(); i += 4) ASSERT_EQ(zero[i], 0.0f) << "pixel " << i / 4;

    const Scene scene = test::noisyScene(16);
    const uint32_t spp = 32;
    CpuBackend backend;
    renderWithAovs(backend, scene, spp / 2, aovBit(Aov::Variance));
    backend.render(spp / 2);  // Welford's sums carry over between calls
    const std::vector<float> variance = readAov(backend, Aov::Variance);

    // The same samples, traced here: the variance of the mean of each pixel's luminance.
    const CompiledScene compiled = compileRenderScene(scene);
    RenderScene view = compiled.view();
    applyIntegratorToggles(IntegratorToggles{}, view.settings);
    uint32_t noisy = 0;
    for (uint32_t y = 0; y < 16; ++y) {
        for (uint32_t x = 0; x < 16; ++x) {
            double sum = 0.0, sumSq = 0.0;
            for (uint32_t s = 0; s < spp; ++s) {
                PathCounters counters;
                const double l = luminance(tracePath(view, x, y, s, counters));
                sum += l;
                sumSq += l * l;
            }
            const double mean = sum / spp, expected = (sumSq - spp * mean * mean) / (spp - 1.0) / spp;
            const size_t i = (size_t(y) * 16 + x) * 4;
            ASSERT_NEAR(variance[i], expected, 1e-6 * std::fmax(expected, 1e-6))
                << "pixel " << x << ", " << y;
            ASSERT_EQ(variance[i], variance[i + 1]);
            noisy += variance[i] > 0.0f;
        }
    }
    EXPECT_GT(noisy, 16u * 16u / 2u);
}

TEST(Aov, BeautyIsBitIdenticalWithAndWithoutAovs) {
    const Scene scene = test::noisyScene(24);
    CpuBackend plain, withAovs;
    renderWithAovs(plain, scene, 8, 0);
    renderWithAovs(withAovs, scene, 8, kAllAovs);
    std::vector<float> a, b;
    plain.readBeauty(a);
    withAovs.readBeauty(b);
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0);
    EXPECT_EQ(plain.stats().rays, withAovs.stats().rays);
}

TEST(Aov, OnlyEnabledAovsHaveMemory) {
    const Scene scene = test::analyticSphereScene(16, 8);
    const size_t pixels = 16 * 8;
    CpuBackend backend;
    renderWithAovs(backend, scene, 2, 0);
    EXPECT_EQ(backend.aovs(), 0u);
    EXPECT_EQ(backend.aovBytes(), 0u);
    std::vector<float> rgba;
    EXPECT_THROW(backend.readAov(Aov::Albedo, rgba), std::invalid_argument);

    backend.setAovs(aovBit(Aov::Albedo) | aovBit(Aov::SampleCount));
    EXPECT_EQ(backend.aovs(), 0u) << "applies from the next reset";
    EXPECT_THROW(backend.readAov(Aov::Albedo, rgba), std::invalid_argument);
    backend.resetAccumulation();
    EXPECT_EQ(backend.aovs(), aovBit(Aov::Albedo) | aovBit(Aov::SampleCount));
    backend.render(2);
    EXPECT_EQ(backend.aovBytes(), pixels * 3 * sizeof(double));
    EXPECT_NO_THROW(backend.readAov(Aov::Albedo, rgba));
    EXPECT_NO_THROW(backend.readAov(Aov::SampleCount, rgba));
    EXPECT_THROW(backend.readAov(Aov::Depth, rgba), std::invalid_argument);

    backend.setAovs(kAllAovs);
    backend.resetAccumulation();
    EXPECT_EQ(backend.aovBytes(), pixels * aovDoublesPerPixel(kAllAovs) * sizeof(double));
    backend.setAovs(0);
    backend.resetAccumulation();
    EXPECT_EQ(backend.aovBytes(), 0u);
}

}  // namespace
}  // namespace pt
