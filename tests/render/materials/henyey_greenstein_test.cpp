// The Henyey-Greenstein phase function (henyey_greenstein.h): normalised, mean cosine g, and its
// sampling follows its density by chi-square, from forward to backward lobes and stiff g.
#include "render/materials/henyey_greenstein.h"

#include <gtest/gtest.h>

#include <cmath>

#include "chi_square.h"

namespace pt {
namespace {

using namespace test;

constexpr float kG[] = {-0.99f, -0.9f, -0.3f, 0.0f, 0.3f, 0.9f, 0.99f};

// Integrals over the sphere by the cosine (the phase function is symmetric about the axis).
double integrateOverCosine(float g, int power) {
    const int n = 2000000;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const double c = -1.0 + (i + 0.5) * 2.0 / n;
        sum += henyeyGreenstein(float(c), g) * std::pow(c, power);
    }
    return sum * 2.0 / n * 2.0 * kPiD;
}

TEST(HenyeyGreenstein, IsNormalisedWithMeanCosineG) {
    for (float g : kG) {
        const double tolerance = std::fabs(g) > 0.95f ? 3e-3 : 1e-4;  // the peak is steep there
        EXPECT_NEAR(integrateOverCosine(g, 0), 1.0, tolerance) << g;
        EXPECT_NEAR(integrateOverCosine(g, 1), g, tolerance) << g;
    }
}

TEST(HenyeyGreenstein, SampledCosinesCoverTheRangeInOrder) {
    for (float g : kG) {
        EXPECT_NEAR(sampleHenyeyGreensteinCosine(g, 0.0f), -1.0f, 1e-4f) << g;
        EXPECT_NEAR(sampleHenyeyGreensteinCosine(g, 0.99999994f), 1.0f, 1e-3f) << g;
        float last = -2.0f;
        for (int i = 0; i < 1000; ++i) {
            const float c = sampleHenyeyGreensteinCosine(g, (i + 0.5f) / 1000.0f);
            EXPECT_GE(c, last) << g;  // an inverse CDF is monotone
            last = c;
        }
    }
}

// Chi-square of sampled directions against the density, with the light travelling along +z
// (forward lobes up, backward ones down) and along a tilted direction.
TEST(HenyeyGreenstein, SamplesFollowTheDensity) {
    const int cases = int(std::size(kG)) * 2;
    const double level = sidakLevel(0.01, cases);
    int index = 0;
    for (float g : kG) {
        for (const Vec3 travelling : {Vec3{0.0f, 0.0f, 1.0f}, normalize(Vec3{0.3f, -0.5f, 0.8f})}) {
            const double width = std::max(1.0 - std::fabs(double(g)), 0.005);
            const LobeHistogram h(toDouble(travelling), width, toDouble(-travelling), width);
            const DirectionSampler sample = [&](Pcg32& rng, Vec3& wi) {
                wi = sampleHenyeyGreenstein(travelling, g, {rng.uniform(), rng.uniform()}).direction;
                return true;
            };
            const DirectionPdf pdf = [&](Vec3 wi) {
                return double(henyeyGreenstein(dot(travelling, wi), g));
            };
            const ChiSquareResult r = runChiSquare(h, sample, pdf, 1000000, 500u + uint64_t(index++));
            EXPECT_TRUE(r.failure.empty()) << g << ": " << r.failure;
            EXPECT_GE(r.pValue, level) << "g " << g << ": chi2 " << r.chi2 << " dof " << r.dof;
            EXPECT_NEAR(r.pdfIntegral, 1.0, 3e-3) << g;
            std::printf("g %+.2f along (%.2f, %.2f, %.2f): p %.4f\n", double(g), double(travelling.x),
                        double(travelling.y), double(travelling.z), r.pValue);
        }
    }
}

// The same test rejects samples of g against the density of g + 0.05: it can fail.
TEST(HenyeyGreenstein, RejectsADensityOfAnotherG) {
    for (float g : {-0.5f, 0.0f, 0.5f}) {
        const Vec3 travelling{0.0f, 0.0f, 1.0f};
        const LobeHistogram h(toDouble(travelling), 0.5, toDouble(-travelling), 0.5);
        const DirectionSampler sample = [&](Pcg32& rng, Vec3& wi) {
            wi = sampleHenyeyGreenstein(travelling, g, {rng.uniform(), rng.uniform()}).direction;
            return true;
        };
        const DirectionPdf wrong = [&](Vec3 wi) { return double(henyeyGreenstein(wi.z, g + 0.05f)); };
        EXPECT_LT(runChiSquare(h, sample, wrong, 1000000, 7).pValue, 1e-6) << g;
    }
}

// The weight of a sample is 1: its pdf is the phase function's value in its direction.
TEST(HenyeyGreenstein, SamplePdfIsThePhaseFunction) {
    Pcg32 rng(4);
    for (float g : kG) {
        const Vec3 travelling =
            normalize(Vec3{rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f});
        for (int i = 0; i < 200; ++i) {
            const PhaseSample s = sampleHenyeyGreenstein(travelling, g, {rng.uniform(), rng.uniform()});
            EXPECT_NEAR(length(s.direction), 1.0f, 1e-5f);
            const float expected = henyeyGreenstein(dot(travelling, s.direction), g);
            EXPECT_NEAR(s.pdf / expected, 1.0f, std::fabs(g) > 0.95f ? 2e-2f : 2e-3f) << g;
        }
    }
}

}  // namespace
}  // namespace pt
