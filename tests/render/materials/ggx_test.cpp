// The GGX distribution (ggx.h): normalisation of D and of the visible normals, masking bounds,
// and robust sampling at extreme angles and roughness.
#include "render/materials/ggx.h"

#include <gtest/gtest.h>

#include <cmath>

#include "chi_square.h"

namespace pt {
namespace {

// Projected area of the microfacets: integral of D(m) cos(m) over the hemisphere = 1. The
// substitution tan(theta) = alpha tan(u) spreads even a very narrow peak over u in [0, pi/2).
double projectedArea(float alpha) {
    const int n = 200000;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const double u = (i + 0.5) / n * (kPi / 2.0);
        const double tanTheta = alpha * std::tan(u);
        const double theta = std::atan(tanTheta);
        const double dThetaDu = alpha / (std::cos(u) * std::cos(u)) / (1.0 + tanTheta * tanTheta);
        const Vec3 m{float(std::sin(theta)), 0.0f, float(std::cos(theta))};
        sum += ggxD(m, alpha) * std::cos(theta) * std::sin(theta) * 2.0 * kPi * dThetaDu;
    }
    return sum * (kPi / 2.0) / n;
}

TEST(Ggx, DistributionIsNormalised) {
    for (float alpha : {1e-3f, 0.01f, 0.1f, 0.5f, 1.0f})
        EXPECT_NEAR(projectedArea(alpha), 1.0, 2e-4) << alpha;
}

// The visible normals of any view integrate to 1 (Heitz 2014, eq. 18): Monte Carlo over
// cosine-distributed normals, E[pdf(m) / (m.z / pi)]. `alpha` is a float or a GgxAlpha2.
template <class Alpha>
double visibleNormalIntegral(Vec3 wo, Alpha alpha, test::Pcg32& rng) {
    const int n = 400000;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const float r = sqrtf(rng.uniform()), phi = 2.0f * kPi * rng.uniform();
        const Vec3 m{r * cosf(phi), r * sinf(phi), sqrtf(fmaxf(0.0f, 1.0f - r * r))};
        if (m.z <= 0.0f) continue;
        sum += ggxVisibleNormalPdf(wo, m, alpha) / (m.z * kInvPi);
    }
    return sum / n;
}

TEST(Ggx, VisibleNormalsAreNormalised) {
    test::Pcg32 rng(9);
    for (float alpha : {0.2f, 0.5f, 1.0f}) {
        for (float cosTheta : {1.0f, 0.5f, 0.05f}) {
            const Vec3 wo{sqrtf(1.0f - cosTheta * cosTheta), 0.0f, cosTheta};
            EXPECT_NEAR(visibleNormalIntegral(wo, alpha, rng), 1.0, 0.02) << alpha << " " << cosTheta;
        }
    }
}

// KHR_materials_anisotropy's stretched lobe, seen off its axes.
TEST(Ggx, AnisotropicVisibleNormalsAreNormalised) {
    test::Pcg32 rng(5);
    for (GgxAlpha2 alpha : {GgxAlpha2{0.8f, 0.2f}, GgxAlpha2{0.2f, 0.6f}}) {
        for (float cosTheta : {1.0f, 0.5f, 0.1f}) {
            const float s = sqrtf(1.0f - cosTheta * cosTheta);
            const Vec3 wo{s * 0.6f, s * 0.8f, cosTheta};
            EXPECT_NEAR(visibleNormalIntegral(wo, alpha, rng), 1.0, 0.03)
                << alpha.x << " " << alpha.y << " " << cosTheta;
        }
    }
}

TEST(Ggx, MaskingIsBoundedAndHeightCorrelated) {
    test::Pcg32 rng(4);
    for (float alpha : {1e-3f, 0.1f, 1.0f}) {
        for (int i = 0; i < 1000; ++i) {
            const float z1 = fmaxf(rng.uniform(), 1e-6f), z2 = fmaxf(rng.uniform(), 1e-6f);
            const Vec3 a{sqrtf(1.0f - z1 * z1), 0.0f, z1}, b{0.0f, sqrtf(1.0f - z2 * z2), z2};
            const float g1a = 2.0f * a.z / (a.z + ggxMaskingTerm(a, alpha));
            const float g1b = 2.0f * b.z / (b.z + ggxMaskingTerm(b, alpha));
            const float g2 = ggxG2(a, b, alpha);
            EXPECT_LE(g2, fminf(g1a, g1b) * (1.0f + 1e-6f));
            EXPECT_GE(g2, g1a * g1b * (1.0f - 1e-5f));  // correlation only increases visibility
        }
    }
}

TEST(Ggx, VisibleNormalSamplingIsRobust) {
    test::Pcg32 rng(8);
    for (float alpha : {1e-8f, 1e-3f, 0.5f, 1.0f}) {
        for (float cosTheta : {1.0f, 0.3f, 1e-6f, 0.0f}) {
            const Vec3 wo{sqrtf(1.0f - cosTheta * cosTheta), 0.0f, cosTheta};
            for (int i = 0; i < 1000; ++i) {
                const Vec3 m = sampleGgxVisibleNormal(wo, alpha, {rng.uniform(), rng.uniform()});
                ASSERT_TRUE(isFinite(m));
                ASSERT_NEAR(length(m), 1.0f, 1e-5f);
                ASSERT_GE(m.z, 0.0f);
                ASSERT_GE(dot(wo, m), -1e-6f);
            }
        }
    }
}

}  // namespace
}  // namespace pt
