#pragma once
// A bumpy grid skinned to two joints, built in memory for tests of posing on the host and on a
// device: node 0 places the mesh, node 1 is the root joint at x = -1 and node 2 its child at
// x = 0, about which bendSkinnedGrid turns the right half up (about z). A vertex's weight on
// joint 2 rises smoothly from 0 at x = -0.5 to 1 at x = 0.5, so the bend is a smooth curve.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "render/compile/compile_scene.h"
#include "render/compile/host_refit.h"
#include "render/scene/scene_animation.h"
#include "support/scene_builder.h"

namespace pt::test {

// test::bumpyGrid with normals up and tangents along +X: the skin moves all three.
inline Mesh skinnableGrid(uint32_t n, uint32_t seed) {
    Mesh mesh = bumpyGrid(n, seed);
    mesh.name = "skinned grid";
    mesh.normals.assign(mesh.positions.size(), Vec3(0.0f, 1.0f, 0.0f));
    mesh.tangents.assign(mesh.positions.size(), Vec4(1.0f, 0.0f, 0.0f, 1.0f));
    return mesh;
}

inline Scene skinnedGridScene(uint32_t n) {
    Scene scene;
    scene.render = {48, 48, 4, 16, 0};
    scene.camera.position = {0.0f, 4.0f, 3.0f};
    scene.camera.lookAt = {0, 0, 0};
    scene.environment.color = {1, 1, 1};
    const uint32_t grey = addMaterial(scene, "grey", diffuse({0.5f, 0.5f, 0.5f}));
    scene.meshes.push_back(skinnableGrid(n, 7));
    Instance instance;
    instance.name = "skinned grid";
    instance.materials = {grey};
    scene.instances.push_back(instance);

    AnimationRig rig;
    rig.parents = {-1, -1, 1};
    rig.restPoses.resize(3);
    rig.restPoses[1].translation = {-1.0f, 0.0f, 0.0f};
    rig.restPoses[2].translation = {1.0f, 0.0f, 0.0f};  // x = 0 in the world
    Skin skin;
    skin.joints = {1, 2};
    skin.inverseBindMatrices = {inverse(rig.restPoses[1].matrix()),
                                inverse(rig.restPoses[1].matrix() * rig.restPoses[2].matrix())};
    rig.skins.push_back(skin);
    rig.instances.push_back({0, 0, Affine3{}});
    SkinnedMesh skinned;
    const Mesh& mesh = scene.meshes[0];
    skinned.bindPositions = mesh.positions;
    skinned.bindNormals = mesh.normals;
    skinned.bindTangents = mesh.tangents;
    for (const Vec3& p : mesh.positions) {
        const float t = std::fmin(std::fmax(p.x + 0.5f, 0.0f), 1.0f);
        const float w = t * t * (3.0f - 2.0f * t);
        JointInfluences in;
        in.joints[0] = 0, in.weights[0] = 1.0f - w;
        in.joints[1] = 1, in.weights[1] = w;
        skinned.influences.push_back(in);
    }
    rig.skinnedMeshes.push_back(std::move(skinned));
    scene.rigs.push_back(std::move(rig));
    return scene;
}

// Turns joint 2 by `radians` about z in the rig's rest pose (the pose poseRig gives animation -1).
inline void bendSkinnedGrid(Scene& scene, float radians) {
    scene.rigs[0].restPoses[2].rotation = {0.0f, 0.0f, std::sin(0.5f * radians), std::cos(0.5f * radians)};
}

// What a backend that built the grid's BLAS at rest and refits it to the bend `radians` should
// find: that refit's SAH cost over the cost as built (render/compile/host_refit.h, on the host).
inline float refitSahRatioOfBend(uint32_t n, float radians) {
    Scene scene = skinnedGridScene(n);
    CompiledScene compiled = compileRenderScene(scene);
    const float built = blasSahCost(compiled, 0);
    bendSkinnedGrid(scene, radians);
    const SceneDelta delta = poseRig(scene, 0, -1, 0.0f, SkinningSite::Host);
    copyMovedMeshes(scene, delta.meshes, compiled);
    refitBlasOnHost(compiled, 0);
    return blasSahCost(compiled, 0) / built;
}

// Rebuild thresholds between the ratios refitSahRatioOfBend gives for `bends`, none within 1%
// of a ratio: a backend must refit below the threshold and rebuild above it, with room for the
// rounding of a skin on another processor.
inline std::vector<float> thresholdsBetween(std::vector<float> ratios) {
    std::sort(ratios.begin(), ratios.end());
    std::vector<float> thresholds;
    for (size_t i = 0; i + 1 < ratios.size(); ++i) {
        if (ratios[i + 1] > ratios[i] * 1.02f) thresholds.push_back(0.5f * (ratios[i] + ratios[i + 1]));
    }
    return thresholds;
}

// For thresholds between the refit ratios of several bends: `frame(threshold, bend)` (a
// backend's sync action for a frame bent `bend` from rest, its rebuild ratio `threshold`) must
// be `rebuilt` where the bend's ratio is above the threshold and "refit" below.
template <class Frame>
void expectRefitDecisionsFollowTheSahRatio(uint32_t n, const std::string& rebuilt, Frame&& frame) {
    const std::vector<float> bends = {0.1f, 0.4f, 0.8f, 1.2f, 1.6f};
    std::vector<float> ratios;
    for (const float bend : bends) ratios.push_back(refitSahRatioOfBend(n, bend));
    const std::vector<float> thresholds = thresholdsBetween(ratios);
    ASSERT_GE(thresholds.size(), 2u) << "the bends must drift the SAH apart for the test to mean anything";
    for (const float threshold : thresholds) {
        for (size_t i = 0; i < bends.size(); ++i) {
            EXPECT_EQ(frame(threshold, bends[i]), ratios[i] > threshold ? rebuilt : "refit")
                << "bend " << bends[i] << ", refit SAH ratio " << ratios[i] << ", threshold " << threshold;
        }
    }
}

}  // namespace pt::test
