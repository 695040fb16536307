// glTF skins and animations imported into a rig and posed (issue 19): SimpleSkin against an
// evaluation of its two joints written out in the test, the Fox's rest pose against its bind
// pose, and the BVH the CPU backend refits after each animated frame against brute force.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "assets/scene_loader.h"
#include "render/backend/backend.h"
#include "render/scene/scene_animation.h"
#include "support/load_scene.h"
#include "support/test_paths.h"
#include "support/vertex_distance.h"

namespace pt {
namespace {

const char* const kSimpleSkin = "SimpleSkin/SimpleSkin.gltf";
const char* const kFox = "Fox/Fox.glb";

void expectNear(Vec3 a, Vec3 b, float tolerance, const std::string& what) {
    EXPECT_NEAR(a.x, b.x, tolerance) << what;
    EXPECT_NEAR(a.y, b.y, tolerance) << what;
    EXPECT_NEAR(a.z, b.z, tolerance) << what;
}

// SimpleSkin: ten vertices in rows at y = 0, 0.5, ..., 2 (x = 0 and 1), weighted from joint 0
// (node 1, at y = 1) to joint 1 (node 2, its child at the same place) linearly up the strip;
// both inverse bind matrices translate by (-0.5, -1, 0). Its one animation turns node 2 about
// z, 45 degrees a half second up to 90. A vertex (x, y) with weight w on joint 1 then goes to
// (1 - w) (x - 0.5, y) + w ((0, 1) + R(angle) (x - 0.5, y - 1)).
Vec3 simpleSkinVertex(float x, float y, float w, float angle) {
    const float c = std::cos(angle), s = std::sin(angle);
    const float rx = x - 0.5f, ry = y - 1.0f;
    const Vec3 turned{c * rx - s * ry, 1.0f + s * rx + c * ry, 0.0f};
    return Vec3(x - 0.5f, y, 0.0f) * (1.0f - w) + turned * w;
}

TEST(GltfAnimation, SimpleSkinFollowsItsJoints) {
    PT_REQUIRE_SHARED_ASSET(kSimpleSkin);
    Scene scene = test::loadSceneOrFail(test::sharedAsset(kSimpleSkin));
    ASSERT_EQ(scene.rigs.size(), 1u);
    const AnimationRig& rig = scene.rigs[0];
    ASSERT_EQ(rig.animations.size(), 1u);
    EXPECT_FLOAT_EQ(rig.animations[0].duration(), 5.5f);
    ASSERT_EQ(rig.skinnedMeshes.size(), 1u);
    for (const std::string& w : scene.warnings) EXPECT_EQ(w.find("not applied"), std::string::npos) << w;
    const uint32_t mesh = rig.skinnedMeshes[0].mesh;

    // Without normals in the file the triangles are flat-shaded, each with vertices of its own:
    // each vertex's bind position says which of the ten it is.
    const std::vector<Vec3>& bind = rig.skinnedMeshes[0].bindPositions;
    ASSERT_EQ(bind.size(), 24u);
    const auto check = [&](float angle, const std::string& when) {
        const std::vector<Vec3>& p = scene.meshes[mesh].positions;
        ASSERT_EQ(p.size(), bind.size());
        for (size_t v = 0; v < p.size(); ++v) {
            const float x = bind[v].x, y = bind[v].y;
            expectNear(p[v], simpleSkinVertex(x, y, y / 2, angle), 1e-5f,
                       when + ", vertex " + std::to_string(v));
        }
    };
    check(0.0f, "rest pose (the imported scene)");
    const SceneDelta moved = poseRig(scene, 0, 0, 1.0f);
    EXPECT_TRUE(moved.has(SceneChanges::Geometry));
    EXPECT_TRUE(moved.meshes == TouchedIds::only({mesh}));
    check(float(M_PI) / 2, "t = 1 s, a key");
    // Halfway from the first key to the second (45 degrees, as the file rounds its quaternion):
    // slerp's angle is linear in time.
    const std::vector<float>& keys = rig.animations[0].samplers[0].values;
    const float second = 2.0f * std::atan2(keys[6], keys[7]);
    EXPECT_NEAR(second, float(M_PI) / 4, 1e-3f);
    poseRig(scene, 0, 0, 0.25f);
    check(second / 2, "t = 0.25 s");
    poseRig(scene, 0, 0, 4.0f);
    check(-float(M_PI) / 2, "t = 4 s");
    poseRig(scene, 0, -1, 0.0f);
    check(0.0f, "back to rest");
    EXPECT_THROW(poseRig(scene, 0, 1, 0.0f), std::invalid_argument);
}

TEST(GltfAnimation, TheFoxRestsInItsBindPose) {
    PT_REQUIRE_SHARED_ASSET(kFox);
    Scene scene = test::loadSceneOrFail(test::sharedAsset(kFox));
    ASSERT_EQ(scene.rigs.size(), 1u);
    const AnimationRig& rig = scene.rigs[0];
    ASSERT_EQ(rig.animations.size(), 3u) << "Survey, Walk, Run";
    ASSERT_EQ(rig.skins.size(), 1u);
    ASSERT_EQ(rig.skinnedMeshes.size(), 1u);
    const SkinnedMesh& skinned = rig.skinnedMeshes[0];
    const std::vector<Vec3>& rest = scene.meshes[skinned.mesh].positions;
    ASSERT_EQ(rest.size(), skinned.bindPositions.size());
    // The Fox's joints rest where its inverse bind matrices were taken: every joint matrix is
    // the identity, so the rest pose is the bind pose.
    EXPECT_LT(test::largestDistance(rest, skinned.bindPositions), 1e-3f)
        << "largest distance from the bind pose (the Fox is about 150 units long)";
    // Each animation moves it, and keeps it finite and near where it stands.
    for (int32_t a = 0; a < 3; ++a) {
        poseRig(scene, 0, a, 0.5f);
        float moved = 0.0f;
        for (size_t v = 0; v < rest.size(); ++v) {
            const Vec3 p = scene.meshes[skinned.mesh].positions[v];
            ASSERT_TRUE(isFinite(p)) << rig.animations[size_t(a)].name << ", vertex " << v;
            moved = std::fmax(moved, length(p - skinned.bindPositions[v]));
        }
        EXPECT_GT(moved, 1.0f) << rig.animations[size_t(a)].name;
        EXPECT_LT(moved, 200.0f) << rig.animations[size_t(a)].name;
    }
}

// The CPU backend refits the Fox's BLAS for each frame of its walk (the delta names the
// mesh); the closest hits of rays through the refitted tree equal a brute-force search.
TEST(GltfAnimation, RefittedFramesHitWhatBruteForceHits) {
    PT_REQUIRE_SHARED_ASSET(kFox);
    Scene scene = test::loadSceneOrFail(test::sharedAsset(kFox));
    ASSERT_EQ(scene.rigs.size(), 1u);
    scene.render.width = scene.render.height = 32;
    auto refitted = createBackend("cpu");
    refitted->sync(scene, SceneChanges::All);
    Vec3 lo, hi;
    scene.worldBounds(lo, hi);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (const float time : {0.2f, 0.45f, 0.8f}) {
        const SceneDelta delta = poseRig(scene, 0, 1, time);
        const SyncReport report = refitted->sync(scene, delta);
        EXPECT_TRUE(report.action == "refit" || report.action == "full build") << report.action;
        IntegratorToggles brute;
        brute.bruteForce = true;
        auto reference = createBackend("cpu");
        reference->setToggles(brute);
        reference->sync(scene, SceneChanges::All);
        // Rays from around the box towards points inside it.
        std::vector<Ray> rays;
        const Vec3 centre = (lo + hi) * 0.5f, size = hi - lo;
        for (int i = 0; i < 2000; ++i) {
            const Vec3 target = lo + size * Vec3(u(rng), u(rng), u(rng));
            const Vec3 origin = centre + size * Vec3(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f) * 3.0f;
            rays.push_back(Ray{origin, target - origin});
        }
        std::vector<Hit> got, want;
        refitted->traceRays(rays, false, 1, &got);
        reference->traceRays(rays, false, 1, &want);
        int hits = 0;
        for (size_t i = 0; i < rays.size(); ++i) {
            ASSERT_EQ(got[i].valid(), want[i].valid()) << "t = " << time << ", ray " << i;
            if (!got[i].valid()) continue;
            ++hits;
            EXPECT_EQ(got[i].t, want[i].t) << "t = " << time << ", ray " << i;
        }
        EXPECT_GT(hits, 200) << "the rays must find the Fox";
    }
}

// Fixtures written by tests/data/gltf/animation_fixtures.py.
TEST(GltfAnimation, BadSamplersAndJointsNameTheFileAndTheElement) {
    const auto refused = [](const char* file, const std::string& words) {
        const LoadResult result = loadScene(test::testDataPath(std::string("gltf/") + file));
        ASSERT_FALSE(result.ok()) << file;
        EXPECT_NE(result.error.find(file), std::string::npos) << result.error;
        EXPECT_NE(result.error.find(words), std::string::npos) << result.error;
    };
    refused("anim_bad_times.gltf",
            "animations[0].samplers[0]: key times are not strictly increasing at key 2");
    refused("skin_bad_joint.gltf", "nodes[2].skin: vertex 2: joint 3 is past the skin's 2 joints");
}

TEST(GltfAnimation, WeightsThatDoNotSumToOneAreNormalisedWithOneWarning) {
    Scene scene = test::loadSceneOrFail(test::testDataPath("gltf/skin_weights.gltf"));
    size_t warned = 0;
    for (const std::string& w : scene.warnings)
        warned += w.find("1 vertices' skin weights did not sum to 1") != std::string::npos;
    EXPECT_EQ(warned, 1u);
    ASSERT_EQ(scene.rigs.size(), 1u);
    // Joint 1 rests one unit up: half of each vertex's weight lifts it by half a unit, the
    // renormalised one too.
    const std::vector<Vec3>& p = scene.meshes[scene.rigs[0].skinnedMeshes.at(0).mesh].positions;
    const Vec3 quad[] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    ASSERT_EQ(p.size(), 4u);
    for (size_t v = 0; v < 4; ++v)
        expectNear(p[v], quad[v] + Vec3(0.0f, 0.5f, 0.0f), 1e-6f, "vertex " + std::to_string(v));
}

}  // namespace
}  // namespace pt
