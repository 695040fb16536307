// Backend::setAovSampleCap on the CPU backend: a capped path AOV stops at the first pass that
// finds it full and keeps the average of the samples it took; the beauty, the variance and the
// AOVs left uncapped go on as without a cap; a cap lifted lets the AOV go on; the denoiser
// accepts capped guides, and camera rays go back to packets once no path AOV records.
#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <vector>

#include "render/backend/aov.h"
#include "render/backend/backend.h"
#include "support/aov_scenes.h"
#include "support/render_cpu.h"

namespace pt {
namespace {

std::unique_ptr<Backend> syncedCpu(const Scene& scene, AovMask aovs, const AovSampleCap& cap) {
    std::unique_ptr<Backend> backend = createBackend("cpu");
    backend->setAovs(aovs);
    backend->setAovSampleCap(cap);
    backend->sync(scene, SceneChanges::All, {});
    return backend;
}

bool packetsActive(const Backend& backend) {
    for (const ToggleState& s : backend.toggleStates()) {
        if (s.id == ToggleId::RayPackets) return s.active;
    }
    return false;
}

// Pixel jitter is on, so the albedo of an edge pixel differs from sample to sample: an AOV that
// took other samples than the first four would read differently. The cap falls inside a call,
// which renders up to it and then on without the AOV.
TEST(AovSampleCap, ACappedAovKeepsTheAverageOfTheSamplesItTook) {
    const Scene scene = test::noisyScene(24);
    const AovMask aovs = aovBit(Aov::Albedo) | aovBit(Aov::Depth) | aovBit(Aov::Variance);
    const std::unique_ptr<Backend> capped = syncedCpu(scene, aovs, {aovBit(Aov::Albedo), 4});
    capped->render(3);
    capped->render(3);
    EXPECT_EQ(capped->aovSamples(Aov::Albedo), 4u) << "stopped at the cap, inside the second call";
    const std::vector<float> albedoAt4 = test::aovOf(*capped, Aov::Albedo);
    capped->render(5);
    capped->render(1);
    EXPECT_EQ(capped->aovSamples(Aov::Albedo), 4u);
    EXPECT_EQ(capped->aovSamples(Aov::Depth), 12u);
    EXPECT_EQ(test::aovOf(*capped, Aov::Albedo), albedoAt4);

    const std::unique_ptr<Backend> uncapped = syncedCpu(scene, aovs, {});
    uncapped->render(4);
    EXPECT_EQ(test::aovOf(*uncapped, Aov::Albedo), albedoAt4) << "the first four samples' average";
    uncapped->render(8);
    EXPECT_EQ(test::beautyOf(*capped), test::beautyOf(*uncapped)) << "a cap never changes the beauty";
    EXPECT_EQ(test::aovOf(*capped, Aov::Depth), test::aovOf(*uncapped, Aov::Depth));
    EXPECT_EQ(test::aovOf(*capped, Aov::Variance), test::aovOf(*uncapped, Aov::Variance));

    // Lifted, the AOV goes on from the next pass; a reset starts it with the beauty, capped again.
    capped->setAovSampleCap({});
    capped->render(2);
    EXPECT_EQ(capped->aovSamples(Aov::Albedo), 6u);
    EXPECT_NE(test::aovOf(*capped, Aov::Albedo), albedoAt4);
    capped->setAovSampleCap({aovBit(Aov::Albedo), 4});
    capped->resetAccumulation();
    capped->render(7);
    EXPECT_EQ(capped->aovSamples(Aov::Albedo), 4u) << "one call of 7 stops it at 4";
    EXPECT_EQ(capped->stats().samplesPerPixel, 7u);
}

TEST(AovSampleCap, OnlyPathAovsWithAtLeastOneSampleCanBeCapped) {
    const std::unique_ptr<Backend> backend = createBackend("cpu");
    EXPECT_THROW(backend->setAovSampleCap({aovBit(Aov::Variance), 8}), std::invalid_argument);
    EXPECT_THROW(backend->setAovSampleCap({aovBit(Aov::SampleCount), 8}), std::invalid_argument);
    EXPECT_THROW(backend->setAovSampleCap({aovBit(Aov::Albedo), 0}), std::invalid_argument);
    EXPECT_EQ(backend->aovSampleCap().aovs, 0u) << "a refused cap leaves the one before";
    EXPECT_NO_THROW(backend->setAovSampleCap({0, 0}));
    EXPECT_EQ(settledGuideCap(0).aovs, kDenoiseGuideAovs & ~aovBit(Aov::Variance));
    EXPECT_EQ(settledGuideCap(0).samples, kSettledGuideSamples);
    EXPECT_EQ(settledGuideCap(aovBit(Aov::Albedo)).aovs & aovBit(Aov::Albedo), 0u) << "kept in full";
    EXPECT_EQ(settledGuideCap(0, 0).aovs, 0u) << "0 samples: no cap";
}

// Capped guides hold fewer samples than the beauty and still guide it; one added later must
// first fill up to the cap.
TEST(AovSampleCap, TheDenoiserTakesGuidesThatStoppedAtTheCap) {
    const Scene scene = test::noisyScene(24);
    const std::unique_ptr<Backend> backend = syncedCpu(scene, kDenoiseGuideAovs, settledGuideCap(0, 4));
    backend->render(10);
    backend->render(10);
    EXPECT_EQ(backend->aovSamples(Aov::Albedo), 4u);
    EXPECT_EQ(backend->aovSamples(Aov::Variance), 20u);
    EXPECT_TRUE(denoiseGuidesComplete(*backend));
    std::vector<float> denoised;
    EXPECT_NO_THROW(backend->readDenoised(denoised));
    EXPECT_EQ(denoised.size(), test::beautyOf(*backend).size());

    backend->changeAovs(kDenoiseGuideAovs & ~aovBit(Aov::Albedo));
    backend->changeAovs(kDenoiseGuideAovs);
    backend->render(2);
    EXPECT_FALSE(denoiseGuidesComplete(*backend)) << "albedo: 2 samples, under the cap of 4";
    EXPECT_THROW(backend->readDenoised(denoised), std::invalid_argument);
    backend->render(2);
    EXPECT_TRUE(denoiseGuidesComplete(*backend));
}

// Path AOVs keep camera rays out of packets (they record each ray's traversal); once the cap
// holds every one of them, the packets come back, and the beauty is still the one-ray-at-a-time
// image bit for bit.
TEST(AovSampleCap, CameraRaysGoBackToPacketsOnceNoPathAovRecords) {
    const Scene scene = test::noisyScene(24);
    const std::unique_ptr<Backend> capped = syncedCpu(scene, kDenoiseGuideAovs, settledGuideCap(0, 3));
    const bool avx2 = packetsActive(*syncedCpu(scene, 0, {}));
    EXPECT_FALSE(packetsActive(*capped));
    capped->render(3);
    EXPECT_EQ(packetsActive(*capped), avx2) << "every path AOV holds its 3 samples";
    capped->render(4);

    const std::unique_ptr<Backend> uncapped = syncedCpu(scene, kDenoiseGuideAovs, {});
    uncapped->render(7);
    EXPECT_FALSE(packetsActive(*uncapped));
    EXPECT_EQ(test::beautyOf(*capped), test::beautyOf(*uncapped));
    EXPECT_EQ(test::aovOf(*capped, Aov::Variance), test::aovOf(*uncapped, Aov::Variance));
    if (!avx2) GTEST_SKIP() << "this processor runs no AVX2: the packet walk does not apply";
}

}  // namespace
}  // namespace pt
