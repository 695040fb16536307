// Free-flight sampling with spectral MIS (free_flight.h): in every channel, the mean weight of
// flights that reach the surface is the transmittance exp(-sigma_t d), and the mean weight of
// scattering events is what the medium scatters, sigma_s / sigma_t (1 - exp(-sigma_t d)); for
// grey and coloured media, extinctions 1e4 apart, a black channel, and a coloured throughput.
#include "render/integrator/free_flight.h"

#include <gtest/gtest.h>

#include <cmath>

#include "render/materials/chi_square.h"

namespace pt {
namespace {

struct Medium {
    const char* name;
    Vec3 sigmaT, sigmaS;
};

TEST(FreeFlight, EveryChannelIsUnbiasedForScatteringAndPassing) {
    const Medium media[] = {
        {"grey", Vec3(1.0f), Vec3(0.8f)},
        {"skin-like", {0.8f, 2.0f, 4.0f}, {0.75f, 1.6f, 2.4f}},
        {"stiff", {1e-2f, 1.0f, 1e2f}, {1e-2f, 0.5f, 99.0f}},
        {"absorbing", {1.0f, 1.0f, 1.0f}, {0.0f, 0.0f, 0.0f}},
        {"clear red", {0.0f, 1.0f, 2.0f}, {0.0f, 0.9f, 1.0f}},
    };
    test::Pcg32 rng(12);
    for (const Medium& m : media) {
        for (const Vec3 throughput : {Vec3(1.0f), Vec3{1.0f, 0.2f, 0.05f}}) {
            for (const float depth : {0.1f, 1.0f, 5.0f}) {
                const int n = 400000;
                double passed[3] = {0, 0, 0}, passed2[3] = {0, 0, 0}, scattered[3] = {0, 0, 0},
                       scattered2[3] = {0, 0, 0};
                for (int i = 0; i < n; ++i) {
                    const FreeFlight f =
                        sampleFreeFlight(m.sigmaT, m.sigmaS, throughput, depth, rng.uniform(), rng.uniform());
                    ASSERT_TRUE(isFinite(f.weight)) << m.name;
                    ASSERT_LE(f.distance, depth);
                    for (int c = 0; c < 3; ++c) {
                        double* sum = f.scattered ? scattered : passed;
                        double* sum2 = f.scattered ? scattered2 : passed2;
                        sum[c] += f.weight[c];
                        sum2[c] += double(f.weight[c]) * f.weight[c];
                    }
                }
                for (int c = 0; c < 3; ++c) {
                    const double st = m.sigmaT[c], ss = m.sigmaS[c];
                    const double expectPassed = std::exp(-st * depth);
                    const double expectScattered = st > 0.0 ? ss / st * (1.0 - std::exp(-st * depth)) : 0.0;
                    const double mp = passed[c] / n, ms = scattered[c] / n;
                    const double sep = std::sqrt(std::max(0.0, passed2[c] / n - mp * mp) / n);
                    const double ses = std::sqrt(std::max(0.0, scattered2[c] / n - ms * ms) / n);
                    EXPECT_NEAR(mp, expectPassed, 5.0 * sep + 1e-4)
                        << m.name << " channel " << c << " depth " << depth << " throughput " << throughput.y;
                    EXPECT_NEAR(ms, expectScattered, 5.0 * ses + 1e-4)
                        << m.name << " channel " << c << " depth " << depth << " throughput " << throughput.y;
                }
            }
        }
    }
}

// With no surface ahead (tMax infinite) a scattering medium always scatters, and a channel
// that does not attenuate passes to infinity: the weights stay finite.
TEST(FreeFlight, AnInfiniteMediumScattersAndAClearChannelEscapes) {
    test::Pcg32 rng(3);
    for (int i = 0; i < 10000; ++i) {
        const FreeFlight grey =
            sampleFreeFlight(Vec3(2.0f), Vec3(1.0f), Vec3(1.0f), kInf, rng.uniform(), rng.uniform());
        ASSERT_TRUE(grey.scattered);
        ASSERT_TRUE(isFinite(grey.weight));
        const FreeFlight clear = sampleFreeFlight({0.0f, 1.0f, 1.0f}, {0.0f, 1.0f, 1.0f}, Vec3(1.0f), kInf,
                                                  rng.uniform(), rng.uniform());
        ASSERT_TRUE(isFinite(clear.weight));
    }
    // The channel probabilities follow throughput x albedo, uniform where that is black.
    const Vec3 p = freeFlightChannelProbabilities({1, 1, 1}, {0.5f, 0.25f, 0.25f}, {1, 2, 0});
    EXPECT_NEAR(p.x, 0.5f, 1e-6f);
    EXPECT_NEAR(p.y, 0.5f, 1e-6f);
    EXPECT_EQ(p.z, 0.0f);
    const Vec3 uniform = freeFlightChannelProbabilities({1, 1, 1}, Vec3(0.0f), Vec3(1.0f));
    EXPECT_NEAR(uniform.x, 1.0f / 3.0f, 1e-6f);
}

}  // namespace
}  // namespace pt
