// The denoiser on images whose truth is known: flat, edged, poisoned with NaN, and a smooth
// textured image with noise of a known variance, at the noise of a few samples and of thousands.
#include "render/denoise/denoiser.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>
#include <vector>

#include "render/util/image_error.h"

namespace pt {
namespace {

// A test image: the mean beauty, its guides and the variance of each pixel's mean luminance,
// all RGBA as the backends give them.
struct Frame {
    uint32_t width, height, samples = 64;
    std::vector<float> beauty, albedo, normal, depth, emission, alpha, variance;

    Frame(uint32_t w, uint32_t h)
        : width(w),
          height(h),
          beauty(4 * w * h, 1.0f),
          albedo(4 * w * h, 1.0f),
          normal(4 * w * h, 0.0f),
          depth(4 * w * h, 5.0f),
          emission(4 * w * h, 0.0f),
          alpha(4 * w * h, 1.0f),
          variance(4 * w * h, 0.0f) {
        for (size_t i = 0; i < size_t(w) * h; ++i) normal[4 * i + 2] = 1.0f;  // a wall facing the camera
    }
    // Calls perPixel(x, y) for every pixel, row by row.
    template <class PerPixel>
    void forEachPixel(const PerPixel& perPixel) const {
        for (uint32_t y = 0; y < height; ++y) {
            for (uint32_t x = 0; x < width; ++x) perPixel(x, y);
        }
    }
    void set(std::vector<float>& plane, uint32_t x, uint32_t y, Vec3 v) const {
        float* p = &plane[4 * (size_t(y) * width + x)];
        p[0] = v.x;
        p[1] = v.y;
        p[2] = v.z;
        p[3] = 1.0f;
    }
    Vec3 at(const std::vector<float>& plane, uint32_t x, uint32_t y) const {
        const float* p = &plane[4 * (size_t(y) * width + x)];
        return {p[0], p[1], p[2]};
    }
    DenoiseInput input() const {
        DenoiseInput in;
        in.samples = samples;
        in.beauty = beauty.data();
        in.varianceOfMean = variance.data();
        in.guides = {width,        height,          albedo.data(), normal.data(),
                     depth.data(), emission.data(), alpha.data()};
        return in;
    }
    std::vector<float> denoised() const {
        std::vector<float> out;
        denoiseOnCpu(input(), out);
        return out;
    }
};

TEST(Denoiser, AFlatNoiseFreeImagePassesUnchanged) {
    Frame f(40, 30);
    for (uint32_t y = 0; y < f.height; ++y) {
        for (uint32_t x = 0; x < f.width; ++x) {
            f.set(f.albedo, x, y, {0.7f, 0.5f, 0.3f});
            f.set(f.beauty, x, y, {0.35f, 0.25f, 0.15f});
        }
    }
    const std::vector<float> out = f.denoised();
    for (size_t i = 0; i < out.size(); ++i) EXPECT_NEAR(out[i], i % 4 == 3 ? 1.0f : f.beauty[i], 1e-6f) << i;
}

// Two albedos meet at x = 20 on one lit wall, with noise at both: the profile across the edge
// keeps its step (remodulation puts each side's albedo back), and each side's colour is its own.
TEST(Denoiser, AnEdgeBetweenTwoAlbedosStaysAnEdge) {
    Frame f(40, 16);
    f.samples = 4;
    std::mt19937 rng(1);
    std::normal_distribution<float> noise(0.0f, 0.05f);
    const Vec3 left(0.8f, 0.2f, 0.2f), right(0.2f, 0.2f, 0.8f);
    for (uint32_t y = 0; y < f.height; ++y) {
        for (uint32_t x = 0; x < f.width; ++x) {
            const Vec3 a = x < 20 ? left : right;
            f.set(f.albedo, x, y, a);
            f.set(f.beauty, x, y, a * (0.5f + noise(rng)));
            f.set(f.variance, x, y, Vec3(0.05f * 0.05f * 0.25f));
        }
    }
    const std::vector<float> out = f.denoised();
    for (uint32_t y = 0; y < f.height; ++y) {
        const Vec3 l = f.at(out, 19, y), r = f.at(out, 20, y);
        EXPECT_NEAR(l.x, 0.4f, 0.04f) << "row " << y;
        EXPECT_NEAR(l.z, 0.1f, 0.02f) << "row " << y;
        EXPECT_NEAR(r.x, 0.1f, 0.02f) << "row " << y;
        EXPECT_NEAR(r.z, 0.4f, 0.04f) << "row " << y;
    }
}

// Stripes of blue albedo on either side of kMinAlbedo (0.005 and 0.03, as on a green lawn) under
// one light, with noise of 30% in each channel: every stripe keeps its own blue. A divisor that
// jumped at kMinAlbedo gave the 0.005 stripes their neighbours' demodulated blue, which the
// luminance stop hardly sees (blue weighs 0.07 in luminance): their blue came out 100x the
// truth.
TEST(Denoiser, AlbedoChannelsNearZeroKeepTheirScale) {
    Frame f(48, 16);
    f.samples = 16;
    std::mt19937 rng(4);
    std::normal_distribution<float> noise(0.0f, 0.3f);
    const float light = 0.5f;
    std::vector<float> truth(f.beauty.size(), 1.0f);
    f.forEachPixel([&](uint32_t x, uint32_t y) {
        const Vec3 albedo(0.3f, 0.6f, (x / 3) % 2 ? 0.03f : 0.005f), exact = albedo * light;
        f.set(f.albedo, x, y, albedo);
        f.set(truth, x, y, exact);
        f.set(f.beauty, x, y, exact * (Vec3(1.0f) + Vec3(noise(rng), noise(rng), noise(rng))));
        f.set(f.variance, x, y, Vec3(0.09f * luminance(exact * exact)));
    });
    const std::vector<float> out = f.denoised();
    const double raw = imageError(f.beauty, truth).relMse, denoised = imageError(out, truth).relMse;
    std::cout << "[ figures  ] blue albedo 0.005 / 0.03 stripes: relMSE raw " << raw << ", denoised "
              << denoised << "\n";
    EXPECT_LE(denoised, 0.5 * raw);
    for (uint32_t x = 0; x < f.width; ++x) {
        float blue = 0.0f;
        for (uint32_t y = 0; y < f.height; ++y) blue += f.at(out, x, y).z / float(f.height);
        EXPECT_NEAR(blue, f.at(truth, x, 0).z, 0.1f * f.at(truth, x, 0).z) << "column " << x;
    }
}

// A one-pixel black line (albedo 0) with a 4% sheen that no albedo scales, on a white wall, at
// the noise of 16 samples: the line's demodulated radiance is its sheen over the albedo floor,
// and with its variance it must not open the wall's luminance stops to it, nor the wall's noise
// the line's (before the outlier weight and the albedo floor the wall beside the line came out
// at 0.74, and the line at 0.089).
TEST(Denoiser, ABlackLineDoesNotBleedIntoAWhiteWall) {
    Frame f(40, 16);
    f.samples = 16;
    std::mt19937 rng(6);
    std::normal_distribution<float> noise(0.0f, 1.0f);
    f.forEachPixel([&](uint32_t x, uint32_t y) {
        const bool line = x == 20;
        const float truth = line ? 0.04f : 1.0f, sigma = 0.3f * truth;
        f.set(f.albedo, x, y, Vec3(line ? 0.0f : 1.0f));
        f.set(f.beauty, x, y, Vec3(truth + sigma * noise(rng)));
        f.set(f.variance, x, y, Vec3(sigma * sigma));
    });
    const std::vector<float> out = f.denoised();
    float wall = 0.0f, line = 0.0f;  // the largest errors beside the line and on it
    for (uint32_t y = 0; y < f.height; ++y) {
        for (const uint32_t x : {18u, 19u, 21u, 22u})
            wall = std::max(wall, std::fabs(f.at(out, x, y).x - 1.0f));
        line = std::max(line, std::fabs(f.at(out, 20, y).x - 0.04f));
    }
    std::cout << "[ figures  ] black line on a white wall: largest error beside it " << wall << ", on it "
              << line << "\n";
    EXPECT_LE(wall, 0.15f);
    EXPECT_LE(line, 0.06f);
}

// A one-pixel object against a constant sky: every tap is on the sky, whose variance is 0, so
// the object's variance is outlying beside its neighbours'; it must still keep its own value
// (with no floor under outlierWeight it weighed nothing and was pulled towards 0).
TEST(Denoiser, AOnePixelObjectAgainstAConstantSkyKeepsItsValue) {
    Frame f(9, 9);
    f.samples = 16;
    f.forEachPixel([&](uint32_t x, uint32_t y) {
        const bool object = x == 4 && y == 4;
        f.set(f.albedo, x, y, Vec3(object ? 0.5f : 0.0f));
        f.set(f.normal, x, y, object ? Vec3(0, 0, 1) : Vec3(0.0f));
        f.set(f.depth, x, y, Vec3(object ? 5.0f : 0.0f));
        f.set(f.alpha, x, y, Vec3(object ? 1.0f : 0.0f));
        f.set(f.emission, x, y, Vec3(object ? 0.0f : 1.0f));
        f.set(f.beauty, x, y, Vec3(object ? 0.4f : 1.0f));
        f.set(f.variance, x, y, Vec3(object ? 0.05f : 0.0f));
    });
    EXPECT_NEAR(f.at(f.denoised(), 4, 4).x, 0.4f, 1e-3f);
}

// A shadow edge no guide shows (one wall, bright left, dark right) below a row of sky whose
// pixels vary (an environment image): a sky pixel's variance is none of the wall's business.
// (When it was kept, divided by the albedo floor squared, it opened the luminance stops of the
// wall's top row, which then smoothed the edge away.)
TEST(Denoiser, ASkysVarianceDoesNotOpenTheLuminanceStopsBelowIt) {
    Frame f(40, 16);
    f.samples = 16;
    std::mt19937 rng(7);
    std::normal_distribution<float> noise(0.0f, 1.0f);
    f.forEachPixel([&](uint32_t x, uint32_t y) {
        const bool sky = y == 0;
        const float truth = x < 20 ? 1.0f : 0.1f, sigma = 0.02f;
        f.set(f.albedo, x, y, Vec3(sky ? 0.0f : 1.0f));
        f.set(f.normal, x, y, sky ? Vec3(0.0f) : Vec3(0, 0, 1));
        f.set(f.depth, x, y, Vec3(sky ? 0.0f : 5.0f));
        f.set(f.alpha, x, y, Vec3(sky ? 0.0f : 1.0f));
        const float skyValue = 2.0f + noise(rng);
        f.set(f.emission, x, y, Vec3(sky ? skyValue : 0.0f));
        f.set(f.beauty, x, y, Vec3(sky ? skyValue : truth + sigma * noise(rng)));
        f.set(f.variance, x, y, Vec3(sky ? 0.5f : sigma * sigma));
    });
    const std::vector<float> out = f.denoised();
    float worst = 0.0f;  // on the top row, next to the sky, within 3 pixels of the edge
    for (uint32_t x = 17; x < 23; ++x)
        worst = std::max(worst, std::fabs(f.at(out, x, 1).x - (x < 20 ? 1.0f : 0.1f)));
    std::cout << "[ figures  ] shadow edge below a varying sky: largest error on the row below it " << worst
              << "\n";
    EXPECT_LE(worst, 0.03f);
}

// A geometric edge (a step in depth and a turn of the normal) between a bright and a dark
// surface of one albedo: the guides keep the bright side from bleeding into the dark one.
TEST(Denoiser, AGeometricEdgeStopsTheFilter) {
    Frame f(40, 16);
    f.samples = 16;
    std::mt19937 rng(2);
    std::normal_distribution<float> noise(0.0f, 0.02f);
    f.forEachPixel([&](uint32_t x, uint32_t y) {
        const bool near = x < 20;
        f.set(f.beauty, x, y, Vec3((near ? 1.0f : 0.1f) + noise(rng)));
        f.set(f.depth, x, y, Vec3(near ? 2.0f : 6.0f));
        f.set(f.normal, x, y, near ? Vec3(0, 0, 1) : Vec3(1, 0, 0));
        f.set(f.variance, x, y, Vec3(0.02f * 0.02f));
    });
    const std::vector<float> out = f.denoised();
    for (uint32_t y = 0; y < f.height; ++y) {
        EXPECT_NEAR(f.at(out, 19, y).x, 1.0f, 0.03f) << "row " << y;
        EXPECT_NEAR(f.at(out, 20, y).x, 0.1f, 0.03f) << "row " << y;
    }
}

// A CpuDenoiser keeps its planes from call to call: what one call leaves in them (its own
// variance estimate at few samples, its sizes) must not reach the next.
TEST(Denoiser, AKeptWorkspaceGivesWhatAFreshOneGives) {
    std::mt19937 rng(5);
    std::normal_distribution<float> noise(0.0f, 0.1f);
    const auto noisy = [&](uint32_t w, uint32_t h, uint32_t samples) {
        Frame f(w, h);
        f.samples = samples;
        for (uint32_t y = 0; y < h; ++y) {
            for (uint32_t x = 0; x < w; ++x) {
                f.set(f.beauty, x, y, Vec3(0.5f + noise(rng)));
                f.set(f.variance, x, y,
                      Vec3(samples < kMinSamplesForOwnVariance ? 0.0f : 0.01f / float(samples)));
                if (x > w / 2) f.set(f.depth, x, y, Vec3(0.0f));  // sky: left of the wall only
            }
        }
        return f;
    };
    const Frame frames[] = {noisy(40, 30, 1), noisy(40, 30, 16), noisy(23, 37, 2), noisy(40, 30, 1)};
    CpuDenoiser kept;
    for (const Frame& f : frames) {
        std::vector<float> reused;
        kept.run(f.input(), reused);
        EXPECT_EQ(reused, f.denoised()) << f.width << "x" << f.height << ", " << f.samples << " spp";
    }
}

// A firefly: one of a pixel's 16 samples found a path 1000x as bright as the rest, so its mean
// is 63x the truth and its own variance estimate is huge. Its neighbours must replace it, and it
// must not spread into them (without outlierWeight it came out at 1.37 here).
TEST(Denoiser, AFireflyIsReplacedByItsNeighboursAndDoesNotSpread) {
    Frame f(32, 32);
    f.samples = 16;
    std::mt19937 rng(5);
    std::normal_distribution<float> noise(0.0f, 0.1f);
    f.forEachPixel([&](uint32_t x, uint32_t y) {
        f.set(f.beauty, x, y, Vec3(1.0f + noise(rng)));
        f.set(f.variance, x, y, Vec3(0.01f));
    });
    const float sampleValue = 1000.0f, mean = (15.0f + sampleValue) / 16.0f;
    const float sampleVariance =
        (15.0f * (1.0f - mean) * (1.0f - mean) + (sampleValue - mean) * (sampleValue - mean)) / 15.0f;
    f.set(f.beauty, 16, 16, Vec3(mean));
    f.set(f.variance, 16, 16, Vec3(sampleVariance / 16.0f));
    const std::vector<float> out = f.denoised();
    std::cout << "[ figures  ] firefly of " << mean << " on a wall of 1: denoised " << f.at(out, 16, 16).x
              << ", its neighbour " << f.at(out, 17, 16).x << "\n";
    EXPECT_NEAR(f.at(out, 16, 16).x, 1.0f, 0.2f);
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            if (dx == 0 && dy == 0) continue;
            EXPECT_NEAR(f.at(out, 16 + dx, 16 + dy).x, 1.0f, 0.1f) << "neighbour " << dx << ", " << dy;
        }
    }
}

// A firefly in a first sample: one pixel's only path found a light, 60x the wall's value. The
// wall is bumpy and seen through a defocused lens, so one sample's normals differ from pixel to
// pixel by 20 degrees: the edge stops part every pixel from its neighbours, whose spread then
// gives it hardly any variance, and the noise bound kept most of the firefly (3.1 without the
// clamp). Held to its
// neighbours by fireflyLimitAt, which ignores the edge stops, it must come down to the wall;
// and from kMinSamplesForOwnVariance samples on, where each pixel's own variance speaks, a pixel
// that truly outshines its neighbours (a variance of 0) keeps its value.
TEST(Denoiser, AFireflyInAFirstSampleIsHeldToItsNeighbours) {
    Frame f(32, 32);
    f.samples = 1;
    std::mt19937 rng(9);
    std::normal_distribution<float> noise(0.0f, 0.1f);
    std::uniform_real_distribution<float> turn(0.0f, 6.2831853f);
    f.forEachPixel([&](uint32_t x, uint32_t y) {
        f.set(f.beauty, x, y, Vec3(1.0f + noise(rng)));
        const float tilt = 0.35f, around = turn(rng);  // 20 degrees off the wall's normal
        f.set(f.normal, x, y,
              {std::sin(tilt) * std::cos(around), std::sin(tilt) * std::sin(around), std::cos(tilt)});
    });
    f.set(f.beauty, 16, 16, Vec3(60.0f));
    const std::vector<float> out = f.denoised();
    std::cout << "[ figures  ] 1-spp firefly of 60 on a bumpy wall of 1: denoised " << f.at(out, 16, 16).x
              << "\n";
    EXPECT_NEAR(f.at(out, 16, 16).x, 1.0f, 0.3f);
    f.samples = kMinSamplesForOwnVariance;
    EXPECT_NEAR(f.at(f.denoised(), 16, 16).x, 60.0f, 1e-3f) << "a bright pixel of no variance";
}

// A shadow edge no guide shows (one wall, lit left, unlit right) at 2 spp. The neighbours' spread
// across the edge is the light's, so the variance they estimate for an unlit pixel beside it
// opened its luminance stop to the lit side (it came out at 0.95 here); its own variance, 0 (both
// its samples found no light), must have its say (firstSamplesVariance).
TEST(Denoiser, AShadowEdgeAtTwoSamplesKeepsItsDarkSide) {
    Frame f(32, 32);
    f.samples = 2;
    std::mt19937 rng(4);
    std::normal_distribution<float> noise(0.0f, 1.0f);
    f.forEachPixel([&](uint32_t x, uint32_t y) {
        const bool lit = x < 16;
        f.set(f.beauty, x, y, Vec3(lit ? 4.0f + noise(rng) : 0.0f));
        f.set(f.variance, x, y, Vec3(lit ? 0.5f : 0.0f));
    });
    const std::vector<float> out = f.denoised();
    std::cout << "[ figures  ] 2-spp shadow edge of 4 against 0: denoised beside it " << f.at(out, 16, 16).x
              << " and " << f.at(out, 15, 16).x << "\n";
    for (uint32_t y = 0; y < 32; ++y) {
        for (uint32_t x = 16; x < 32; ++x) EXPECT_LT(f.at(out, x, y).x, 0.05f) << x << ", " << y;
    }
}

TEST(Denoiser, NanAndInfinityNeverReachTheOutput) {
    Frame f(24, 24);
    f.samples = 2;
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    f.set(f.beauty, 5, 5, {nan, 1.0f, 1.0f});
    f.set(f.beauty, 12, 12, {inf, inf, inf});
    f.set(f.variance, 12, 13, Vec3(nan));
    f.set(f.albedo, 3, 20, Vec3(nan));
    f.set(f.depth, 20, 3, Vec3(inf));
    const std::vector<float> out = f.denoised();
    EXPECT_TRUE(allFinite(out));
    // The flat wall's value, 1, survives around the poisoned pixels.
    EXPECT_NEAR(f.at(out, 8, 8).y, 1.0f, 1e-4f);
}

// A smooth lit wall with a texture, and noise of a known standard deviation a pixel: at the
// noise of a few samples the filter removes most of the error; at the noise of thousands it
// must not add any (it fades out as the variance falls).
struct NoisyWall {
    Frame frame{96, 96};
    std::vector<float> truth;

    NoisyWall(float sigma, uint32_t samples, uint32_t seed) {
        frame.samples = samples;
        truth.assign(frame.beauty.size(), 1.0f);
        std::mt19937 rng(seed);
        std::normal_distribution<float> noise(0.0f, 1.0f);
        for (uint32_t y = 0; y < frame.height; ++y) {
            for (uint32_t x = 0; x < frame.width; ++x) {
                // A checker texture of 6-pixel squares under light that falls off across the wall,
                // with what no guide shows: a hard shadow edge and fine ripples of light.
                const Vec3 albedo = ((x / 6 + y / 6) % 2) ? Vec3(0.8f, 0.6f, 0.2f) : Vec3(0.2f, 0.4f, 0.7f);
                float light =
                    0.3f + 0.7f * std::exp(-float((x - 30) * (x - 30) + (y - 60) * (y - 60)) / 1800.0f);
                if (x > 70) light *= 0.3f;
                if (y < 24) light *= 1.0f + 0.05f * std::sin(float(x) * 1.5f);
                const Vec3 exact = albedo * light;
                frame.set(truth, x, y, exact);
                frame.set(frame.albedo, x, y, albedo);
                frame.set(frame.beauty, x, y, exact + Vec3(noise(rng), noise(rng), noise(rng)) * sigma);
                const float lum =
                    sigma * std::sqrt(0.2126f * 0.2126f + 0.7152f * 0.7152f + 0.0722f * 0.0722f);
                frame.set(frame.variance, x, y, Vec3(samples < kMinSamplesForOwnVariance ? 0.0f : lum * lum));
            }
        }
    }
};

TEST(Denoiser, RemovesMostOfTheNoiseOfAFewSamples) {
    for (const uint32_t samples : {1u, 4u, 16u}) {
        const NoisyWall wall(0.4f / std::sqrt(float(samples)), samples, 3 + samples);
        const double raw = imageError(wall.frame.beauty, wall.truth).relMse;
        const double denoised = imageError(wall.frame.denoised(), wall.truth).relMse;
        std::cout << "[ figures  ] " << samples << " spp-like noise: relMSE raw " << raw << ", denoised "
                  << denoised << " (" << raw / denoised << "x less)\n";
        EXPECT_LE(denoised, 0.25 * raw) << samples;
    }
}

// A path tracer's first sample is not Gaussian: most paths miss the light and bring nothing,
// the few that find it bring much (here 1 in 3 pixels, carrying three times the truth). The
// neighbours' spread underestimates such noise; the filter must still clean a first sample.
TEST(Denoiser, CleansTheHeavyTailedNoiseOfAFirstSample) {
    NoisyWall wall(0.0f, 1, 11);
    std::mt19937 rng(12);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (uint32_t y = 0; y < wall.frame.height; ++y) {
        for (uint32_t x = 0; x < wall.frame.width; ++x) {
            const float found = u(rng) < 1.0f / 3.0f ? 3.0f : 0.0f;
            wall.frame.set(wall.frame.beauty, x, y, wall.frame.at(wall.truth, x, y) * found);
        }
    }
    const double raw = imageError(wall.frame.beauty, wall.truth).relMse;
    const double denoised = imageError(wall.frame.denoised(), wall.truth).relMse;
    std::cout << "[ figures  ] heavy-tailed first sample: relMSE raw " << raw << ", denoised " << denoised
              << " (" << raw / denoised << "x less)\n";
    EXPECT_LE(denoised, 0.1 * raw);
}

TEST(Denoiser, FadesOutAsTheNoiseFalls) {
    const NoisyWall wall(0.4f / 64.0f, 4096, 7);  // the noise of 4096 samples
    const double raw = imageError(wall.frame.beauty, wall.truth).relMse;
    const double denoised = imageError(wall.frame.denoised(), wall.truth).relMse;
    std::cout << "[ figures  ] 4096 spp-like noise: relMSE raw " << raw << ", denoised " << denoised << "\n";
    EXPECT_LE(denoised, 1.05 * raw);
}

}  // namespace
}  // namespace pt
