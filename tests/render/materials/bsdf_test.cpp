#include "render/materials/bsdf.h"

#include <gtest/gtest.h>

#include "render/sampling/sampler.h"

namespace pt {
namespace {

Vec3 directionAt(float cosTheta) { return {sqrtf(1.0f - cosTheta * cosTheta), 0.0f, cosTheta}; }

TEST(Fresnel, DielectricMatchesKnownValues) {
    EXPECT_NEAR(fresnelDielectric(1.0f, 1.5f), 0.04f, 1e-6f);     // ((1.5-1)/(1.5+1))^2
    EXPECT_NEAR(fresnelDielectric(0.3f, 1.0f), 0.0f, 1e-7f);       // index-matched: no interface
    EXPECT_FLOAT_EQ(fresnelDielectric(0.1f, 1.0f / 1.5f), 1.0f);   // total internal reflection
    EXPECT_NEAR(fresnelDielectric(1e-6f, 1.5f), 1.0f, 1e-4f);      // grazing
    EXPECT_NEAR(fresnelDielectric(1.0f, 4.0f), 0.36f, 1e-6f);
}

TEST(Bsdf, LambertianSampleWeightIsTheAlbedoAndMatchesEvalOverPdf) {
    const BsdfParams p{{0.5f, 0.25f, 1.0f}, 0.0f, 0.0f, 1.5f};
    const Frame frame = Frame::fromNormal({0, 0, 1});
    const Vec3 wo = directionAt(0.6f);
    for (uint32_t i = 0; i < 256; ++i) {
        const BsdfSample s = sampleBsdf(p, frame, wo, sampleDimension(0, i, 0, 0),
                                        {sampleDimension(0, i, 1, 0), sampleDimension(0, i, 2, 0)});
        ASSERT_FALSE(s.delta);
        ASSERT_GT(s.pdf, 0.0f);
        const Vec3 expected = evalBsdf(p, frame, wo, s.wi) / pdfBsdf(p, frame, wo, s.wi);
        EXPECT_NEAR(s.weight.x, expected.x, 1e-5f);
        EXPECT_NEAR(s.weight.y, expected.y, 1e-5f);
        EXPECT_NEAR(s.weight.z, expected.z, 1e-5f);
        EXPECT_FLOAT_EQ(s.weight.x, 0.5f);
    }
}

// A white smooth dielectric loses no energy: reflection and refraction probabilities sum to 1
// and each weight is 1 (refraction's 1/eta^2 is radiance compression, undone on exit).
TEST(Bsdf, SmoothGlassSplitsByFresnelAndConservesEnergy) {
    for (float ior : {1.0f, 1.0001f, 1.5f, 2.42f, 4.0f}) {
        for (float cosTheta : {1.0f, 0.7f, 0.2f, 1e-3f}) {
            const BsdfParams p{{1, 1, 1}, 0.0f, 1.0f, ior};
            const Frame frame = Frame::fromNormal({0, 0, 1});
            const Vec3 wo = directionAt(cosTheta);
            const int kN = 20000;
            int reflected = 0;
            double transmittedEnergy = 0;
            for (int i = 0; i < kN; ++i) {
                const BsdfSample s = sampleBsdf(p, frame, wo, 0.0f, {(float(i) + 0.5f) / kN, 0.5f});
                ASSERT_TRUE(s.delta);
                ASSERT_TRUE(isFinite(s.weight));
                ASSERT_NEAR(length(s.wi), 1.0f, 1e-5f);
                if (s.transmitted) {
                    EXPECT_LT(s.wi.z, 0.0f);
                    transmittedEnergy += s.weight.x * ior * ior;
                } else {
                    EXPECT_NEAR(s.wi.z, cosTheta, 1e-5f);
                    ++reflected;
                }
            }
            const float fresnel = fresnelDielectric(cosTheta, ior);
            EXPECT_NEAR(double(reflected) / kN, fresnel, 2e-4) << "ior " << ior << " cos " << cosTheta;
            EXPECT_NEAR((reflected + transmittedEnergy) / kN, 1.0, 1e-4);
        }
    }
}

TEST(Bsdf, IndexMatchedGlassPassesStraightThrough) {
    const BsdfParams p{{1, 1, 1}, 0.0f, 1.0f, 1.0f};
    const Frame frame = Frame::fromNormal(normalize(Vec3{0.3f, -0.2f, 0.9f}));
    const Vec3 wo = normalize(Vec3{0.5f, 0.1f, 0.7f});
    const BsdfSample s = sampleBsdf(p, frame, wo, 0.0f, {0.5f, 0.5f});
    EXPECT_TRUE(s.transmitted);
    EXPECT_NEAR(s.wi.x, -wo.x, 1e-5f);
    EXPECT_NEAR(s.wi.y, -wo.y, 1e-5f);
    EXPECT_NEAR(s.wi.z, -wo.z, 1e-5f);
}

TEST(Bsdf, GlassInsideTotallyReflectsBeyondTheCriticalAngle) {
    const BsdfParams p{{1, 1, 1}, 0.0f, 1.0f, 1.5f};
    const Frame frame = Frame::fromNormal({0, 0, 1});
    const Vec3 wo = {0.9f, 0.0f, -sqrtf(1.0f - 0.81f)};  // inside, 64 degrees from the normal
    for (float u : {0.0f, 0.5f, 0.999f}) {
        const BsdfSample s = sampleBsdf(p, frame, wo, 0.0f, {u, 0.5f});
        EXPECT_FALSE(s.transmitted);
        EXPECT_LT(s.wi.z, 0.0f);  // stays inside
    }
}

TEST(Bsdf, MirrorFollowsSchlickAndLobesMixByMetallic) {
    const BsdfParams mirror{{0.9f, 0.6f, 0.3f}, 1.0f, 0.0f, 1.5f};
    const Frame frame = Frame::fromNormal({0, 0, 1});
    const BsdfSample s = sampleBsdf(mirror, frame, directionAt(1.0f), 0.3f, {0.5f, 0.5f});
    EXPECT_TRUE(s.delta);
    EXPECT_NEAR(s.weight.x, 0.9f, 1e-6f);
    EXPECT_NEAR(s.weight.z, 0.3f, 1e-6f);
    EXPECT_FALSE(hasNonDeltaLobes(mirror));
    const LobeWeights w = lobeWeights({{1, 1, 1}, 0.25f, 0.5f, 1.5f});
    EXPECT_FLOAT_EQ(w.diffuse + w.mirror + w.glass, 1.0f);
    EXPECT_FLOAT_EQ(w.glass, 0.375f);
}

}  // namespace
}  // namespace pt
