// The first frame of a large mesh from a BVH built on the GPU (IntegratorToggles::gpuFirstBuild):
// the sync builds a tree on the device (H-PLOC, or an LBVH without gpuPloc) instead of waiting for
// the host's SAH tree, which
// builds on a thread behind it and is swapped in when done. No hit and no pixel changes on the
// way, and a tree that lands after an edit is refitted to it. Skips without a device.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "cuda_test_support.h"
#include "render/backend/cpu/cpu_backend.h"
#include "render/backend/cuda/cuda_backend.h"
#include "soup_scene.h"
#include "support/scene_builder.h"

namespace pt {
namespace {

constexpr const char* kGpuFirstBuildStep = "build BLAS (GPU H-PLOC; SAH on the host behind it)";
constexpr const char* kLbvhFirstBuildStep = "build BLAS (GPU LBVH; SAH on the host behind it)";

// A soup over the GPU first build's threshold (1 << 18 primitives), drawn twice, and a small
// one below it: one deferred BLAS under the TLAS beside one built on the host.
Scene largeSoupScene() {
    Scene scene = test::soupScene(300000, 3000);
    scene.render = {48, 32, 1, 4, 0};
    return scene;
}

bool hasStep(const SyncReport& report, const std::string& name) {
    return std::any_of(report.steps.begin(), report.steps.end(),
                       [&](const SyncStep& s) { return s.name == name; });
}

// One schedule for both backends: the auto schedule's trial would run different kernels.
IntegratorToggles fixedSchedule(bool gpuFirstBuild) {
    IntegratorToggles t;
    t.autoSchedule = false;
    t.gpuFirstBuild = gpuFirstBuild;
    return t;
}

// A first build of `scene` with `toggles` in `backend`, which must take the sync step `step`;
// returns the SAH cost of its first BLAS.
float firstBuildCost(cuda::CudaBackend& backend, const Scene& scene, const IntegratorToggles& toggles,
                     const char* step) {
    backend.setToggles(toggles);
    EXPECT_TRUE(hasStep(backend.sync(scene, SceneChanges::All, {}), step)) << step;
    return backend.blasSahCost(0);
}

// A first build of `scene` whose edits will refit and never rebuild. By LBVH: its cost is
// above the SAH tree's (H-PLOC's may be below), so a fall in cost shows that tree landed.
void syncForRefits(cuda::CudaBackend& backend, const Scene& scene) {
    IntegratorToggles neverRebuild = fixedSchedule(true);
    neverRebuild.rebuildSahRatio = 1e9f;
    neverRebuild.gpuPloc = false;
    backend.setToggles(neverRebuild);
    backend.sync(scene, SceneChanges::All, {});
}

TEST(CudaFirstBuild, TheFirstFrameWalksAGpuBuildAndTheSahTreeLandsBehindIt) {
    PT_REQUIRE_CUDA_DEVICE();
    const Scene scene = largeSoupScene();
    cuda::CudaBackend deferred, hostBuilt;
    deferred.setToggles(fixedSchedule(true));
    hostBuilt.setToggles(fixedSchedule(false));
    EXPECT_TRUE(hasStep(deferred.sync(scene, SceneChanges::All, {}), kGpuFirstBuildStep));
    EXPECT_FALSE(hasStep(hostBuilt.sync(scene, SceneChanges::All, {}), kGpuFirstBuildStep));
    const float hplocCost = deferred.blasSahCost(0), sahCost = hostBuilt.blasSahCost(0);
    EXPECT_NE(hplocCost, sahCost) << "the first frame's tree should be the GPU's";
    {
        cuda::CudaBackend lbvhFirst;
        IntegratorToggles lbvh = fixedSchedule(true);
        lbvh.gpuPloc = false;
        const float lbvhCost = firstBuildCost(lbvhFirst, scene, lbvh, kLbvhFirstBuildStep);
        std::cout << "[ sah      ] first frame's BLAS of 300,000 triangles: H-PLOC " << hplocCost << ", LBVH "
                  << lbvhCost << ", host binned SAH " << sahCost << "\n";
        EXPECT_LT(hplocCost, lbvhCost) << "H-PLOC's tree should cost less to walk than the LBVH's";
        // Without the leaf collapse: leaves of one primitive, dearer to walk, with the same hits.
        cuda::CudaBackend singleLeaves;
        IntegratorToggles uncollapsed = fixedSchedule(true);
        uncollapsed.gpuLeafCollapse = false;
        const float singleLeafCost = firstBuildCost(singleLeaves, scene, uncollapsed, kGpuFirstBuildStep);
        std::cout << "[ sah      ] H-PLOC without the leaf collapse " << singleLeafCost << "\n";
        EXPECT_LT(hplocCost, singleLeafCost) << "the collapse should pay on 300,000 triangles";
        EXPECT_EQ(test::bufferBytes(singleLeaves, "BVH scratch (leaf collapse)"), 0u);
        test::expectSameHits(singleLeaves, hostBuilt, test::soupRays(20000, 7), "H-PLOC's single leaves");
    }
    EXPECT_EQ(deferred.blasSahCost(1), hostBuilt.blasSahCost(1))
        << "a mesh under the threshold, built on the host";

    EXPECT_GT(test::bufferBytes(deferred, "BVH scratch (H-PLOC builder)"), 1u << 20);
    EXPECT_GT(test::bufferBytes(deferred, "BVH scratch (leaf collapse)"), 1u << 20);
    const std::vector<Ray> rays = test::soupRays(100000, 3);
    test::expectSameHits(deferred, hostBuilt, rays, "GPU first build vs host SAH");
    deferred.render(2);               // on the GPU's tree, or on the SAH tree where it was done
    deferred.finishBackgroundWork();  // lands it where render() did not
    EXPECT_EQ(deferred.blasSahCost(0), sahCost) << "the host's SAH tree should have landed";
    EXPECT_FALSE(deferred.finishBackgroundWork().has_value()) << "work left after finishing it";
    // The first build's scratch went with it (300,000 boxes are 7 MiB).
    EXPECT_EQ(test::bufferBytes(deferred, "BVH scratch (H-PLOC builder)"), 0u);
    EXPECT_EQ(test::bufferBytes(deferred, "BVH scratch (leaf collapse)"), 0u);
    EXPECT_EQ(test::bufferBytes(deferred, "BVH scratch (LBVH builder)"), 0u);
    EXPECT_EQ(test::bufferBytes(deferred, "BVH scratch (primitive boxes)"), 0u);
    EXPECT_EQ(test::bufferBytes(deferred, "BLAS nodes"), test::bufferBytes(hostBuilt, "BLAS nodes"))
        << "the region the GPU build reserved (2n - 1 nodes) should fit the SAH tree";
    test::expectSameHits(deferred, hostBuilt, rays, "landed SAH tree vs host SAH");

    // The swap kept the accumulation, and it is the image the host's tree renders.
    deferred.render(2);
    hostBuilt.render(4);
    EXPECT_EQ(deferred.stats().samplesPerPixel, 4u);
    EXPECT_LE(test::largestBeautyDifference(deferred, hostBuilt), 1e-6f) << "the image changed with the tree";
}

// A tree's topology holds for any positions of its primitives: the SAH tree built from the
// positions before an edit lands refitted to the positions after it.
TEST(CudaFirstBuild, AnEditBeforeTheSwapRefitsTheTreeThatLands) {
    PT_REQUIRE_CUDA_DEVICE();
    Scene scene = largeSoupScene();
    cuda::CudaBackend edited;
    syncForRefits(edited, scene);
    for (Vec3& p : scene.meshes[0].positions) p = p * 1.3f + Vec3(0.0f, 0.4f, 0.0f);
    EXPECT_EQ(edited.sync(scene, SceneChanges::Geometry, {}).action, "refit");
    const float refittedLbvhCost = edited.blasSahCost(0);
    EXPECT_TRUE(edited.finishBackgroundWork().has_value()) << "nothing was building behind the first frame";
    EXPECT_LT(edited.blasSahCost(0), refittedLbvhCost) << "the SAH tree should have landed";
    CpuBackend cpu;
    cpu.sync(scene, SceneChanges::All, {});
    test::expectSameHits(edited, cpu, test::soupRays(100000, 4), "SAH tree landed after an edit vs CPU");
}

// Two meshes over the threshold: both regions have room for their LBVHs from the upload, and
// both trees land.
TEST(CudaFirstBuild, TwoLargeMeshesBothGetTheirSahTrees) {
    PT_REQUIRE_CUDA_DEVICE();
    Scene scene = test::soupScene(300000, 270000);
    cuda::CudaBackend deferred, hostBuilt;
    deferred.setToggles(fixedSchedule(true));
    hostBuilt.setToggles(fixedSchedule(false));
    EXPECT_TRUE(hasStep(deferred.sync(scene, SceneChanges::All, {}), kGpuFirstBuildStep));
    hostBuilt.sync(scene, SceneChanges::All, {});
    const std::vector<Ray> rays = test::soupRays(100000, 6);
    test::expectSameHits(deferred, hostBuilt, rays, "two GPU first builds vs host SAH");
    EXPECT_TRUE(deferred.finishBackgroundWork().has_value());
    for (uint32_t blas : {0u, 1u}) EXPECT_EQ(deferred.blasSahCost(blas), hostBuilt.blasSahCost(blas)) << blas;
    EXPECT_EQ(test::bufferBytes(deferred, "BLAS nodes"), test::bufferBytes(hostBuilt, "BLAS nodes"));
    test::expectSameHits(deferred, hostBuilt, rays, "two landed SAH trees vs host SAH");
}

// After the swap the BLAS's region holds the SAH tree alone; a refit walks that tree's parents.
TEST(CudaFirstBuild, ARefitAfterTheSwapRefitsTheSahTree) {
    PT_REQUIRE_CUDA_DEVICE();
    Scene scene = largeSoupScene();
    cuda::CudaBackend edited;
    syncForRefits(edited, scene);
    edited.finishBackgroundWork();
    for (Vec3& p : scene.meshes[0].positions) p = p * 0.8f + Vec3(0.2f, -0.3f, 0.1f);
    EXPECT_EQ(edited.sync(scene, SceneChanges::Geometry, {}).action, "refit");
    CpuBackend cpu;
    cpu.sync(scene, SceneChanges::All, {});
    test::expectSameHits(edited, cpu, test::soupRays(100000, 5), "refitted SAH tree after the swap vs CPU");
}

// With the compressed nodes on, the large mesh is still built on the GPU first and walks its
// binary trees, as the small one does until the collapse behind the first frame lands. The
// large mesh's SAH tree lands with a compressed form built behind the first frame too, appended
// after the others': the same nodes and entries the host's build of that tree gives, less the
// deferred mesh's empty stand-in. The hits are the CPU's throughout.
TEST(CudaFirstBuild, WithCompressedNodesTheDeferredMeshGetsItsCompressedFormWithItsSahTree) {
    PT_REQUIRE_CUDA_DEVICE();
    IntegratorToggles wide = fixedSchedule(true);
    wide.gpuWideBvh = true;
    cuda::CudaBackend backend, hostBuilt;
    backend.setToggles(wide);
    wide.gpuFirstBuild = false;
    hostBuilt.setToggles(wide);
    const Scene scene = largeSoupScene();
    EXPECT_TRUE(hasStep(backend.sync(scene, SceneChanges::All, {}), kGpuFirstBuildStep));
    hostBuilt.sync(scene, SceneChanges::All, {});
    EXPECT_TRUE(hostBuilt.finishBackgroundWork().has_value()) << "the collapse behind the first frame";
    for (const ToggleState& s : backend.toggleStates()) {
        if (s.id == ToggleId::GpuFirstBuild || s.id == ToggleId::GpuWideBvh) {
            EXPECT_TRUE(s.active) << s.note;
        }
    }
    const char* nodes = "BLAS compressed 8-wide nodes";
    const char* entries = "BLAS compressed primitive indices";
    const char* triangles = "BLAS compressed leaf triangles";
    EXPECT_EQ(test::bufferBytes(backend, nodes), 0u) << "nothing lands before the first frame";
    EXPECT_EQ(backend.stats().walk, "");
    CpuBackend cpu;
    cpu.sync(scene, SceneChanges::All, {});
    const std::vector<Ray> rays = test::soupRays(100000, 8);
    test::expectSameHits(backend, cpu, rays, "GPU first build, binary walk vs CPU");

    EXPECT_TRUE(backend.finishBackgroundWork().has_value());
    EXPECT_EQ(test::bufferBytes(backend, nodes),
              test::bufferBytes(hostBuilt, nodes) + sizeof(CompressedWideNode))
        << "the landed tree's compressed nodes, after the stand-in's one";
    EXPECT_EQ(test::bufferBytes(backend, entries), test::bufferBytes(hostBuilt, entries));
    EXPECT_EQ(test::bufferBytes(backend, triangles), test::bufferBytes(hostBuilt, triangles));
    EXPECT_EQ(test::bufferBytes(backend, "BLAS compressed sources (refit)"),
              test::bufferBytes(hostBuilt, "BLAS compressed sources (refit)") +
                  CompressedWideNode::kWidth * sizeof(uint32_t));
    test::expectSameHits(backend, cpu, rays, "landed SAH tree's compressed nodes vs CPU");

    // The images of the landed compressed form and of the host's, at equal samples.
    backend.render(4);
    hostBuilt.render(4);
    EXPECT_LE(test::largestBeautyDifference(backend, hostBuilt), 1e-6f) << "the image changed with the tree";
}

// With the compressed nodes on, an edit before the swap and one after it: the landed tree is
// refitted and its compressed form requantised (and its leaf triangles gathered again) from it,
// and a refit after the swap requantises the appended form.
TEST(CudaFirstBuild, WithCompressedNodesEditsBeforeAndAfterTheSwapRequantiseTheLandedForm) {
    PT_REQUIRE_CUDA_DEVICE();
    Scene scene = largeSoupScene();
    cuda::CudaBackend edited;
    IntegratorToggles neverRebuild = fixedSchedule(true);
    neverRebuild.rebuildSahRatio = 1e9f;
    neverRebuild.gpuWideBvh = true;
    edited.setToggles(neverRebuild);
    edited.sync(scene, SceneChanges::All, {});
    for (Vec3& p : scene.meshes[0].positions) p = p * 1.3f + Vec3(0.0f, 0.4f, 0.0f);
    EXPECT_EQ(edited.sync(scene, SceneChanges::Geometry, {}).action, "refit");
    // The edit's sync landed the small mesh's compressed nodes (the collapse reads the compiled
    // BLASes): the large mesh's come with its SAH tree.
    const uint64_t smallMesh = test::bufferBytes(edited, "BLAS compressed 8-wide nodes");
    EXPECT_GT(smallMesh, 0u);
    EXPECT_TRUE(edited.finishBackgroundWork().has_value()) << "nothing was building behind the first frame";
    EXPECT_GT(test::bufferBytes(edited, "BLAS compressed 8-wide nodes"), 10 * smallMesh)
        << "no compressed form landed with the SAH tree";
    CpuBackend cpu;
    cpu.sync(scene, SceneChanges::All, {});
    test::expectSameHits(edited, cpu, test::soupRays(100000, 9),
                         "compressed form landed after an edit vs CPU");

    for (Vec3& p : scene.meshes[0].positions) p = p * 0.8f + Vec3(0.2f, -0.3f, 0.1f);
    EXPECT_EQ(edited.sync(scene, SceneChanges::Geometry, {}).action, "refit");
    cpu.sync(scene, SceneChanges::Geometry, {});
    test::expectSameHits(edited, cpu, test::soupRays(100000, 10), "landed compressed form refitted vs CPU");
}

}  // namespace
}  // namespace pt
