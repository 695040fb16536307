// Posing for a device (SkinningSite::Device): the Scene's vertices stay, the pose's joints wait
// with the skinned mesh, and skinning them on the host later gives exactly what a host pose
// gives; merged geometry leaves skinned meshes instanced.
#include "render/scene/scene_animation.h"

#include <gtest/gtest.h>

#include <cstring>

#include "render/compile/compile_scene.h"
#include "support/skinned_grid.h"

namespace pt {
namespace {

template <class T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST(SceneAnimation, ADevicePoseLeavesTheVerticesAndKeepsTheJoints) {
    Scene host = test::skinnedGridScene(8);
    test::bendSkinnedGrid(host, 0.7f);
    Scene device = host;
    const Mesh unposed = host.meshes[0];

    const SceneDelta hostDelta = poseRig(host, 0, -1, 0.0f, SkinningSite::Host);
    const SceneDelta deviceDelta = poseRig(device, 0, -1, 0.0f, SkinningSite::Device);
    EXPECT_EQ(hostDelta, deviceDelta);
    EXPECT_EQ(deviceDelta, meshesMoved({0}));
    EXPECT_FALSE(sameBits(host.meshes[0].positions, unposed.positions)) << "the bend moved nothing";
    EXPECT_TRUE(sameBits(device.meshes[0].positions, unposed.positions));
    EXPECT_TRUE(sameBits(device.meshes[0].normals, unposed.normals));
    EXPECT_EQ(pendingSkinOf(host, 0), nullptr);
    ASSERT_NE(pendingSkinOf(device, 0), nullptr);
    EXPECT_EQ(pendingSkinOf(device, 0)->pendingJoints.size(), 2u);

    EXPECT_EQ(skinPendingOnHost(device), std::vector<uint32_t>{0});
    EXPECT_EQ(pendingSkinOf(device, 0), nullptr);
    EXPECT_TRUE(sameBits(device.meshes[0].positions, host.meshes[0].positions));
    EXPECT_TRUE(sameBits(device.meshes[0].normals, host.meshes[0].normals));
    EXPECT_TRUE(sameBits(device.meshes[0].tangents, host.meshes[0].tangents));
    EXPECT_TRUE(skinPendingOnHost(device).empty()) << "nothing is left pending";
}

TEST(SceneAnimation, AHostPoseAfterADevicePoseLeavesNothingPending) {
    Scene scene = test::skinnedGridScene(4);
    test::bendSkinnedGrid(scene, 0.3f);
    poseRig(scene, 0, -1, 0.0f, SkinningSite::Device);
    test::bendSkinnedGrid(scene, -0.4f);
    poseRig(scene, 0, -1, 0.0f, SkinningSite::Host);
    EXPECT_EQ(pendingSkinOf(scene, 0), nullptr);
    EXPECT_TRUE(skinPendingOnHost(scene).empty());
}

// A mesh whose vertices an edit replaced (another count) is no longer the rig's to skin.
TEST(SceneAnimation, AReplacedMeshIsNotSkinned) {
    Scene scene = test::skinnedGridScene(4);
    poseRig(scene, 0, -1, 0.0f, SkinningSite::Device);
    scene.meshes[0] = test::skinnableGrid(3, 1);
    const Mesh replaced = scene.meshes[0];
    EXPECT_EQ(pendingSkinOf(scene, 0), nullptr);
    EXPECT_TRUE(skinPendingOnHost(scene).empty());
    EXPECT_TRUE(sameBits(scene.meshes[0].positions, replaced.positions));
    EXPECT_EQ(poseRig(scene, 0, -1, 0.0f, SkinningSite::Device), SceneDelta{});
}

// Small instances merge into one BLAS, but not a skinned one: every frame would bake it again.
TEST(SceneAnimation, MergedGeometryLeavesSkinnedMeshesInstanced) {
    Scene scene = test::skinnedGridScene(4);
    for (int i = 0; i < 3; ++i) {
        scene.meshes.push_back(test::skinnableGrid(2, uint32_t(i)));
        Instance instance = scene.instances[0];
        instance.mesh = uint32_t(scene.meshes.size() - 1);
        instance.objectToWorld = translationTransform(Vec3(3.0f * float(i + 1), 0.0f, 0.0f));
        scene.instances.push_back(instance);
    }
    CompileOptions options;
    options.mergeSmallInstances = true;
    const CompiledScene compiled = compileRenderScene(scene, options);
    ASSERT_TRUE(compiled.merged.active()) << "the three plain grids should merge";
    EXPECT_EQ(compiled.merged.pieces.size(), 3u);
    for (const MergedPiece& piece : compiled.merged.pieces) EXPECT_NE(piece.mesh, 0u);
}

}  // namespace
}  // namespace pt
