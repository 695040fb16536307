// Environment importance sampling: the distribution follows luminance x sin(theta), sampled
// directions follow the density the integrator evaluates for MIS (chi-square), and the
// density integrates to one over the sphere.
#include "render/lights/environment_sampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "render/compile/compile_scene.h"
#include "render/lights/environment_distribution.h"
#include "support/scene_builder.h"

namespace pt {
namespace {

using test::addFloatTexture;
using test::addMaterial;
using test::addShape;
using test::diffuse;
using test::trs;

// A sky of `width` x `height` texels from `texel`, around a small sphere.
template <class TexelFn>
Scene skyScene(uint32_t width, uint32_t height, TexelFn texel, bool nearest, float rotationDegrees = 0.0f) {
    Scene scene;
    addShape(scene, ObjectKind::Sphere, trs({0, 0, 0}), addMaterial(scene, "s", diffuse({0.5f, 0.5f, 0.5f})));
    scene.environment.texture = addFloatTexture(scene, width, height, texel);
    scene.textures.back().nearest = nearest;
    scene.environment.rotationDegrees = rotationDegrees;
    return scene;
}

Vec4 patchySky(uint32_t x, uint32_t y) {
    const float l = 0.1f + float((x * 7 + y * 13) % 5) + (x == 20 && y == 5 ? 500.0f : 0.0f);
    return {l, 0.5f * l, 2.0f * l, 1.0f};
}

TEST(EnvironmentSampling, CellDensityIsLuminanceTimesSinTheta) {
    const uint32_t w = 32, h = 16;
    const Scene scene = skyScene(w, h, patchySky, true);
    const EnvironmentDistribution d = buildEnvironmentDistribution(scene.textures[0]);
    ASSERT_EQ(d.width, w);
    ASSERT_EQ(d.height, h);
    double total = 0.0;
    for (uint32_t y = 0; y < h; ++y) {
        for (uint32_t x = 0; x < w; ++x) {
            const Vec4 c = patchySky(x, y);
            total += luminance(c.xyz()) * std::sin(kPi * (y + 0.5) / h);
        }
    }
    const double mean = total / (w * h);
    for (uint32_t y = 0; y < h; ++y) {
        for (uint32_t x = 0; x < w; ++x) {
            const double expected = luminance(patchySky(x, y).xyz()) * std::sin(kPi * (y + 0.5) / h) / mean;
            ASSERT_NEAR(d.pdf[y * w + x], expected, 1e-4 * expected) << x << ", " << y;
        }
    }
}

// Bilinear filtering spreads each texel over its neighbours' cells: a single bright texel in
// a black image must give its eight neighbours probability too, or light would be missed.
TEST(EnvironmentSampling, BilinearLookupNeverFallsOnAZeroProbabilityCell) {
    const Scene scene = skyScene(
        16, 8,
        [](uint32_t x, uint32_t y) {
            return x == 5 && y == 3 ? Vec4{1, 1, 1, 1} : Vec4{0, 0, 0, 1};
        },
        false);
    const EnvironmentDistribution d = buildEnvironmentDistribution(scene.textures[0]);
    ASSERT_EQ(d.width, 16u);
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) EXPECT_GT(d.pdf[(3 + dy) * 16 + 5 + dx], 0.0f) << dx << ", " << dy;
    }
    EXPECT_EQ(d.pdf[3 * 16 + 8], 0.0f);
    const Scene black = skyScene(
        4, 2,
        [](uint32_t, uint32_t) {
            return Vec4{0, 0, 0, 1};
        },
        false);
    EXPECT_EQ(buildEnvironmentDistribution(black.textures[0]).width, 0u) << "nothing to sample";
}

// Chi-square goodness of fit: directions drawn by sampleEnvironmentDirection() against the
// density environmentDirectionPdf() reports, binned on a (phi, cos theta) grid, so the
// test checks sampling and evaluation against each other, including rotation.
TEST(EnvironmentSampling, SampledDirectionsFollowTheEvaluatedDensity) {
    const Scene scene = skyScene(32, 16, patchySky, false, 30.0f);
    const CompiledScene compiled = compileRenderScene(scene);
    const RenderScene view = compiled.view();
    ASSERT_TRUE(environmentIsImportanceSampled(view));

    constexpr int kPhiBins = 24, kCosBins = 12;
    auto bin = [](Vec3 d) {
        const float phi = std::atan2(d.z, d.x) + kPi;
        const int i = std::min(int(phi / (2 * kPi) * kPhiBins), kPhiBins - 1);
        const int j = std::min(int((d.y + 1.0f) * 0.5f * kCosBins), kCosBins - 1);
        return j * kPhiBins + i;
    };
    // Expected probability per bin: integrate the density on a fine grid in (phi, cos theta),
    // where the solid-angle measure is uniform.
    std::vector<double> expected(kPhiBins * kCosBins, 0.0);
    constexpr int kFine = 60;
    double integral = 0.0;
    for (int j = 0; j < kCosBins * kFine; ++j) {
        const double y = -1.0 + 2.0 * (j + 0.5) / (kCosBins * kFine);
        for (int i = 0; i < kPhiBins * kFine; ++i) {
            const double phi = 2 * kPi * (i + 0.5) / (kPhiBins * kFine) - kPi;
            const double r = std::sqrt(1 - y * y);
            const Vec3 d{float(r * std::cos(phi)), float(y), float(r * std::sin(phi))};
            const double p =
                environmentDirectionPdf(view, d) * (4 * kPi) / (double(kCosBins * kFine) * kPhiBins * kFine);
            expected[size_t(bin(d))] += p;
            integral += p;
        }
    }
    EXPECT_NEAR(integral, 1.0, 2e-3) << "the density integrates to one over the sphere";

    constexpr int kSamples = 200000;
    std::vector<double> observed(expected.size(), 0.0);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    int disagreements = 0;
    for (int s = 0; s < kSamples; ++s) {
        Vec3 d;
        float pdf;
        ASSERT_TRUE(sampleEnvironmentDirection(view, {uniform(rng), uniform(rng)}, d, pdf));
        ASSERT_NEAR(length(d), 1.0f, 1e-5f);
        // Sampled and evaluated densities agree, except where rounding moves a direction
        // within an ulp of a cell edge into the neighbouring cell.
        const float evaluated = environmentDirectionPdf(view, d);
        disagreements += std::fabs(pdf - evaluated) > 2e-3f * evaluated + 1e-6f;
        observed[size_t(bin(d))] += 1.0;
    }
    EXPECT_LT(disagreements, kSamples / 2000);
    double chi2 = 0.0;
    int dof = -1;
    double pooledObserved = 0.0, pooledExpected = 0.0;
    for (size_t b = 0; b < expected.size(); ++b) {
        const double e = expected[b] * kSamples;
        if (e < 5.0) {  // pool sparse bins, as usual for chi-square
            pooledObserved += observed[b];
            pooledExpected += e;
            continue;
        }
        chi2 += (observed[b] - e) * (observed[b] - e) / e;
        ++dof;
    }
    if (pooledExpected > 5.0) {
        chi2 += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
        ++dof;
    }
    // Wilson-Hilferty: the 1e-4 upper quantile of chi-square with `dof` degrees of freedom.
    const double k = dof, z = 3.719;
    const double threshold = k * std::pow(1 - 2 / (9 * k) + z * std::sqrt(2 / (9 * k)), 3);
    EXPECT_LT(chi2, threshold) << "dof " << dof;
}

// Estimating the irradiance of the upper hemisphere by importance sampling gives the value a
// brute-force quadrature of the same radiance gives: the density is normalised and matches.
TEST(EnvironmentSampling, ImportanceSampledIntegralMatchesQuadrature) {
    const Scene scene = skyScene(32, 16, patchySky, false);
    const CompiledScene compiled = compileRenderScene(scene);
    const RenderScene view = compiled.view();
    double quadrature = 0.0;
    constexpr int kN = 1000;
    for (int j = 0; j < kN; ++j) {
        const double y = (j + 0.5) / kN;  // cos theta over the upper hemisphere
        for (int i = 0; i < 2 * kN; ++i) {
            const double phi = 2 * kPi * (i + 0.5) / (2 * kN);
            const double r = std::sqrt(1 - y * y);
            const Vec3 d{float(r * std::cos(phi)), float(y), float(r * std::sin(phi))};
            quadrature += luminance(environmentRadiance(view, d)) * y * (2 * kPi / (2 * kN)) / kN;
        }
    }
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    double estimate = 0.0;
    constexpr int kSamples = 400000;
    for (int s = 0; s < kSamples; ++s) {
        Vec3 d;
        float pdf;
        if (!sampleEnvironmentDirection(view, {uniform(rng), uniform(rng)}, d, pdf) || d.y <= 0.0f) continue;
        estimate += luminance(environmentRadiance(view, d)) * d.y / pdf;
    }
    estimate /= kSamples;
    EXPECT_NEAR(estimate / quadrature, 1.0, 0.01) << estimate << " vs " << quadrature;
}

}  // namespace
}  // namespace pt
