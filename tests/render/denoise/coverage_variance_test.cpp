// coverageFreeVariance against the variance computed directly from a silhouette pixel's
// samples: some on a surface, the rest on the sky.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "render/denoise/atrous_filter.h"

namespace pt {
namespace {

struct Pixel {
    float varianceOfMean = 0.0f;  // as the variance AOV gives it: M2 / ((n - 1) n)
    float alpha = 0.0f, surfaceLight = 0.0f, skyLight = 0.0f;
    float surfaceVarianceOfMean = 0.0f;  // the truth: the variance of alpha times the surface mean
};

// `hits` surface samples of luminance 0.3 +- 0.2 (uniform) and `misses` of sky `sky` +- `skySpread`.
Pixel pixelOf(uint32_t hits, uint32_t misses, float sky, float skySpread, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<double> all, surface;
    for (uint32_t k = 0; k < hits; ++k) surface.push_back(0.3 + 0.2 * u(rng));
    all = surface;
    double skySum = 0.0;
    for (uint32_t k = 0; k < misses; ++k) {
        all.push_back(sky + skySpread * u(rng));
        skySum += all.back();
    }
    const auto meanAndSquares = [](const std::vector<double>& v) {
        double mean = 0.0, m2 = 0.0;
        for (double x : v) mean += x / double(v.size());
        for (double x : v) m2 += (x - mean) * (x - mean);
        return std::pair<double, double>(mean, m2);
    };
    const double n = double(all.size()), k = double(hits);
    const double m2 = meanAndSquares(all).second;
    const auto [surfaceMean, surfaceM2] = meanAndSquares(surface);
    Pixel p;
    p.varianceOfMean = float(m2 / ((n - 1.0) * n));
    p.alpha = float(k / n);
    p.surfaceLight = float(surfaceMean * k / n);
    p.skyLight = float(skySum / n);
    p.surfaceVarianceOfMean = float((k / n) * (k / n) * surfaceM2 / ((k - 1.0) * k));
    return p;
}

float coverageFree(const Pixel& p, uint32_t samples) {
    return denoise::coverageFreeVariance(p.varianceOfMean, p.alpha, p.surfaceLight, p.skyLight, samples);
}

TEST(CoverageFreeVariance, UnderAUniformSkyIsTheVarianceOfTheSurfaceSamples) {
    for (const uint32_t hits : {3u, 8u, 40u}) {
        const Pixel p = pixelOf(hits, 64 - hits, 1.5f, 0.0f, hits);
        const float got = coverageFree(p, 64);
        EXPECT_NEAR(got, p.surfaceVarianceOfMean, 1e-3f * p.surfaceVarianceOfMean) << hits << " hits";
        // The coverage noise was most of the pixel's variance.
        EXPECT_LT(got, 0.2f * p.varianceOfMean) << hits << " hits";
    }
}

TEST(CoverageFreeVariance, UnderAVaryingSkyNeverFallsBelowTheSurfaceVariance) {
    for (uint32_t seed = 0; seed < 20; ++seed) {
        const Pixel p = pixelOf(10, 22, 1.5f, 0.5f, seed);
        EXPECT_GE(coverageFree(p, 32), p.surfaceVarianceOfMean * (1.0f - 1e-4f)) << "seed " << seed;
    }
}

TEST(CoverageFreeVariance, LeavesCoveredAndNearlyEmptyPixelsAlone) {
    const Pixel covered = pixelOf(16, 0, 0.0f, 0.0f, 1);
    EXPECT_EQ(coverageFree(covered, 16), covered.varianceOfMean);
    const Pixel oneHit = pixelOf(1, 15, 1.5f, 0.0f, 2);  // one surface sample: no spread to measure
    EXPECT_EQ(coverageFree(oneHit, 16), oneHit.varianceOfMean);
}

}  // namespace
}  // namespace pt
