// KHR_materials_anisotropy's GGX (ggx.h, GgxAlpha2; bsdf.h): the stretched distribution is
// normalised (its visible normals: ggx_test.cpp), equal alphas give the isotropic functions
// exactly, the lobe is wider along the frame's x, and the BSDF's sample weights are eval / pdf.
#include <gtest/gtest.h>

#include <cmath>

#include "chi_square.h"
#include "render/materials/bsdf.h"

namespace pt {
namespace {

using test::Pcg32;

// Projected area, the integral of D(m) cos(m) over the hemisphere, by importance sampling with
// the isotropic lobe of the larger alpha at normal incidence (density D_iso(m) m.z), whose
// tails cover the stretched lobe's.
double projectedArea(GgxAlpha2 alpha, int n, uint64_t seed) {
    Pcg32 rng(seed);
    double sum = 0.0;
    const float proposal = fmaxf(alpha.x, alpha.y);
    for (int i = 0; i < n; ++i) {
        const Vec3 m = sampleGgxVisibleNormal({0.0f, 0.0f, 1.0f}, proposal, {rng.uniform(), rng.uniform()});
        const double pdf = ggxD(m, proposal) * m.z;
        if (pdf > 0.0) sum += ggxD(m, alpha) * m.z / pdf;
    }
    return sum / n;
}

TEST(AnisotropicGgx, DistributionIsNormalised) {
    for (GgxAlpha2 alpha :
         {GgxAlpha2{0.5f, 0.5f}, GgxAlpha2{1.0f, 0.2f}, GgxAlpha2{0.3f, 0.05f}, GgxAlpha2{0.1f, 0.8f}})
        EXPECT_NEAR(projectedArea(alpha, 400000, 3), 1.0, 0.01) << alpha.x << " " << alpha.y;
}

TEST(AnisotropicGgx, EqualAlphasAreTheIsotropicFunctions) {
    Pcg32 rng(7);
    for (float alpha : {0.01f, 0.3f, 1.0f}) {
        const GgxAlpha2 both{alpha, alpha};
        for (int i = 0; i < 200; ++i) {
            const Vec3 wo =
                normalize(Vec3{rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() + 0.01f});
            const Vec2 u{rng.uniform(), rng.uniform()};
            const Vec3 m = sampleGgxVisibleNormal(wo, alpha, u), m2 = sampleGgxVisibleNormal(wo, both, u);
            EXPECT_NEAR(length(m - m2), 0.0f, 1e-5f);
            EXPECT_NEAR(ggxD(m, both) / ggxD(m, alpha), 1.0f, 1e-4f);
            EXPECT_NEAR(ggxMaskingTerm(wo, both), ggxMaskingTerm(wo, alpha), 1e-6f);
        }
    }
}

// Brushed metal: the highlight spreads along the brushing direction (x). At normal incidence,
// a direction tilted 20 degrees toward x reflects more than one tilted toward y, by far; a
// rotation by 180 degrees of the direction changes nothing (a direction, not an arrow).
TEST(AnisotropicGgx, TheHighlightStretchesAlongTheDirection) {
    BsdfParams brushed{{0.9f, 0.9f, 0.9f}, 1.0f, 0.0f, 1.5f};
    brushed.roughness = 0.3f;
    brushed.anisotropy = 0.8f;
    const Frame frame = Frame::fromNormal({0.0f, 0.0f, 1.0f});
    const Vec3 wo{0.0f, 0.0f, 1.0f};
    const float t = 20.0f * kPi / 180.0f;
    const Vec3 alongX{sinf(t), 0.0f, cosf(t)}, alongY{0.0f, sinf(t), cosf(t)};
    const float fx = evalBsdf(brushed, frame, wo, alongX).x, fy = evalBsdf(brushed, frame, wo, alongY).x;
    EXPECT_GT(fx, 5.0f * fy) << fx << " " << fy;
    const Frame turned{-frame.tangent, -frame.bitangent, frame.normal};
    EXPECT_NEAR(evalBsdf(brushed, turned, wo, alongX).x, fx, 1e-5f * fx);
    brushed.anisotropy = 0.0f;  // isotropic: the two agree
    EXPECT_NEAR(evalBsdf(brushed, frame, wo, alongX).x, evalBsdf(brushed, frame, wo, alongY).x, 1e-6f);
}

// Sample weights are eval / pdf and the pdf is pdfBsdf's, for anisotropic metal, plastic and
// rough glass (both sides), off the frame's axes.
TEST(AnisotropicGgx, BsdfSampleWeightIsEvalOverPdf) {
    Pcg32 rng(31);
    const Frame frame = Frame::fromNormal({0.0f, 0.0f, 1.0f});
    int checked = 0;
    for (float strength : {0.3f, 0.9f, 1.0f}) {
        for (float roughness : {0.0f, 0.2f, 0.7f}) {
            for (float transmission : {0.0f, 1.0f}) {
                BsdfParams p{{0.8f, 0.6f, 0.4f}, transmission > 0.0f ? 0.0f : 0.5f, transmission, 1.5f};
                p.roughness = roughness;
                p.anisotropy = strength;
                for (int i = 0; i < 300; ++i) {
                    const Vec3 wo = normalize(
                        Vec3{rng.uniform() - 0.5f, rng.uniform() - 0.5f,
                             (transmission > 0.0f && i % 2 ? -1.0f : 1.0f) * (rng.uniform() + 0.05f)});
                    const BsdfSample s =
                        sampleBsdf(p, frame, wo, rng.uniform(), {rng.uniform(), rng.uniform()});
                    if (s.delta || isBlack(s.weight)) continue;
                    ASSERT_FALSE(s.delta) << "a rough-in-one-direction lobe is not a mirror";
                    const float pdf = pdfBsdf(p, frame, wo, s.wi);
                    const Vec3 f = evalBsdf(p, frame, wo, s.wi);
                    ASSERT_GT(pdf, 0.0f);
                    EXPECT_NEAR(s.pdf / pdf, 1.0f, 1e-4f);
                    for (int c = 0; c < 3; ++c)
                        EXPECT_NEAR(s.weight[c], f[c] / pdf, 1e-4f * (1.0f + f[c] / pdf));
                    ++checked;
                }
            }
        }
    }
    EXPECT_GT(checked, 3000);
}

}  // namespace
}  // namespace pt
