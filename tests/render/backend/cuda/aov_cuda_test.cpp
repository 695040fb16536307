// AOVs on the CUDA backend against the CPU backend's, for the megakernel and the wavefront
// (with and without the first-hit cache): the same samples, so the same values to float
// rounding; a beauty left bit-identical; device memory only for the AOVs enabled.
// Every test skips with a message where no CUDA device is present.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <vector>

#include "cuda_test_support.h"
#include "render/backend/aov.h"
#include "render/backend/cpu/cpu_backend.h"
#include "render/backend/cuda/cuda_backend.h"
#include "support/aov_scenes.h"

namespace pt {
namespace {

struct Schedule {
    const char* name;
    IntegratorToggles toggles;
};

std::vector<Schedule> schedules(bool pixelJitter) {
    IntegratorToggles t;
    t.pixelJitter = pixelJitter;
    std::vector<Schedule> out;
    t.autoSchedule = false;  // each schedule on its own
    t.megakernel = true;
    out.push_back({"megakernel", t});
    t.megakernel = false;
    out.push_back({"wavefront", t});  // with the first-hit cache where jitter is off
    t.firstHitCache = false;
    t.streamCompaction = false;
    out.push_back({"wavefront, no cache, no compaction", t});
    return out;
}

// Renders spp samples in two calls (the second reads what a first-hit cache kept).
void renderAovs(Backend& backend, const Scene& scene, uint32_t spp, AovMask aovs,
                const IntegratorToggles& toggles) {
    backend.setToggles(toggles);
    backend.setAovs(aovs);
    backend.sync(scene, SceneChanges::All, {});
    backend.render(spp / 2);
    backend.render(spp - spp / 2);
}

// Pixels whose AOV differs by more than 1e-5 (relative above 1) in any channel.
size_t differingPixels(const Backend& cpu, const Backend& gpu, Aov aov, float* worst) {
    std::vector<float> a, b;
    cpu.readAov(aov, a);
    gpu.readAov(aov, b);
    EXPECT_EQ(a.size(), b.size()) << aovName(aov);
    size_t differing = 0;
    *worst = 0.0f;
    for (size_t i = 0; i + 3 < std::min(a.size(), b.size()); i += 4) {
        bool same = true;
        for (int c = 0; c < 4; ++c) {
            const float d = std::fabs(a[i + c] - b[i + c]);
            *worst = std::max(*worst, d);
            same &= d <= 1e-5f * std::max(1.0f, std::fabs(a[i + c]));
        }
        differing += !same;
    }
    return differing;
}

void expectAovsMatch(const Backend& cpu, const Backend& gpu, AovMask aovs, const char* what) {
    for (uint32_t i = 0; i < kAovCount; ++i) {
        const Aov aov = Aov(i);
        if (!(aovs & aovBit(aov))) continue;
        float worst = 0.0f;
        EXPECT_EQ(differingPixels(cpu, gpu, aov, &worst), 0u)
            << what << ": " << aovName(aov) << ", largest difference " << worst;
    }
}

// The variance of `gpu` against `cpu`'s (the beauty's samples agree but where a transcendental
// function rounded otherwise and a path took another turn: cuda_backend_test.cpp), and its
// beauty against a render of `spp` samples without AOVs, which it must equal bit for bit.
void expectVarianceAndPlainBeauty(const Backend& cpu, const Backend& gpu, const Scene& scene, uint32_t spp,
                                  const Schedule& s, const char* what) {
    float worst = 0.0f;
    const size_t differing = differingPixels(cpu, gpu, Aov::Variance, &worst);
    std::cout << "[ figures  ] variance, " << what << ", " << s.name << ": " << differing << " of " << 32 * 32
              << " pixels differ from the CPU by more than 1e-5\n";
    EXPECT_LT(differing, size_t(0.02 * 32 * 32)) << s.name;
    cuda::CudaBackend plain;
    renderAovs(plain, scene, spp, 0, s.toggles);
    std::vector<float> beauty, plainBeauty;
    gpu.readBeauty(beauty);
    plain.readBeauty(plainBeauty);
    EXPECT_EQ(beauty, plainBeauty) << s.name << ": " << what << " changed the beauty";
}

TEST(AovCuda, SphereAovsMatchTheCpu) {
    PT_REQUIRE_CUDA_DEVICE();
    const Scene scene = test::analyticSphereScene(64, 48);
    const AovMask aovs = kAllAovs & ~aovBit(Aov::Variance);  // variance: see the noisy scene
    CpuBackend cpu;
    // bvh_cost counts the nodes of the walk that ran: both backends walk the binary tree here,
    // not their 8-wide forms (the CPU's, the GPU's compressed one).
    IntegratorToggles binaryWalk = schedules(false)[0].toggles;
    binaryWalk.wideBvh = false;
    renderAovs(cpu, scene, 4, aovs, binaryWalk);
    for (const Schedule& s : schedules(false)) {
        cuda::CudaBackend gpu;
        IntegratorToggles gpuBinaryWalk = s.toggles;
        gpuBinaryWalk.gpuWideBvh = false;
        renderAovs(gpu, scene, 4, aovs, gpuBinaryWalk);
        // One instance, one sphere: both backends' BVHs are a single node per level, so even
        // bvh_cost agrees exactly.
        expectAovsMatch(cpu, gpu, aovs, s.name);
    }
}

// Jittered samples and two instances: averages over distinct rays. The BVHs over instances
// come from different builders (CPU binned SAH, GPU LBVH), so bvh_cost may differ and is left out.
TEST(AovCuda, JitteredAovsAndVarianceMatchTheCpu) {
    PT_REQUIRE_CUDA_DEVICE();
    const Scene scene = test::noisyScene(32);
    const AovMask aovs = kAllAovs & ~aovBit(Aov::BvhCost);
    const uint32_t spp = 16;
    CpuBackend cpu;
    renderAovs(cpu, scene, spp, aovs, schedules(true)[0].toggles);
    for (const Schedule& s : schedules(true)) {
        cuda::CudaBackend gpu;
        renderAovs(gpu, scene, spp, aovs, s.toggles);
        expectAovsMatch(cpu, gpu, aovs & ~aovBit(Aov::Variance), s.name);
        // The beauty's samples agree except where a transcendental function rounded otherwise
        // and a path took another turn (cuda_backend_test.cpp), and the variance with them.
        float worst = 0.0f;
        const size_t differing = differingPixels(cpu, gpu, Aov::Variance, &worst);
        std::cout << "[ figures  ] variance, " << s.name << ": " << differing << " of " << 32 * 32
                  << " pixels differ from the CPU by more than 1e-5\n";
        EXPECT_LT(differing, size_t(0.02 * 32 * 32)) << s.name;
    }
}

// A half-transparent pane in front of the ball: camera segments pass it (stochastic alpha) and
// end at a later bounce of the wavefront, whose shade then still records AOVs.
TEST(AovCuda, AovsSeenThroughAnAlphaBlendedPaneMatchTheCpu) {
    PT_REQUIRE_CUDA_DEVICE();
    Scene scene = test::noisyScene(32);
    Material glassPane = test::diffuse({0.2f, 0.5f, 0.9f});
    glassPane.alphaMode = AlphaMode::Blend;
    glassPane.alpha = 0.5f;
    const uint32_t pane = test::addMaterial(scene, "pane", glassPane);
    test::addShape(scene, ObjectKind::Quad, test::trs({0, 0.8f, 2.0f}, {90, 0, 0}, {0.6f, 1, 0.6f}), pane,
                   "pane");
    const AovMask aovs = kAllAovs & ~(aovBit(Aov::BvhCost) | aovBit(Aov::Variance));
    CpuBackend cpu;
    renderAovs(cpu, scene, 16, aovs, schedules(true)[0].toggles);
    std::vector<float> albedo;  // the pane's blue mixed with the grey behind it
    cpu.readAov(Aov::Albedo, albedo);
    size_t throughPane = 0;
    for (size_t i = 0; i < albedo.size(); i += 4) throughPane += albedo[i + 2] > albedo[i] + 0.1f ? 1 : 0;
    ASSERT_GT(throughPane, 20u) << "the pane must be in view";
    for (const Schedule& s : schedules(true)) {
        cuda::CudaBackend gpu;
        renderAovs(gpu, scene, 16, aovs, s.toggles);
        expectAovsMatch(cpu, gpu, aovs, s.name);
    }
}

TEST(AovCuda, BeautyIsBitIdenticalWithAndWithoutAovs) {
    PT_REQUIRE_CUDA_DEVICE();
    const Scene scene = test::noisyScene(32);
    for (bool jitter : {true, false}) {
        for (const Schedule& s : schedules(jitter)) {
            cuda::CudaBackend plain, withAovs;
            renderAovs(plain, scene, 8, 0, s.toggles);
            renderAovs(withAovs, scene, 8, kAllAovs, s.toggles);
            std::vector<float> a, b;
            plain.readBeauty(a);
            withAovs.readBeauty(b);
            ASSERT_EQ(a.size(), b.size());
            EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0)
                << s.name << ", jitter " << jitter;
        }
    }
}

TEST(AovCuda, DeviceMemoryGrowsOnlyWithAovs) {
    PT_REQUIRE_CUDA_DEVICE();
    const Scene scene = test::analyticSphereScene(64, 48);
    IntegratorToggles wavefront;
    wavefront.autoSchedule = false;
    wavefront.megakernel = false;
    wavefront.pixelJitter = false;  // the first-hit cache applies, and with bvh_cost keeps costs
    cuda::CudaBackend gpu;
    // Each call renders 2 passes as 1 + 1, so the wave's own buffers keep one size throughout.
    renderAovs(gpu, scene, 2, 0, wavefront);
    EXPECT_EQ(gpu.aovBytes(), 0u);
    const uint64_t without = gpu.deviceMemoryBytes();
    std::vector<float> rgba;
    EXPECT_THROW(gpu.readAov(Aov::Depth, rgba), std::invalid_argument);

    gpu.setAovs(kAllAovs);
    gpu.resetAccumulation();
    gpu.render(1);
    gpu.render(1);
    EXPECT_GE(gpu.aovBytes(), 64u * 48u * aovDoublesPerPixel(kAllAovs) * sizeof(double));
    EXPECT_EQ(gpu.deviceMemoryBytes(), without + gpu.aovBytes());
    EXPECT_NO_THROW(gpu.readAov(Aov::Depth, rgba));

    gpu.setAovs(0);
    gpu.resetAccumulation();
    gpu.render(1);
    gpu.render(1);
    EXPECT_EQ(gpu.aovBytes(), 0u);
    EXPECT_EQ(gpu.deviceMemoryBytes(), without);
}

// AOVs added while the beauty accumulates (Backend::changeAovs, the editor's AOV view): both
// backends start them at the same sample, so they agree as AOVs accumulated from the start do,
// and the beauty is left as it was.
TEST(AovCuda, AovsAddedMidAccumulationMatchTheCpu) {
    PT_REQUIRE_CUDA_DEVICE();
    const Scene scene = test::noisyScene(32);
    const AovMask added = aovBit(Aov::Albedo) | aovBit(Aov::InstanceId) | aovBit(Aov::SampleCount) |
                          aovBit(Aov::Variance) | aovBit(Aov::Depth);
    const auto render = [&](Backend& backend, const IntegratorToggles& toggles) {
        renderAovs(backend, scene, 6, aovBit(Aov::Depth), toggles);
        backend.changeAovs(added);
        backend.render(5);
        backend.render(5);
        EXPECT_EQ(backend.aovSamples(Aov::Albedo), 10u) << backend.name();
        EXPECT_EQ(backend.aovSamples(Aov::Depth), 16u) << backend.name() << ": kept from the start";
    };
    CpuBackend cpu;
    render(cpu, schedules(true)[0].toggles);
    for (const Schedule& s : schedules(true)) {
        cuda::CudaBackend gpu;
        render(gpu, s.toggles);
        expectAovsMatch(cpu, gpu, added & ~aovBit(Aov::Variance), s.name);
        expectVarianceAndPlainBeauty(cpu, gpu, scene, 16, s, "AOVs added at 6 spp");
    }
}

// AOVs capped at 4 samples (Backend::setAovSampleCap, the denoiser's settled guides), one
// sample a call so both backends stop them at the same sample: the same averages as the CPU's,
// the variance over every sample, and the beauty bit for bit that of a render without AOVs
// (after the cap no path AOV records, so the scene's specialised kernels run instead of the AOV
// kernel, still adding the variance).
TEST(AovCuda, CappedAovsMatchTheCpuAndLeaveTheBeauty) {
    PT_REQUIRE_CUDA_DEVICE();
    const Scene scene = test::noisyScene(32);
    const AovMask aovs =
        aovBit(Aov::Albedo) | aovBit(Aov::Alpha) | aovBit(Aov::Depth) | aovBit(Aov::Variance);
    const AovSampleCap cap{aovs & kPathAovs, 4};  // the variance alone goes on
    const auto render = [&](Backend& backend, const IntegratorToggles& toggles) {
        backend.setAovSampleCap(cap);
        renderAovs(backend, scene, 2, aovs, toggles);
        for (int pass = 0; pass < 8; ++pass) backend.render(1);
        EXPECT_EQ(backend.aovSamples(Aov::Albedo), 4u) << backend.name();
        EXPECT_EQ(backend.aovSamples(Aov::Depth), 4u) << backend.name();
        EXPECT_EQ(backend.aovSamples(Aov::Variance), 10u) << backend.name();
    };
    CpuBackend cpu;
    render(cpu, schedules(true)[0].toggles);
    for (const Schedule& s : schedules(true)) {
        cuda::CudaBackend gpu;
        render(gpu, s.toggles);
        expectAovsMatch(cpu, gpu, aovs & ~aovBit(Aov::Variance), s.name);
        expectVarianceAndPlainBeauty(cpu, gpu, scene, 10, s, "a cap");
    }
}

}  // namespace
}  // namespace pt
