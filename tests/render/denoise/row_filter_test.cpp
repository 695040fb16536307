// The CPU's row form of the denoiser's neighbourhood steps against the per-pixel steps the GPU
// runs (atrous_filter.h), bit for bit: a random image with every kind of pixel (sky beside
// surfaces, left-out pixels, creases, depth cliffs) through each pass's step, image edges
// included, at sizes that are not a multiple of a SIMD vector; and the firefly pass's box sums
// (firefly_limits.h) against its per-pixel form, to float rounding.
#include "render/denoise/row_filter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "render/denoise/atrous_filter.h"
#include "render/denoise/firefly_limits.h"

namespace pt::denoise {
namespace {

// One random image in both forms: the per-pixel arrays and the CPU's planes.
struct RandomImage {
    uint32_t width, height;
    PlaneLayout layout{width, height};
    std::vector<DenoiseSample> samples;
    std::vector<DenoiseSurface> surfaces;
    std::vector<SurfaceStops> stops;
    SurfacePlanes surfacePlanes{layout};

    RandomImage(uint32_t w, uint32_t h, uint32_t seed)
        : width(w), height(h), samples(size_t(w) * h), surfaces(size_t(w) * h), stops(size_t(w) * h) {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        for (size_t i = 0; i < samples.size(); ++i) {
            const float kind = u(rng);
            // Patches of a few surfaces, so that neighbours share some and differ in others.
            const uint32_t x = uint32_t(i % w), y = uint32_t(i / w);
            const uint32_t patch = (x / 7 + 3 * (y / 5)) % 4;
            const Vec3 normal =
                patch == 0 ? Vec3(0, 0, 1) : normalize(Vec3(0.3f * float(patch), u(rng) * 0.1f, 1.0f));
            const bool sky = patch == 3 && kind < 0.5f;
            surfaces[i] = {sky ? Vec3(0.0f) : normal, sky ? 0.0f : 2.0f + float(patch) + 0.01f * u(rng)};
            stops[i].normalPower = kNormalPower / (1.0f + 10.0f * u(rng));
            const Vec3 radiance(u(rng), u(rng) * 2.0f, u(rng) * 0.5f);
            // Left out, noiseless (a constant sky: outlier limits of 0), a firefly (far past its
            // neighbours' variance) or ordinary.
            const float variance = kind < 0.15f ? 0.0f : (kind < 0.2f ? 50.0f * u(rng) : 0.1f * u(rng));
            samples[i] =
                kind < 0.05f ? DenoiseSample{Vec3(0.0f), kInvalid} : DenoiseSample{radiance, variance};
        }
        for (uint32_t y = 0; y < h; ++y) {
            for (uint32_t x = 0; x < w; ++x) {
                const uint32_t i = y * w + x;
                stops[i].depthSlope = depthSlopeAt(surfaces.data(), w, h, x, y);
                surfacePlanes.store(layout.at(x, y), surfaces[i], stops[i]);
            }
        }
    }
};

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(RowFilter, AtrousRowsMatchThePerPixelStepBitForBit) {
    for (const auto& [w, h] : {std::pair{67u, 45u}, std::pair{5u, 3u}, std::pair{1u, 9u}}) {
        const RandomImage image(w, h, w * 31 + h);
        std::vector<PackedSample> packed(image.samples.size());
        SamplePlanes planes(image.layout), out(image.layout);
        const SampleOutput input(planes);
        for (uint32_t y = 0; y < h; ++y) {
            for (uint32_t x = 0; x < w; ++x) {
                packed[y * w + x] = packSample(image.samples[y * w + x]);
                input.store(image.layout.at(x, y), image.samples[y * w + x]);
            }
        }
        RowSums sums(w);
        for (uint32_t step = 1; step <= 16; step *= 2) {
            for (uint32_t y = 0; y < h; ++y)
                atrousRow(planes, image.surfacePlanes, image.layout, y, step, sums, out);
            size_t mismatches = 0;
            for (uint32_t y = 0; y < h; ++y) {
                for (uint32_t x = 0; x < w; ++x) {
                    const PackedSample expected =
                        atrousAt(packed.data(), image.surfaces.data(), image.stops.data(), w, h, x, y, step);
                    const PackedSample got = out.packed(image.layout.at(x, y));
                    mismatches += std::memcmp(&expected, &got, sizeof got) != 0;
                }
            }
            EXPECT_EQ(mismatches, 0u) << w << "x" << h << ", step " << step;
        }
    }
}

// The box sums of fireflyLimits against fireflyLimitAt's 48 taps: equal to float rounding
// (doubles summed in another order) on a random image, on one with a firefly 3e4 or 1e7 times
// its neighbours (where taking it out of its own row by subtraction lost its neighbours), and on
// a low-noise surface (a spread of 1e-4 of the mean, where one pass of float sums lost the
// spread).
TEST(RowFilter, FireflyLimitsMatchThePerPixelStep) {
    enum class Variant { Random, Firefly, HugeFirefly, LowNoise };
    for (const auto& [w, h] : {std::pair{67u, 45u}, std::pair{12u, 10u}}) {
        for (const Variant variant :
             {Variant::Random, Variant::Firefly, Variant::HugeFirefly, Variant::LowNoise}) {
            RandomImage image(w, h, w + 7 * h);
            DenoiseSample& centre = image.samples[(h / 2) * w + w / 2];
            if (variant == Variant::Firefly) centre = {Vec3(3.0e4f, 2.0e4f, 1.0e4f), 1.0f};
            if (variant == Variant::HugeFirefly) centre = {Vec3(1.0e7f), 1.0f};
            if (variant == Variant::LowNoise) {
                std::mt19937 rng(w);
                std::uniform_real_distribution<float> u(0.0f, 1.0f);
                for (DenoiseSample& sample : image.samples) {
                    if (sample.valid()) sample.radiance = Vec3(1.0f + 1e-4f * u(rng));
                }
            }
            FireflyRowSums rowSums;
            std::vector<float> limits(size_t(w) * h);
            fireflyLimits(image.samples.data(), image.surfaces.data(), w, h, rowSums, limits.data());
            size_t mismatches = 0, limited = 0;
            for (uint32_t y = 0; y < h; ++y) {
                for (uint32_t x = 0; x < w; ++x) {
                    const float expected =
                        fireflyLimitAt(image.samples.data(), image.surfaces.data(), w, h, x, y);
                    const float got = limits[y * w + x];
                    mismatches += !(std::fabs(got - expected) <= 2e-6f * std::fabs(expected));
                    limited += expected < kNoLuminanceLimit;
                }
            }
            EXPECT_EQ(mismatches, 0u) << w << "x" << h << ", variant " << int(variant);
            EXPECT_GT(limited, w * h / 2) << "most pixels have neighbours enough for a limit";
        }
    }
}

TEST(RowFilter, SpatialVarianceRowsMatchThePerPixelStepBitForBit) {
    for (const auto& [w, h] : {std::pair{67u, 45u}, std::pair{3u, 2u}}) {
        const RandomImage image(w, h, w + h);
        LuminancePlanes luminance(image.layout);
        for (uint32_t y = 0; y < h; ++y) {
            for (uint32_t x = 0; x < w; ++x) luminance.store(image.layout.at(x, y), image.samples[y * w + x]);
        }
        RowSums sums(w);
        std::vector<float> variance(w);
        size_t mismatches = 0, leftOut = 0;
        for (uint32_t y = 0; y < h; ++y) {
            spatialVarianceRow(luminance, image.surfacePlanes, image.layout, y, sums, variance.data());
            for (uint32_t x = 0; x < w; ++x) {
                const float expected = spatialVarianceAt(image.samples.data(), image.surfaces.data(),
                                                         image.stops.data(), w, h, x, y);
                mismatches += !sameBits(expected, variance[x]);
                leftOut += expected == kInvalid;
            }
        }
        EXPECT_EQ(mismatches, 0u) << w << "x" << h;
        if (w * h > 100) {
            EXPECT_GT(leftOut, 0u) << "the image has left-out pixels";
        }
    }
}

}  // namespace
}  // namespace pt::denoise
