// The CUDA traversal's compressed 8-wide BVH (render/bvh/compressed_wide_bvh.h): on the device
// it finds the hits the binary walk and the CPU find, closest and any, after a refit too, and
// its buffers exist only while the wide toggle is on. Skips with a message without a device.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "cuda_test_support.h"
#include "render/backend/cpu/cpu_backend.h"
#include "render/backend/cuda/cuda_backend.h"
#include "render/bvh/bvh_test_util.h"
#include "support/scene_builder.h"

namespace pt {
namespace {

// Two soups (one instanced twice), so the walk runs under the TLAS and on a lone BLAS too.
Scene soupScene(uint32_t triangles) {
    test::Rng rng(21);
    Scene scene;
    scene.render = {32, 32, 1, 4, 0};
    const uint32_t grey = test::addMaterial(scene, "grey", test::diffuse({0.5f, 0.5f, 0.5f}));
    scene.meshes.push_back(test::makeSoup(test::SoupKind::Uniform, triangles, rng));
    scene.meshes.push_back(test::makeSoup(test::SoupKind::Clustered, triangles / 2, rng));
    for (uint32_t i = 0; i < 3; ++i) {
        Instance inst;
        inst.name = "soup " + std::to_string(i);
        inst.mesh = i == 2 ? 1 : 0;
        inst.materials = {grey};
        inst.objectToWorld = translationTransform(Vec3(1.7f * float(i), 0.1f * float(i), 0.0f));
        scene.instances.push_back(inst);
    }
    return scene;
}

std::vector<Ray> soupRays(uint32_t count, uint32_t seed) {
    test::Rng rng(seed);
    std::vector<Ray> rays;
    for (uint32_t i = 0; i < count; ++i)
        rays.push_back(test::randomRay(rng, Vec3(-2.0f), Vec3(5.0f, 2.0f, 2.0f)));
    return rays;
}

uint64_t bufferBytes(const Backend& backend, const std::string& name) {
    for (const auto& [buffer, bytes] : backend.deviceMemoryByBuffer())
        if (buffer == name) return bytes;
    ADD_FAILURE() << "no buffer named " << name;
    return 0;
}

// Closest and any hits of `rays` in `a` and `b` agree: the same instance and t, bit for bit.
void expectSameHits(Backend& a, Backend& b, const std::vector<Ray>& rays, const char* what) {
    for (const bool anyHit : {false, true}) {
        std::vector<Hit> ha, hb;
        a.traceRays(rays, anyHit, 1, &ha);
        b.traceRays(rays, anyHit, 1, &hb);
        ASSERT_EQ(ha.size(), hb.size());
        size_t mismatches = 0, hits = 0;
        for (size_t i = 0; i < ha.size(); ++i) {
            hits += ha[i].valid();
            mismatches += ha[i].valid() != hb[i].valid() ||
                          (!anyHit && (ha[i].instance != hb[i].instance || ha[i].t != hb[i].t));
        }
        EXPECT_EQ(mismatches, 0u) << what << (anyHit ? ", any hit" : ", closest hit");
        EXPECT_GT(hits, ha.size() / 5) << what << ": too few rays hit to test anything";
    }
}

TEST(CudaWideBvh, TheCompressedWalkFindsTheBinaryWalksAndTheCpusHits) {
    PT_REQUIRE_CUDA_DEVICE();
    const Scene scene = soupScene(40000);
    cuda::CudaBackend wide, binary;
    IntegratorToggles on;
    on.gpuWideBvh = true;
    wide.setToggles(on);
    wide.sync(scene, SceneChanges::All, {});
    binary.sync(scene, SceneChanges::All, {});
    EXPECT_GT(bufferBytes(wide, "BLAS compressed 8-wide nodes"), 0u);
    EXPECT_EQ(bufferBytes(binary, "BLAS compressed 8-wide nodes"), 0u) << "allocated with the toggle off";
    EXPECT_EQ(bufferBytes(binary, "BLAS compressed sources (refit)"), 0u);
    CpuBackend cpu;
    cpu.sync(scene, SceneChanges::All, {});
    const std::vector<Ray> rays = soupRays(200000, 5);
    expectSameHits(wide, binary, rays, "compressed vs binary (GPU)");
    expectSameHits(wide, cpu, rays, "compressed (GPU) vs CPU");
}

// Moved vertices refit the binary nodes on the device, and the compressed boxes follow.
TEST(CudaWideBvh, ARefitRequantisesTheCompressedBoxes) {
    PT_REQUIRE_CUDA_DEVICE();
    Scene scene = soupScene(20000);
    cuda::CudaBackend edited;
    IntegratorToggles neverRebuild;
    neverRebuild.rebuildSahRatio = 1e9f;
    neverRebuild.gpuWideBvh = true;
    edited.setToggles(neverRebuild);
    edited.sync(scene, SceneChanges::All, {});
    for (Vec3& p : scene.meshes[0].positions) p = p * 1.3f + Vec3(0.0f, 0.4f, 0.0f);
    const SyncReport report = edited.sync(scene, SceneChanges::Geometry, {});
    EXPECT_EQ(report.action, "refit");
    CpuBackend cpu;
    cpu.sync(scene, SceneChanges::All, {});
    expectSameHits(edited, cpu, soupRays(200000, 6), "refitted compressed (GPU) vs CPU");
}

// A degraded refit rebuilds the BLAS on the GPU (an LBVH): its compressed form is dropped and
// the kernels walk the new binary nodes.
TEST(CudaWideBvh, AGpuRebuildFallsBackToTheBinaryWalk) {
    PT_REQUIRE_CUDA_DEVICE();
    Scene scene = soupScene(20000);
    cuda::CudaBackend edited;
    IntegratorToggles on;
    on.gpuWideBvh = true;
    edited.setToggles(on);
    edited.sync(scene, SceneChanges::All, {});
    std::mt19937 rng(9);
    std::shuffle(scene.meshes[0].positions.begin(), scene.meshes[0].positions.end(), rng);
    EXPECT_EQ(edited.sync(scene, SceneChanges::Geometry, {}).action, "rebuild");
    CpuBackend cpu;
    cpu.sync(scene, SceneChanges::All, {});
    expectSameHits(edited, cpu, soupRays(200000, 7), "rebuilt (GPU, binary walk) vs CPU");
}

}  // namespace
}  // namespace pt
