// The CUDA traversal's compressed 8-wide BVH (render/bvh/compressed_wide_bvh.h): on the device
// it finds the hits the binary walk and the CPU find, closest and any, after a refit too, and
// its buffers exist only while the wide toggle is on, once the collapse behind the first frame
// has landed. Skips with a message without a device.
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
#include "soup_scene.h"
#include "support/scene_builder.h"

namespace pt {
namespace {

Scene soupScene(uint32_t triangles) { return test::soupScene(triangles, triangles / 2); }

// A fixed schedule, whose passes walk the compressed nodes wherever they exist, so that
// BackendStats::walk says whether any exist (the auto schedule's says what its trial chose).
IntegratorToggles walkedAsBuilt() {
    IntegratorToggles t;
    t.autoSchedule = false;
    return t;
}

TEST(CudaWideBvh, TheCompressedWalkFindsTheBinaryWalksAndTheCpusHits) {
    PT_REQUIRE_CUDA_DEVICE();
    const Scene scene = soupScene(40000);
    cuda::CudaBackend wide, binary;
    IntegratorToggles on = walkedAsBuilt();
    on.gpuWideBvh = true;
    IntegratorToggles off = walkedAsBuilt();
    off.gpuWideBvh = false;
    wide.setToggles(on);
    binary.setToggles(off);
    wide.sync(scene, SceneChanges::All, {});
    binary.sync(scene, SceneChanges::All, {});
    // The first frame walks the binary nodes: the compressed ones are collapsed behind it.
    EXPECT_EQ(test::bufferBytes(wide, "BLAS compressed 8-wide nodes"), 0u);
    EXPECT_EQ(wide.stats().walk, "");
    const std::vector<Ray> rays = test::soupRays(200000, 5);
    test::expectSameHits(wide, binary, rays, "before the compressed nodes land (GPU)");
    EXPECT_TRUE(wide.finishBackgroundWork().has_value()) << "nothing was collapsing behind the first frame";
    EXPECT_FALSE(binary.finishBackgroundWork().has_value()) << "collapsing with the toggle off";
    EXPECT_EQ(wide.stats().walk, "compressed");
    EXPECT_GT(test::bufferBytes(wide, "BLAS compressed 8-wide nodes"), 0u);
    EXPECT_EQ(test::bufferBytes(binary, "BLAS compressed 8-wide nodes"), 0u)
        << "allocated with the toggle off";
    EXPECT_EQ(test::bufferBytes(binary, "BLAS compressed sources (refit)"), 0u);
    EXPECT_EQ(test::bufferBytes(binary, "BLAS compressed leaf triangles"), 0u);
    EXPECT_GT(test::bufferBytes(wide, "BLAS compressed leaf triangles"), 0u);
    CpuBackend cpu;
    cpu.sync(scene, SceneChanges::All, {});
    test::expectSameHits(wide, binary, rays, "compressed vs binary (GPU)");
    test::expectSameHits(wide, cpu, rays, "compressed (GPU) vs CPU");
}

// Moved vertices refit the binary nodes on the device, and the compressed boxes follow. The
// edit's sync lands the compressed nodes first, as the collapse reads the compiled BLASes.
TEST(CudaWideBvh, ARefitRequantisesTheCompressedBoxes) {
    PT_REQUIRE_CUDA_DEVICE();
    Scene scene = soupScene(20000);
    cuda::CudaBackend edited;
    IntegratorToggles neverRebuild = walkedAsBuilt();
    neverRebuild.rebuildSahRatio = 1e9f;
    neverRebuild.gpuWideBvh = true;
    edited.setToggles(neverRebuild);
    edited.sync(scene, SceneChanges::All, {});
    for (Vec3& p : scene.meshes[0].positions) p = p * 1.3f + Vec3(0.0f, 0.4f, 0.0f);
    const SyncReport report = edited.sync(scene, SceneChanges::Geometry, {});
    EXPECT_EQ(report.action, "refit");
    EXPECT_EQ(edited.stats().walk, "compressed");
    CpuBackend cpu;
    cpu.sync(scene, SceneChanges::All, {});
    test::expectSameHits(edited, cpu, test::soupRays(200000, 6), "refitted compressed (GPU) vs CPU");
}

// A degraded refit rebuilds the BLAS on the GPU (an LBVH): its compressed form is dropped and
// the kernels walk the new binary nodes.
TEST(CudaWideBvh, AGpuRebuildFallsBackToTheBinaryWalk) {
    PT_REQUIRE_CUDA_DEVICE();
    Scene scene = soupScene(20000);
    cuda::CudaBackend edited;
    IntegratorToggles on = walkedAsBuilt();
    on.gpuWideBvh = true;
    edited.setToggles(on);
    edited.sync(scene, SceneChanges::All, {});
    std::mt19937 rng(9);
    std::shuffle(scene.meshes[0].positions.begin(), scene.meshes[0].positions.end(), rng);
    edited.finishBackgroundWork();
    EXPECT_EQ(edited.stats().walk, "compressed");
    EXPECT_EQ(edited.sync(scene, SceneChanges::Geometry, {}).action, "rebuild");
    CpuBackend cpu;
    cpu.sync(scene, SceneChanges::All, {});
    test::expectSameHits(edited, cpu, test::soupRays(200000, 7), "rebuilt (GPU, binary walk) vs CPU");
}

}  // namespace
}  // namespace pt
