// The CUDA backend against the CPU backend: the same first hits, the same beauty at equal
// samples, refits that trace like rebuilds, and scheduling toggles that leave the image alone.
// Every test skips with a message where no CUDA device is present.
#include "render/backend/cuda/cuda_backend.h"

#include <cuda_runtime.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <future>
#include <iostream>
#include <random>
#include <thread>
#include <vector>

#include "cuda_test_support.h"
#include "render/backend/cpu/cpu_backend.h"
#include "render/backend/cuda/kernel_variants.h"
#include "render/integrator/camera.h"
#include "support/load_scene.h"
#include "support/scene_builder.h"
#include "support/test_paths.h"

namespace pt {
namespace {

using test::addMaterial;
using test::addShape;
using test::trs;

Scene cornell(uint32_t size, uint32_t maxDepth = 8) {
    Scene scene = test::loadSceneOrFail(test::projectPath("scenes/cornell.json"));
    scene.render.width = scene.render.height = size;
    scene.render.maxDepth = maxDepth;
    return scene;
}

// Renders in `batches` calls of spp / batches samples (so caches made by one call serve the next).
std::vector<float> renderWith(Backend& backend, const Scene& scene, uint32_t spp,
                              const IntegratorToggles& toggles = {}, uint32_t batches = 1) {
    backend.setToggles(toggles);
    backend.sync(scene, SceneChanges::All, {});
    // The compressed nodes land before the first pass, not at whichever wave they are done.
    backend.finishBackgroundWork();
    for (uint32_t b = 0; b < batches; ++b) backend.render(spp / batches);
    EXPECT_EQ(backend.stats().nonfiniteSamples, 0u) << backend.name();
    std::vector<float> rgba;
    backend.readBeauty(rgba);
    return rgba;
}

// A bumpy grid of (n x n) quads in the XZ plane, as one mesh, under a sky.
Scene bumpyGridScene(uint32_t n, uint32_t seed) {
    Scene scene;
    scene.render = {64, 64, 4, 16, 0};
    scene.camera.position = {0.0f, 2.5f, 2.5f};
    scene.camera.lookAt = {0, 0, 0};
    scene.environment.color = {1, 1, 1};
    Mesh mesh = test::bumpyGrid(n, seed);
    mesh.name = "grid";
    scene.meshes.push_back(mesh);
    const uint32_t material = addMaterial(scene, "grey", test::diffuse({0.5f, 0.5f, 0.5f}));
    for (int i = 0; i < 3; ++i) {
        Instance inst;
        inst.name = "grid " + std::to_string(i);
        inst.mesh = 0;
        inst.objectToWorld = trs({0.0f, 0.3f * float(i), 0.0f}, {0.0f, 20.0f * float(i), 0.0f}).toAffine();
        inst.materials = {material};
        scene.instances.push_back(inst);
    }
    return scene;
}

std::vector<Ray> randomRays(uint32_t count, uint32_t seed) {
    return test::downwardRays(count, seed, {1.5f, 1.0f, 1.5f}, 0.5f);
}

// Hits must agree exactly: both backends run the same float operations without contraction.
// Where two surfaces meet at exactly the same t (a box's faces at an edge), every walk gives
// the hit to the lower instance, then the lower primitive (tlas_traversal.h), so trees built by
// other builders should agree there too; such ties still count as agreement while rare, until
// a device run shows that none is left.
void expectSameHits(const std::vector<Hit>& a, const std::vector<Hit>& b, const char* what) {
    ASSERT_EQ(a.size(), b.size());
    size_t mismatches = 0, hits = 0, ties = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        hits += a[i].valid();
        const bool bothHit = a[i].valid() && b[i].valid();
        const bool tie = bothHit && a[i].t == b[i].t &&
                         (a[i].instance != b[i].instance || a[i].primitive != b[i].primitive);
        ties += tie;
        const bool same = tie || (a[i].instance == b[i].instance &&
                                  (!a[i].valid() || (a[i].primitive == b[i].primitive && a[i].t == b[i].t &&
                                                     a[i].u == b[i].u && a[i].v == b[i].v)));
        if (!same && mismatches++ < 5) {
            ADD_FAILURE() << what << ": ray " << i << ": instance " << a[i].instance << " vs "
                          << b[i].instance << ", primitive " << a[i].primitive << " vs " << b[i].primitive
                          << ", t " << a[i].t << " vs " << b[i].t;
        }
    }
    EXPECT_EQ(mismatches, 0u) << what;
    EXPECT_LE(ties, a.size() / 100) << what << ": too many equal-distance ties to be edges";
    if (ties)
        std::cout << "[ figures  ] " << what << ": " << ties << " equal-distance ties of " << a.size()
                  << " rays\n";
    EXPECT_GT(hits, a.size() / 4) << what << ": too few rays hit to test anything";
}

float maxAbsDifference(const std::vector<float>& a, const std::vector<float>& b) {
    float worst = 0.0f;
    for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::fabs(a[i] - b[i]));
    return worst;
}

// How a GPU image (RGBA) agrees with the CPU's at equal samples: the pixels where a channel
// differs by more than 1e-3 of the pixel's brightest CPU channel, and the ratio of the means.
struct CpuAgreement {
    size_t differingPixels = 0;
    double pixels = 0.0;
    double meansRatio = 0.0;
};
CpuAgreement agreementWithCpu(const std::vector<float>& cpu, const std::vector<float>& gpu) {
    CpuAgreement agreement;
    double sumCpu = 0.0, sumGpu = 0.0;
    for (size_t i = 0; i < cpu.size(); i += 4) {
        const float scale = std::max(1e-3f, std::max(cpu[i], std::max(cpu[i + 1], cpu[i + 2])));
        bool differs = false;
        for (size_t c = 0; c < 3; ++c) {
            sumCpu += cpu[i + c];
            sumGpu += gpu[i + c];
            differs |= std::fabs(cpu[i + c] - gpu[i + c]) > 1e-3f * scale;
        }
        agreement.differingPixels += differs ? 1 : 0;
    }
    agreement.pixels = double(cpu.size() / 4);
    agreement.meansRatio = sumGpu / sumCpu;
    return agreement;
}

TEST(CudaBackend, CameraRaysHitWhatTheCpuHits) {
    PT_REQUIRE_CUDA_DEVICE();
    const Scene scene = cornell(128);
    const RenderCamera camera = makeRenderCamera(scene.camera, 128, 128);
    std::vector<Ray> rays;
    for (uint32_t y = 0; y < 128; ++y) {
        for (uint32_t x = 0; x < 128; ++x)
            rays.push_back(generateCameraRay(camera, 128, 128, x, y, {0.5f, 0.5f}, {0.5f, 0.5f}));
    }
    CpuBackend cpu;
    cuda::CudaBackend gpu;
    cpu.sync(scene, SceneChanges::All, {});
    gpu.sync(scene, SceneChanges::All, {});
    std::vector<Hit> cpuHits, gpuHits;
    cpu.traceRays(rays, false, 1, &cpuHits);
    gpu.traceRays(rays, false, 1, &gpuHits);
    expectSameHits(cpuHits, gpuHits, "camera rays");
    std::vector<Hit> cpuAny, gpuAny;
    cpu.traceRays(rays, true, 1, &cpuAny);
    gpu.traceRays(rays, true, 1, &gpuAny);
    for (size_t i = 0; i < rays.size(); ++i) ASSERT_EQ(cpuAny[i].instance, gpuAny[i].instance) << "ray " << i;
}

// The ray-query kernel runs a persistent grid whose warps claim rays from a counter that each
// launch must leave at zero (persistent_grid.cuh). Sets of every size follow one another, one
// set of each size traced after another set of that size: a launch that found the counter
// spent would trace nothing and leave the earlier set's hits in the buffer. The largest set has
// more rays than the resident grid has threads, so warps claim several times; the smallest
// fill part of one warp. One instance and three take the two kernels (ray_query.cu).
TEST(CudaBackend, RayQueriesOfEverySizeTraceEveryRay) {
    PT_REQUIRE_CUDA_DEVICE();
    Scene threeInstances = bumpyGridScene(40, 7), oneInstance = threeInstances;
    oneInstance.instances.resize(1);
    for (const Scene& scene : {oneInstance, threeInstances}) {
        SCOPED_TRACE(std::to_string(scene.instances.size()) + " instances");
        CpuBackend cpu;
        cuda::CudaBackend gpu;
        cpu.sync(scene, SceneChanges::All, {});
        gpu.sync(scene, SceneChanges::All, {});
        uint32_t seed = 100;
        size_t rayCount = 0, hitCount = 0;
        for (uint32_t count : {1u, 31u, 33u, 4097u, 600001u, 5u}) {
            for (int repeat = 0; repeat < 2; ++repeat) {
                SCOPED_TRACE(std::to_string(count) + " rays");
                const std::vector<Ray> rays = randomRays(count, seed++);
                for (bool anyHit : {false, true}) {
                    std::vector<Hit> cpuHits, gpuHits;
                    cpu.traceRays(rays, anyHit, 1, &cpuHits);
                    gpu.traceRays(rays, anyHit, 2, &gpuHits);
                    ASSERT_EQ(cpuHits.size(), gpuHits.size());
                    // Where, exactly: a tie between coincident faces shares its t (expectSameHits).
                    for (size_t i = 0; i < rays.size(); ++i) {
                        ASSERT_EQ(cpuHits[i].valid(), gpuHits[i].valid())
                            << "ray " << i << " any hit " << anyHit;
                        if (!anyHit && cpuHits[i].valid()) {
                            ASSERT_EQ(cpuHits[i].t, gpuHits[i].t) << "ray " << i;
                        }
                    }
                    if (!anyHit) {
                        rayCount += rays.size();
                        hitCount += size_t(std::count_if(cpuHits.begin(), cpuHits.end(),
                                                         [](const Hit& h) { return h.valid(); }));
                    }
                }
            }
        }
        EXPECT_GT(hitCount, rayCount / 4) << "too few rays hit to test anything";
    }
}

TEST(CudaBackend, BeautyMatchesTheCpuAtEqualSamples) {
    PT_REQUIRE_CUDA_DEVICE();
    const Scene scene = cornell(64);
    CpuBackend cpuBackend;
    cuda::CudaBackend gpuBackend;
    const std::vector<float> cpu = renderWith(cpuBackend, scene, 64);
    const std::vector<float> gpu = renderWith(gpuBackend, scene, 64);
    // Same sample numbers, same arithmetic: pixels differ only where a transcendental function
    // rounded differently and a path took another turn.
    size_t differing = 0;
    double sumCpu = 0.0, sumGpu = 0.0;
    for (size_t i = 0; i < cpu.size(); i += 4) {
        for (int c = 0; c < 3; ++c) {
            sumCpu += cpu[i + c];
            sumGpu += gpu[i + c];
        }
        const float scale = std::max(1e-3f, std::max(cpu[i], std::max(cpu[i + 1], cpu[i + 2])));
        for (int c = 0; c < 3; ++c) {
            if (std::fabs(cpu[i + c] - gpu[i + c]) > 1e-3f * scale) {
                ++differing;
                break;
            }
        }
    }
    const double pixels = double(cpu.size() / 4);
    std::cout << "[ figures  ] CPU vs CUDA, Cornell 64x64 at 64 spp: " << differing << " of " << pixels
              << " pixels differ by more than 1e-3 relative; largest deviation " << maxAbsDifference(cpu, gpu)
              << "; image means " << sumCpu / pixels / 3 << " vs " << sumGpu / pixels / 3 << "\n";
    EXPECT_LT(double(differing), 0.02 * pixels);
    EXPECT_NEAR(sumGpu / sumCpu, 1.0, 2e-3);
}

// An 8-bit texture of `size` x `size` texels of pseudo-random RGBA, bilinear and repeating.
int32_t addNoiseTexture(Scene& scene, uint32_t size, uint32_t seed) {
    Texture t;
    t.name = "noise " + std::to_string(seed);
    t.width = t.height = size;
    std::mt19937 rng(seed);
    for (uint32_t i = 0; i < size * size * 4; ++i) t.texels8.push_back(uint8_t(rng() & 0xffu));
    scene.textures.push_back(t);
    return int32_t(scene.textures.size() - 1);
}

// Every kernel variant that can render the scene renders what the CPU renders, at equal
// samples: the specialised code leaves out only what the scene does not use. The Cornell box
// (smooth glass, mirror, area light, eight instances) runs every variant with instances, and
// a glossy grid of one instance under a sky, with base-colour (sRGB) and metallic-roughness
// textures tiled over it, every variant with glossy lobes. A variant that leaves out a feature
// the scene has is refused: the leanest covering one runs, as the stats say.
TEST(CudaBackend, EveryKernelVariantMatchesTheCpu) {
    PT_REQUIRE_CUDA_DEVICE();
    Scene oneInstance = bumpyGridScene(16, 3);
    oneInstance.instances.resize(1);
    Mesh& grid = oneInstance.meshes[0];
    for (const Vec3& p : grid.positions) grid.uvs.push_back({1.5f * p.x, 1.5f * p.z});
    const int32_t baseColor = addNoiseTexture(oneInstance, 8, 5),
                  metallicRoughness = addNoiseTexture(oneInstance, 4, 6);
    for (NamedMaterial& m : oneInstance.materials) {  // glossy: half metal, rough
        m.params.metallic = 0.5f;
        m.params.roughness = 0.4f;
        m.params.specular = 1.0f;
        m.params.baseColorTexture.texture = baseColor;
        m.params.metallicRoughnessTexture.texture = metallicRoughness;
    }
    for (const Scene& scene : {cornell(48), oneInstance}) {
        CpuBackend cpuBackend;
        const std::vector<float> cpu = renderWith(cpuBackend, scene, 16);
        const FeatureSet features = cpuBackend.stats().features;
        cuda::CudaBackend gpuBackend;
        int covering = 0;
        for (const cuda::KernelVariant& v : cuda::kKernelVariants) {
            IntegratorToggles t;
            t.kernelVariant = v.name;
            const std::vector<float> gpu = renderWith(gpuBackend, scene, 16, t);
            const bool covers = (features & ~v.features) == 0u;
            covering += covers ? 1 : 0;
            if (!covers) {
                EXPECT_NE(gpuBackend.stats().kernelVariant, v.name)
                    << "features " << describeFeatures(features);
                continue;
            }
            EXPECT_EQ(gpuBackend.stats().kernelVariant, v.name);
            const CpuAgreement a = agreementWithCpu(cpu, gpu);
            std::cout << "[ figures  ] variant " << v.name << ", " << scene.instances.size()
                      << " instance(s): " << a.differingPixels << " of " << a.pixels
                      << " pixels differ from the CPU by more than 1e-3\n";
            EXPECT_LT(double(a.differingPixels), 0.02 * a.pixels) << v.name;
            EXPECT_NEAR(a.meansRatio, 1.0, 2e-3) << v.name;
        }
        // Cornell: lean, glossy, textured, layered, full; the glossy grid: glossy-single and up.
        EXPECT_GE(covering, 5) << describeFeatures(features);
    }
}

// KHR_materials_unlit, _diffuse_transmission and _sheen on the GPU: the Cornell box with its
// red wall unlit (the camera and every bounce see its colour, nothing lights it), its white
// surfaces letting 40% through diffusely and its green wall velvet renders as on the CPU at
// equal samples, on the leanest variant that covers it ("full": diffuse transmission and sheen
// are rare lobes; unlit alone runs "textured").
TEST(CudaBackend, UnlitDiffuseTransmissionAndSheenMatchTheCpu) {
    PT_REQUIRE_CUDA_DEVICE();
    Scene scene = cornell(48);
    scene.materials[size_t(scene.findMaterial("red"))].params.unlit = 1;
    Material& white = scene.materials[size_t(scene.findMaterial("white"))].params;
    white.diffuseTransmission = 0.4f;
    white.diffuseTransmissionColor = {0.9f, 0.8f, 0.7f};
    Material& green = scene.materials[size_t(scene.findMaterial("green"))].params;
    green.sheenColor = {1.0f, 0.5f, 0.8f};
    green.sheenRoughness = 0.4f;
    CpuBackend cpuBackend;
    cuda::CudaBackend gpuBackend;
    const std::vector<float> cpu = renderWith(cpuBackend, scene, 16);
    const std::vector<float> gpu = renderWith(gpuBackend, scene, 16);
    ASSERT_NE(cpuBackend.stats().features & feature::kUnlit, 0u);
    ASSERT_NE(cpuBackend.stats().features & feature::kDiffuseTransmission, 0u);
    ASSERT_NE(cpuBackend.stats().features & feature::kSheen, 0u);
    EXPECT_EQ(gpuBackend.stats().kernelVariant, "full");
    const FeatureSet withoutRareLobes = cpuBackend.stats().features & ~feature::kRareLobes;
    EXPECT_STREQ(cuda::kKernelVariants[cuda::chooseKernelVariant(withoutRareLobes)].name, "textured");
    const double meansRatio = agreementWithCpu(cpu, gpu).meansRatio;
    std::cout << "[ figures  ] unlit red wall, diffusely transmitting white, velvet green, Cornell 48x48 "
                 "at 16 spp: largest CPU/CUDA deviation "
              << maxAbsDifference(cpu, gpu) << ", image means ratio " << meansRatio << "\n";
    EXPECT_NEAR(meansRatio, 1.0, 2e-3);
    // The wall's middle row, seen directly: exactly its colour on both.
    const size_t pixel = (24 * 48 + 2) * 4;
    EXPECT_NEAR(gpu[pixel], 0.63f, 1e-5f);
    EXPECT_NEAR(gpu[pixel + 1], 0.065f, 1e-5f);
    EXPECT_NEAR(cpu[pixel + 2], gpu[pixel + 2], 1e-5f);
}

// KHR_materials_anisotropy, _iridescence and _dispersion on the GPU: the Cornell box's mirror box
// brushed (anisotropic, turned), its white walls under a thin film, its glass sphere dispersive,
// renders as on the CPU at equal samples ("full": all three are rare lobes).
TEST(CudaBackend, AnisotropyIridescenceAndDispersionMatchTheCpu) {
    PT_REQUIRE_CUDA_DEVICE();
    Scene scene = cornell(48);
    Material& mirror = scene.materials[size_t(scene.findMaterial("mirror"))].params;
    mirror.roughness = 0.3f;
    mirror.anisotropyStrength = 0.8f;
    mirror.anisotropyRotation = 0.6f;
    Material& white = scene.materials[size_t(scene.findMaterial("white"))].params;
    white.specular = 1.0f;
    white.iridescence = 1.0f;
    white.iridescenceIor = 1.8f;
    white.iridescenceThicknessMax = 350.0f;
    scene.materials[size_t(scene.findMaterial("glass"))].params.dispersion = 2.0f;
    CpuBackend cpuBackend;
    cuda::CudaBackend gpuBackend;
    const std::vector<float> cpu = renderWith(cpuBackend, scene, 16);
    const std::vector<float> gpu = renderWith(gpuBackend, scene, 16);
    for (const FeatureSet bit : {feature::kAnisotropy, feature::kIridescence, feature::kDispersion})
        ASSERT_NE(cpuBackend.stats().features & bit, 0u) << featureName(bit);
    EXPECT_EQ(gpuBackend.stats().kernelVariant, "full");
    const CpuAgreement a = agreementWithCpu(cpu, gpu);
    std::cout
        << "[ figures  ] brushed mirror box, iridescent white, dispersive glass, Cornell 48x48 at 16 spp: "
        << a.differingPixels << " of " << a.pixels << " pixels differ from the CPU by more than 1e-3, "
        << "largest deviation " << maxAbsDifference(cpu, gpu) << ", image means ratio " << a.meansRatio
        << "\n";
    EXPECT_LT(double(a.differingPixels), 0.02 * a.pixels);
    EXPECT_NEAR(a.meansRatio, 1.0, 2e-3);
}

// Scattering media on the GPU (issue 15): the Cornell box's glass sphere made wax (random-walk
// subsurface), its mirror box a box of index-matched fog, render as on the CPU at equal samples.
// Pixels whose paths take no long walk match to rounding; a walk of hundreds of steps is chaotic
// (an ulp of difference in one step sends the rest elsewhere), so there the images agree in the
// mean (5.6% of the pixels differed by more than 1e-3 on the H100, the means by 1e-4).
TEST(CudaBackend, SubsurfaceAndFogMatchTheCpu) {
    PT_REQUIRE_CUDA_DEVICE();
    Scene scene = cornell(48);
    Material& glass = scene.materials[size_t(scene.findMaterial("glass"))].params;
    glass.transmission = 0.0f;
    glass.subsurface = 1.0f;
    glass.subsurfaceColor = {0.9f, 0.6f, 0.4f};
    glass.subsurfaceRadius = 0.1f;
    glass.roughness = 0.3f;
    Material& fog = scene.materials[size_t(scene.findMaterial("mirror"))].params;
    fog = Material{};
    fog.baseColor = Vec3(1.0f);
    fog.transmission = 1.0f;
    fog.ior = 1.0f;
    fog.thickness = 1.0f;
    fog.attenuationDistance = 0.5f;
    fog.attenuationColor = {0.4f, 0.5f, 0.6f};
    fog.scatterColor = Vec3(0.9f);
    fog.scatterAnisotropy = 0.4f;
    CpuBackend cpuBackend;
    cuda::CudaBackend gpuBackend;
    const std::vector<float> cpu = renderWith(cpuBackend, scene, 16);
    const std::vector<float> gpu = renderWith(gpuBackend, scene, 16);
    for (const FeatureSet bit : {feature::kScatteringMedia, feature::kIndexMatchedBoundaries})
        ASSERT_NE(cpuBackend.stats().features & bit, 0u) << featureName(bit);
    EXPECT_EQ(gpuBackend.stats().kernelVariant, "full");
    const CpuAgreement a = agreementWithCpu(cpu, gpu);
    std::cout << "[ figures  ] wax sphere, fog box, Cornell 48x48 at 16 spp: " << a.differingPixels << " of "
              << a.pixels << " pixels differ from the CPU by more than 1e-3, largest deviation "
              << maxAbsDifference(cpu, gpu) << ", image means ratio " << a.meansRatio << "\n";
    EXPECT_LT(double(a.differingPixels), 0.12 * a.pixels);
    EXPECT_NEAR(a.meansRatio, 1.0, 2e-3);
}

// scenes/extensions.json (a sheen cloth with a colour/roughness texture, a diffusely
// transmitting leaf, glTF files of this project) renders on the GPU as on the CPU.
TEST(CudaBackend, ExtensionSamplesMatchTheCpu) {
    PT_REQUIRE_CUDA_DEVICE();
    Scene scene = test::loadSceneOrFail(test::projectPath("scenes/extensions.json"));
    scene.render.width = 96;
    scene.render.height = 60;
    CpuBackend cpuBackend;
    cuda::CudaBackend gpuBackend;
    const std::vector<float> cpu = renderWith(cpuBackend, scene, 16);
    const std::vector<float> gpu = renderWith(gpuBackend, scene, 16);
    ASSERT_NE(cpuBackend.stats().features & feature::kSheen, 0u);
    const CpuAgreement a = agreementWithCpu(cpu, gpu);
    std::cout << "[ figures  ] extension samples 96x60 at 16 spp on " << gpuBackend.stats().kernelVariant
              << ": " << a.differingPixels << " of " << a.pixels
              << " pixels differ from the CPU by more than 1e-3, largest deviation "
              << maxAbsDifference(cpu, gpu) << ", image means ratio " << a.meansRatio << "\n";
    EXPECT_LT(double(a.differingPixels), 0.02 * a.pixels);
    EXPECT_NEAR(a.meansRatio, 1.0, 2e-3);
}

// Independent samples (other seeds) on the GPU against the CPU: an unbiasedness check by a
// z-test on 8x8 pixel blocks, with the variance taken from the spread of batch means.
TEST(CudaBackend, BeautyAgreesWithTheCpuStatistically) {
    PT_REQUIRE_CUDA_DEVICE();
    Scene scene = cornell(64, 6);
    constexpr uint32_t kBatches = 8, kSpp = 32, kBlock = 8, kBlocks = (64 / kBlock) * (64 / kBlock);
    std::vector<std::vector<double>> cpuMeans(kBlocks), gpuMeans(kBlocks);
    CpuBackend cpuBackend;
    cuda::CudaBackend gpuBackend;
    for (uint32_t batch = 0; batch < kBatches; ++batch) {
        for (int backendIndex = 0; backendIndex < 2; ++backendIndex) {
            scene.render.seed = backendIndex == 0 ? batch : 1000 + batch;
            Backend& backend = backendIndex == 0 ? static_cast<Backend&>(cpuBackend) : gpuBackend;
            const std::vector<float> image = renderWith(backend, scene, kSpp);
            for (uint32_t b = 0; b < kBlocks; ++b) {
                const uint32_t bx = (b % (64 / kBlock)) * kBlock, by = (b / (64 / kBlock)) * kBlock;
                double sum = 0.0;
                for (uint32_t y = by; y < by + kBlock; ++y) {
                    for (uint32_t x = bx; x < bx + kBlock; ++x) {
                        const float* p = &image[(size_t(y) * 64 + x) * 4];
                        sum += p[0] + p[1] + p[2];
                    }
                }
                (backendIndex == 0 ? cpuMeans : gpuMeans)[b].push_back(sum / (kBlock * kBlock * 3));
            }
        }
    }
    const auto meanVar = [](const std::vector<double>& v, double& mean, double& varOfMean) {
        mean = 0.0;
        for (double x : v) mean += x;
        mean /= double(v.size());
        double var = 0.0;
        for (double x : v) var += (x - mean) * (x - mean);
        varOfMean = var / double(v.size() - 1) / double(v.size());
    };
    uint32_t outliers = 0;
    double worstZ = 0.0;
    for (uint32_t b = 0; b < kBlocks; ++b) {
        double mc, vc, mg, vg;
        meanVar(cpuMeans[b], mc, vc);
        meanVar(gpuMeans[b], mg, vg);
        const double z = (mg - mc) / std::sqrt(vc + vg + 1e-12);
        worstZ = std::max(worstZ, std::fabs(z));
        outliers += std::fabs(z) > 4.0;
    }
    std::cout << "[ figures  ] block z-test, CPU vs CUDA (independent seeds): largest |z| " << worstZ << ", "
              << outliers << " of " << kBlocks << " blocks over 4\n";
    // A t-distribution with 14 degrees of freedom puts about 0.1% of blocks past |z| = 4.
    EXPECT_LE(outliers, 1u);
}

// The wavefront schedule, named (not chosen by the auto schedule).
IntegratorToggles wavefrontToggles() {
    IntegratorToggles t;
    t.autoSchedule = false;
    t.megakernel = false;
    return t;
}

// Scheduling toggles change the order of work, never a path's arithmetic: images stay equal.
TEST(CudaBackend, SchedulingTogglesLeaveTheImageUnchanged) {
    PT_REQUIRE_CUDA_DEVICE();
    const Scene scene = cornell(64);
    cuda::CudaBackend backend;
    IntegratorToggles base = wavefrontToggles();  // the wavefront, whose scheduling the toggles change
    base.pixelJitter = false;                     // so that the first-hit cache applies
    base.firstHitCache = false;
    const std::vector<float> reference = renderWith(backend, scene, 16, base, 2);
    struct Variant {
        const char* name;
        IntegratorToggles toggles;
    };
    std::vector<Variant> variants;
    IntegratorToggles t = base;
    t.megakernel = true;
    variants.push_back({"megakernel", t});
    t.pathRegeneration = !t.pathRegeneration;
    variants.push_back(
        {t.pathRegeneration ? "megakernel with path regeneration" : "megakernel without path regeneration",
         t});
    t = base;
    t.streamCompaction = false;
    variants.push_back({"no compaction", t});
    t = base;
    t.materialSort = true;
    variants.push_back({"material sort", t});
    t = base;
    t.materialSort = true;
    t.streamCompaction = false;
    variants.push_back({"material sort without compaction", t});
    t = base;
    t.firstHitCache = true;
    variants.push_back({"first-hit cache", t});
    for (const Variant& v : variants) {
        const std::vector<float> image = renderWith(backend, scene, 16, v.toggles, 2);
        const float worst = maxAbsDifference(reference, image);
        std::cout << "[ figures  ] " << v.name << ": largest deviation from the default " << worst << "\n";
        EXPECT_LE(worst, 1e-5f) << v.name;
    }
    // The first-hit cache must actually be used once it applies.
    IntegratorToggles cached = base;
    cached.firstHitCache = true;
    backend.setToggles(cached);
    for (const ToggleState& s : backend.toggleStates()) {
        if (s.name == "first_hit_cache") {
            EXPECT_TRUE(s.active) << s.note;
        }
    }
    backend.render(4);
    backend.render(4);
    const uint64_t raysCached = backend.stats().rays;
    backend.setToggles(base);
    backend.render(4);
    backend.render(4);
    EXPECT_LT(raysCached, backend.stats().rays) << "a cached first hit traces fewer rays";
    // The compressed 8-wide nodes (a new compile), and the auto schedule over them, whose trial runs each
    // schedule with each walk: a pass a wave, so that all four ways run and then the fastest.
    IntegratorToggles wide = base;
    wide.gpuWideBvh = true;
    EXPECT_LE(maxAbsDifference(reference, renderWith(backend, scene, 16, wide, 2)), 1e-5f)
        << "compressed walk";
    EXPECT_EQ(backend.stats().walk, "compressed");
    wide.autoSchedule = true;
    EXPECT_LE(maxAbsDifference(reference, renderWith(backend, scene, 16, wide, 16)), 1e-5f)
        << "auto schedule, both walks";
    EXPECT_NE(backend.stats().walk, "") << "the trial should have timed both walks and chosen one";
}

// The megakernel's threads stay resident and take paths from a counter; with regeneration a
// thread takes its next path as soon as one ends. Enough paths that each thread takes many
// (256x256 at 16 samples a pass, against about 135,000 resident threads on an H100), so a lost,
// doubled or misplaced path would change the image: both orders equal the wavefront's.
TEST(CudaBackend, PathRegenerationTracesEveryPathOnce) {
    PT_REQUIRE_CUDA_DEVICE();
    const Scene scene = cornell(256);
    cuda::CudaBackend backend;
    const IntegratorToggles wavefront = wavefrontToggles();
    const std::vector<float> reference = renderWith(backend, scene, 16, wavefront);
    std::vector<uint64_t> rays;
    for (const bool regeneration : {true, false}) {
        IntegratorToggles t = wavefront;
        t.megakernel = true;
        t.pathRegeneration = regeneration;
        const std::vector<float> image = renderWith(backend, scene, 16, t);
        const float worst = maxAbsDifference(reference, image);
        rays.push_back(backend.stats().rays);
        std::cout << "[ figures  ] megakernel, regeneration " << (regeneration ? "on" : "off")
                  << ": largest deviation from the wavefront " << worst << ", " << rays.back() << " rays\n";
        EXPECT_LE(worst, 1e-5f) << "regeneration " << regeneration;
    }
    EXPECT_EQ(rays[0], rays[1]);
}

TEST(CudaBackend, RussianRouletteKeepsTheMean) {
    PT_REQUIRE_CUDA_DEVICE();
    const Scene scene = cornell(32);
    cuda::CudaBackend backend;
    IntegratorToggles noRoulette;
    noRoulette.russianRoulette = false;
    const std::vector<float> with = renderWith(backend, scene, 1024);
    const std::vector<float> without = renderWith(backend, scene, 1024, noRoulette);
    double a = 0.0, b = 0.0;
    for (size_t i = 0; i < with.size(); i += 4) {
        a += with[i] + with[i + 1] + with[i + 2];
        b += without[i] + without[i + 1] + without[i + 2];
    }
    EXPECT_NEAR(a / b, 1.0, 0.01);
}

TEST(CudaBackend, RefitTracesLikeARebuild) {
    PT_REQUIRE_CUDA_DEVICE();
    Scene scene = bumpyGridScene(200, 1);
    cuda::CudaBackend refitted;
    IntegratorToggles neverRebuild;
    neverRebuild.rebuildSahRatio = 1e9f;
    refitted.setToggles(neverRebuild);
    refitted.sync(scene, SceneChanges::All, {});
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> jitter(-0.02f, 0.02f);
    for (Vec3& p : scene.meshes[0].positions) p += Vec3(jitter(rng), 4.0f * jitter(rng), jitter(rng));
    const SyncReport report = refitted.sync(scene, SceneChanges::Geometry, {});
    EXPECT_EQ(report.action, "refit");
    EXPECT_GE(refitted.blasSahCost(0), refitted.blasBuiltSahCost(0) * 0.99f);

    cuda::CudaBackend rebuilt;
    rebuilt.sync(scene, SceneChanges::All, {});
    CpuBackend cpu;
    cpu.sync(scene, SceneChanges::All, {});
    const std::vector<Ray> rays = randomRays(200000, 3);
    std::vector<Hit> a, b, c;
    refitted.traceRays(rays, false, 1, &a);
    rebuilt.traceRays(rays, false, 1, &b);
    cpu.traceRays(rays, false, 1, &c);
    expectSameHits(b, a, "refit vs rebuild");
    expectSameHits(c, a, "refit vs CPU");
}

TEST(CudaBackend, DegradedRefitRebuildsOnTheGpu) {
    PT_REQUIRE_CUDA_DEVICE();
    Scene scene = bumpyGridScene(100, 2);
    cuda::CudaBackend backend;
    backend.sync(scene, SceneChanges::All, {});
    // Shuffle vertices across the grid: boxes of the old tree now span the whole mesh.
    std::mt19937 rng(9);
    std::shuffle(scene.meshes[0].positions.begin(), scene.meshes[0].positions.end(), rng);
    const SyncReport report = backend.sync(scene, SceneChanges::Geometry, {});
    EXPECT_EQ(report.action, "rebuild");
    EXPECT_LE(backend.blasSahCost(0), backend.blasBuiltSahCost(0) * 1.0001f);
    CpuBackend cpu;
    cpu.sync(scene, SceneChanges::All, {});
    const std::vector<Ray> rays = randomRays(100000, 4);
    std::vector<Hit> a, b;
    backend.traceRays(rays, false, 1, &a);
    cpu.traceRays(rays, false, 1, &b);
    // Exact t and barycentrics; ties between coincident triangles may pick either, so compare
    // the distance only.
    size_t mismatches = 0;
    for (size_t i = 0; i < a.size(); ++i) mismatches += a[i].instance != b[i].instance || a[i].t != b[i].t;
    EXPECT_EQ(mismatches, 0u);
}

// Instanced (each grid its own BLAS) a move rebuilds the TLAS; merged (render/scene/
// merged_geometry.h) the moved grid's world-space copies are rewritten and the merged BLAS
// refitted. Either way the rays see what a fresh build shows them.
void expectLeastWorkForEachEdit(bool merge) {
    SCOPED_TRACE(merge ? "merged" : "instanced");
    Scene scene = bumpyGridScene(20, 3);
    IntegratorToggles toggles;
    toggles.mergeInstances = merge;
    cuda::CudaBackend backend;
    backend.setToggles(toggles);
    EXPECT_EQ(backend.sync(scene, SceneChanges::All, {}).action, "full build");
    scene.materials[0].params.roughness = 0.9f;
    EXPECT_EQ(backend.sync(scene, SceneChanges::Materials, {}).action, "materials");
    scene.instances[1].objectToWorld = trs({0.5f, 0.0f, 0.0f}).toAffine();
    EXPECT_EQ(backend.sync(scene, SceneChanges::Transforms, {}).action, merge ? "refit" : "TLAS");
    scene.camera.position.x += 0.1f;
    EXPECT_EQ(backend.sync(scene, SceneChanges::Camera, {}).action, "reset");
    backend.render(2);
    EXPECT_EQ(backend.sync(scene, SceneChanges::Display, {}).action, "nothing");
    EXPECT_EQ(backend.stats().samplesPerPixel, 2u) << "a display change keeps the accumulation";
    // Moving an instance must move what the rays see, exactly as a fresh build does.
    cuda::CudaBackend fresh;
    fresh.setToggles(toggles);
    fresh.sync(scene, SceneChanges::All, {});
    const std::vector<Ray> rays = randomRays(50000, 5);
    std::vector<Hit> a, b;
    backend.traceRays(rays, false, 1, &a);
    fresh.traceRays(rays, false, 1, &b);
    expectSameHits(b, a, "edit vs fresh build");
    // Hiding a merged instance collapses its copies; deleting one makes a new plan.
    const auto expectLikeAFreshBuild = [&](const char* what) {
        cuda::CudaBackend again;
        again.setToggles(toggles);
        again.sync(scene, SceneChanges::All, {});
        backend.traceRays(rays, false, 1, &a);
        again.traceRays(rays, false, 1, &b);
        expectSameHits(b, a, what);
    };
    scene.instances[0].visible = false;
    EXPECT_EQ(backend.sync(scene, SceneChanges::Transforms, {}).action, merge ? "refit" : "TLAS");
    expectLikeAFreshBuild("hide vs fresh build");
    scene.instances.pop_back();
    EXPECT_EQ(backend.sync(scene, SceneChanges::Transforms, {}).action, merge ? "full build" : "TLAS");
    expectLikeAFreshBuild("delete vs fresh build");
}

TEST(CudaBackend, SyncDoesTheLeastWorkAnEditNeeds) {
    PT_REQUIRE_CUDA_DEVICE();
    expectLeastWorkForEachEdit(false);
    expectLeastWorkForEachEdit(true);
}

TEST(CudaBackend, AMillionSamplesOfAConstantStayThatConstant) {
    PT_REQUIRE_CUDA_DEVICE();
    Scene scene;
    scene.render = {16, 16, 4, 1, 0};
    scene.environment.color = {0.7f, 0.3f, 0.1f};
    cuda::CudaBackend backend;
    const std::vector<float> image = renderWith(backend, scene, 1000000);
    for (size_t i = 0; i < image.size(); i += 4) {
        ASSERT_NEAR(image[i + 0], 0.7f, 0.7f * 1e-6f) << "pixel " << i / 4;
        ASSERT_NEAR(image[i + 1], 0.3f, 0.3f * 1e-6f) << "pixel " << i / 4;
        ASSERT_NEAR(image[i + 2], 0.1f, 0.1f * 1e-6f) << "pixel " << i / 4;
    }
}

TEST(CudaBackend, BruteForceFindsTheSameHits) {
    PT_REQUIRE_CUDA_DEVICE();
    const Scene scene = bumpyGridScene(60, 4);
    cuda::CudaBackend bvh, brute;
    IntegratorToggles off, instanced;
    off.bruteForce = true;
    brute.setToggles(off);
    instanced.mergeInstances = false;  // both in object space: bit-identical hits
    bvh.setToggles(instanced);
    bvh.sync(scene, SceneChanges::All, {});
    brute.sync(scene, SceneChanges::All, {});
    const std::vector<Ray> rays = randomRays(20000, 6);
    std::vector<Hit> a, b;
    bvh.traceRays(rays, false, 1, &a);
    brute.traceRays(rays, false, 1, &b);
    expectSameHits(b, a, "BVH vs brute force");
}

TEST(CudaBackend, ReportsWhyTheFirstHitCacheCannotApply) {
    PT_REQUIRE_CUDA_DEVICE();
    cuda::CudaBackend backend;
    IntegratorToggles wavefront;
    wavefront.autoSchedule = false;
    wavefront.megakernel = false;
    backend.setToggles(wavefront);
    backend.sync(cornell(16), SceneChanges::All, {});
    for (const ToggleState& s : backend.toggleStates()) {
        if (s.name != "first_hit_cache") continue;
        EXPECT_TRUE(s.requested);
        EXPECT_FALSE(s.active);
        EXPECT_NE(s.note.find("jitter"), std::string::npos) << s.note;
    }
}

// The editor's CUDA-GL interop path: the frame written into device memory is exactly what
// readBeauty hands to the host.
TEST(CudaBackend, DeviceFrameEqualsTheHostFrame) {
    PT_REQUIRE_CUDA_DEVICE();
    const Scene scene = cornell(48);
    cuda::CudaBackend backend;
    const std::vector<float> host = renderWith(backend, scene, 8);
    float* device = nullptr;
    ASSERT_EQ(cudaMalloc(&device, host.size() * sizeof(float)), cudaSuccess);
    ASSERT_TRUE(backend.copyBeautyToDevice(device));
    std::vector<float> copied(host.size());
    ASSERT_EQ(cudaMemcpy(copied.data(), device, copied.size() * sizeof(float), cudaMemcpyDeviceToHost),
              cudaSuccess);
    cudaFree(device);
    EXPECT_EQ(maxAbsDifference(host, copied), 0.0f);
    EXPECT_GT(*std::max_element(copied.begin(), copied.end()), 0.0f);
}

// The editor's interrupt (Backend::setInterruptFlag): a call for hours of waves stops at the
// next wave once the flag is up, and leaves an empty accumulation (no wave of it counts), so
// what follows renders as a fresh backend would.
TEST(CudaBackend, AnInterruptStopsBetweenWavesAndLeavesNoSamples) {
    PT_REQUIRE_CUDA_DEVICE();
    const Scene scene = cornell(256);
    const IntegratorToggles toggles = wavefrontToggles();
    cuda::CudaBackend backend;
    std::atomic<bool> interrupt{false};
    backend.setInterruptFlag(&interrupt);
    renderWith(backend, scene, 2, toggles);
    auto pass = std::async(std::launch::async, [&] { backend.render(100'000'000); });
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    interrupt = true;
    if (pass.wait_for(std::chrono::seconds(60)) != std::future_status::ready) {
        std::fprintf(stderr, "render() went on with the interrupt flag up\n");
        std::abort();  // the waves would hold the test process for hours
    }
    EXPECT_EQ(backend.stats().samplesPerPixel, 0u);
    interrupt = false;
    backend.render(4);
    std::vector<float> resumed;
    backend.readBeauty(resumed);
    cuda::CudaBackend fresh;
    const std::vector<float> expected = renderWith(fresh, scene, 4, toggles);
    EXPECT_EQ(maxAbsDifference(expected, resumed), 0.0f);
}

}  // namespace
}  // namespace pt
