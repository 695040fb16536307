// Skinning on the GPU (device_skins.h): frames posed for the device trace like the same frames
// skinned on the host, a host edit after a GPU skin reaches the device whole, and a full build
// of a scene with a pose pending skins it before the first frame. Skips without a CUDA device.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "cuda_test_support.h"
#include "render/backend/cuda/cuda_backend.h"
#include "render/scene/scene_animation.h"
#include "support/skinned_grid.h"

namespace pt {
namespace {

constexpr uint32_t kGrid = 200;  // 80,000 triangles

std::vector<Hit> trace(Backend& backend) {
    const std::vector<Ray> rays = test::downwardRays(40000, 3, {1.1f, 0.5f, 1.0f}, 0.3f);
    std::vector<Hit> hits;
    backend.traceRays(rays, false, 1, &hits);
    return hits;
}

// Hits of vertices skinned on the GPU and on the host: the same triangle's instance at the same
// distance up to float rounding (the two compilers contract the blend differently); a ray
// through an edge may take either side, so a few in ten thousand may differ.
void expectSameSurface(const std::vector<Hit>& a, const std::vector<Hit>& b, const std::string& what) {
    ASSERT_EQ(a.size(), b.size());
    size_t differ = 0, hits = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        hits += a[i].valid();
        if (a[i].valid() != b[i].valid() || a[i].instance != b[i].instance) {
            ++differ;
        } else if (a[i].valid()) {
            differ += std::fabs(a[i].t - b[i].t) > 1e-4f * (1.0f + a[i].t);
        }
    }
    EXPECT_LE(differ, a.size() / 2000) << what;
    EXPECT_GT(hits, a.size() / 2) << what << ": too few rays hit to test anything";
}

size_t countDifferent(const std::vector<Hit>& a, const std::vector<Hit>& b) {
    size_t differ = 0;
    for (size_t i = 0; i < a.size(); ++i) differ += a[i].valid() != b[i].valid() || a[i].t != b[i].t;
    return differ;
}

bool hasStep(const SyncReport& report, const std::string& name) {
    for (const SyncStep& step : report.steps) {
        if (step.name == name) return true;
    }
    return false;
}

TEST(CudaSkinning, GpuSkinnedFramesTraceLikeHostSkinnedOnes) {
    PT_REQUIRE_CUDA_DEVICE();
    Scene onDevice = test::skinnedGridScene(kGrid);
    Scene onHost = onDevice;
    const std::vector<Vec3> bind = onDevice.meshes[0].positions;
    cuda::CudaBackend gpuSkin, hostSkin;
    ASSERT_TRUE(gpuSkin.capabilities().skinsOnDevice);
    gpuSkin.sync(onDevice, SceneChanges::All, {});
    hostSkin.sync(onHost, SceneChanges::All, {});
    const std::vector<Hit> unbent = trace(gpuSkin);
    for (const float angle : {0.3f, 0.9f, -0.6f, 1.2f}) {
        const std::string frame = "bend " + std::to_string(angle);
        test::bendSkinnedGrid(onDevice, angle);
        test::bendSkinnedGrid(onHost, angle);
        const SyncReport report =
            gpuSkin.sync(onDevice, poseRig(onDevice, 0, -1, 0.0f, SkinningSite::Device), {});
        hostSkin.sync(onHost, poseRig(onHost, 0, -1, 0.0f, SkinningSite::Host), {});
        EXPECT_TRUE(report.action == "refit" || report.action == "rebuild") << frame << ": " << report.action;
        EXPECT_TRUE(hasStep(report, "skin (GPU)")) << frame;
        EXPECT_EQ(onDevice.meshes[0].positions, bind) << frame << ": the host's vertices were skinned";
        const std::vector<Hit> skinned = trace(gpuSkin);
        expectSameSurface(skinned, trace(hostSkin), frame);
        EXPECT_GT(countDifferent(skinned, unbent), skinned.size() / 10)
            << frame << ": the bend moved nothing";
    }
}

// After a GPU skin the host's copy of the vertices lags the device's: an edit that puts back
// exactly the vertices the host last held must still reach the device.
TEST(CudaSkinning, AHostEditAfterAGpuSkinUploadsTheWholeMesh) {
    PT_REQUIRE_CUDA_DEVICE();
    Scene scene = test::skinnedGridScene(kGrid);
    const Mesh unbent = scene.meshes[0];
    cuda::CudaBackend backend;
    backend.sync(scene, SceneChanges::All, {});
    test::bendSkinnedGrid(scene, 1.0f);
    backend.sync(scene, poseRig(scene, 0, -1, 0.0f, SkinningSite::Device), {});
    skinPendingOnHost(scene);
    scene.meshes[0] = unbent;  // a sculpt back to the flat grid
    EXPECT_EQ(backend.sync(scene, meshesMoved({0}), {}).action, "refit");
    cuda::CudaBackend fresh;
    fresh.sync(scene, SceneChanges::All, {});
    EXPECT_EQ(countDifferent(trace(backend), trace(fresh)), 0u);
}

// A backend that first meets a scene posed for the device (the host's vertices an earlier
// pose) skins it before its first frame.
TEST(CudaSkinning, AFullBuildOfAPendingPoseSkinsIt) {
    PT_REQUIRE_CUDA_DEVICE();
    Scene pending = test::skinnedGridScene(kGrid);
    test::bendSkinnedGrid(pending, 0.8f);
    Scene posed = pending;
    poseRig(pending, 0, -1, 0.0f, SkinningSite::Device);
    poseRig(posed, 0, -1, 0.0f, SkinningSite::Host);
    cuda::CudaBackend late, host;
    late.sync(pending, SceneChanges::All, {});
    host.sync(posed, SceneChanges::All, {});
    expectSameSurface(trace(late), trace(host), "full build with a pending pose");
}

// A GPU-skinned frame refits the BLAS built at rest, or rebuilds it on the GPU where the refit's
// SAH cost drifted past the ratio, as a host refit of the same tree predicts.
TEST(CudaSkinning, RefitOrRebuildFollowsTheSahRatio) {
    PT_REQUIRE_CUDA_DEVICE();
    test::expectRefitDecisionsFollowTheSahRatio(60, "rebuild", [](float threshold, float bend) {
        Scene scene = test::skinnedGridScene(60);
        cuda::CudaBackend backend;
        IntegratorToggles toggles;
        toggles.rebuildSahRatio = threshold;
        backend.setToggles(toggles);
        backend.sync(scene, SceneChanges::All, {});
        test::bendSkinnedGrid(scene, bend);
        return backend.sync(scene, poseRig(scene, 0, -1, 0.0f, SkinningSite::Device), {}).action;
    });
}

}  // namespace
}  // namespace pt
