// Backend::changeAovs on the CPU backend: AOVs added while the beauty accumulates start at the
// next pass and average over their own samples; the ones kept keep theirs; the beauty is what
// it would be without them; a reset starts all of them with the beauty again.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "render/backend/aov.h"
#include "render/backend/backend.h"
#include "support/aov_scenes.h"
#include "support/render_cpu.h"

namespace pt {
namespace {

// Without pixel jitter every sample of a pixel starts with the same ray: its first-hit albedo,
// depth and ids are the same whichever samples an AOV holds, so an AOV added at 3 spp must read
// as one accumulated from the start does.
TEST(ChangeAovs, AnAovAddedLaterAveragesItsOwnSamples) {
    const Scene scene = test::noisyScene(24);
    IntegratorToggles toggles;
    toggles.pixelJitter = false;
    const AovMask later = aovBit(Aov::Albedo) | aovBit(Aov::InstanceId) | aovBit(Aov::SampleCount);
    std::unique_ptr<Backend> added = createBackend("cpu");
    added->setToggles(toggles);
    added->setAovs(aovBit(Aov::Depth));
    added->sync(scene, SceneChanges::All, {});
    added->render(3);
    const std::vector<float> depthAt3 = test::aovOf(*added, Aov::Depth);
    added->changeAovs(aovBit(Aov::Depth) | later);
    EXPECT_EQ(added->stats().samplesPerPixel, 3u) << "the beauty keeps its samples";
    EXPECT_EQ(added->aovSamples(Aov::Albedo), 0u);
    EXPECT_EQ(test::aovOf(*added, Aov::Depth), depthAt3) << "a kept AOV keeps its sums";
    added->render(5);
    EXPECT_EQ(added->aovSamples(Aov::Albedo), 5u);
    EXPECT_EQ(added->aovSamples(Aov::Depth), 8u);

    std::unique_ptr<Backend> fromStart = createBackend("cpu");
    fromStart->setToggles(toggles);
    fromStart->setAovs(aovBit(Aov::Depth) | later);
    fromStart->sync(scene, SceneChanges::All, {});
    fromStart->render(8);
    const std::vector<float> albedo = test::aovOf(*added, Aov::Albedo),
                             expected = test::aovOf(*fromStart, Aov::Albedo);
    ASSERT_EQ(albedo.size(), expected.size());
    for (size_t i = 0; i < albedo.size(); ++i) ASSERT_NEAR(albedo[i], expected[i], 1e-6f) << i;
    EXPECT_EQ(test::aovOf(*added, Aov::InstanceId), test::aovOf(*fromStart, Aov::InstanceId))
        << "written by its first sample";
    EXPECT_EQ(test::aovOf(*added, Aov::SampleCount)[0], 5.0f);
    EXPECT_EQ(test::beautyOf(*added), test::beautyOf(*fromStart)) << "AOVs never change the beauty";

    // Dropping one frees it and keeps the others; a reset starts them all with the beauty.
    const uint64_t bytes = added->aovBytes();
    added->changeAovs(aovBit(Aov::Albedo));
    EXPECT_EQ(added->aovs(), aovBit(Aov::Albedo));
    EXPECT_LT(added->aovBytes(), bytes);
    for (size_t i = 0; i < albedo.size(); ++i) ASSERT_EQ(test::aovOf(*added, Aov::Albedo)[i], albedo[i]) << i;
    added->resetAccumulation();
    added->render(2);
    EXPECT_EQ(added->aovs(), aovBit(Aov::Albedo)) << "changeAovs is also the next reset's choice";
    EXPECT_EQ(added->aovSamples(Aov::Albedo), 2u);
}

// Welford's running mean and spread of the samples from the AOV's first on (a sample index
// counted from the accumulation's start would weight the first of them as if it were the
// fourth), and the variance AOV is of the beauty's mean: over its samples, not the AOV's.
TEST(ChangeAovs, TheVarianceCountsFromItsFirstSample) {
    double sums[2] = {0.0, 0.0};
    AovBuffers b{};
    b.mask = aovBit(Aov::Variance);
    b.sums[uint32_t(Aov::Variance)] = sums;
    b.firstSample[uint32_t(Aov::Variance)] = 3;
    const float values[] = {1.0f, 4.0f, 2.0f, 7.0f};
    for (uint32_t i = 0; i < 4; ++i) addVarianceSample(b, 0, 3 + i, Vec3(values[i]));
    EXPECT_NEAR(sums[0], 3.5, 1e-6);                         // the mean of 1, 4, 2, 7
    EXPECT_NEAR(sums[1], 6.25 + 0.25 + 2.25 + 12.25, 1e-5);  // the sum of squared deviations
    std::vector<float> rgba;
    aovImageFromSums(Aov::Variance, sums, 1, 4, 10, rgba);
    EXPECT_NEAR(rgba[0], 21.0 / 3.0 / 10.0, 1e-6) << "the sample variance over the beauty's 10 samples";
}

}  // namespace
}  // namespace pt
