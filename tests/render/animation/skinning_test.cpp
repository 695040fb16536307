// Skinning against an evaluation written independently in the test: a two-joint arm whose
// elbow bends, with the positions and normals its geometry dictates (trigonometry, not
// matrices), the mesh node's own transform, eight influences, mirrored joints, and the
// checks a file's weights get.
#include "render/animation/skinning.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace pt {
namespace {

Vec4 zRotation(float radians) { return {0.0f, 0.0f, std::sin(radians / 2), std::cos(radians / 2)}; }

void expectNear(Vec3 a, Vec3 b, float tolerance, const char* what) {
    EXPECT_NEAR(a.x, b.x, tolerance) << what;
    EXPECT_NEAR(a.y, b.y, tolerance) << what;
    EXPECT_NEAR(a.z, b.z, tolerance) << what;
}

JointInfluences bound(uint16_t joint) {
    JointInfluences in;
    in.joints[0] = joint;
    in.weights[0] = 1.0f;
    return in;
}

JointInfluences blend(uint16_t a, float wa, uint16_t b, float wb) {
    JointInfluences in;
    in.joints[0] = a;
    in.weights[0] = wa;
    in.joints[1] = b;
    in.weights[1] = wb;
    return in;
}

// Node 0: the shoulder at the origin; node 1: the elbow, its child, one unit along +x. The
// skin's inverse bind matrices undo the bind pose.
struct Arm {
    std::vector<int32_t> parents{-1, 0};
    std::vector<NodePose> poses = std::vector<NodePose>(2);
    Skin skin;
    Arm() {
        poses[1].translation = {1.0f, 0.0f, 0.0f};
        skin.joints = {0, 1};
        const std::vector<Affine3> bind = globalTransforms(parents, poses);
        skin.inverseBindMatrices = {inverse(bind[0]), inverse(bind[1])};
    }
    std::vector<Affine3> joints(const Affine3& meshNode = Affine3{}) const {
        return jointMatrices(skin, globalTransforms(parents, poses), meshNode);
    }
};

TEST(Skinning, TheBindPoseLeavesVerticesWhereTheyAre) {
    const Arm arm;
    const std::vector<Vec3> positions{{0.5f, 0.1f, 0.0f}, {1.5f, -0.1f, 0.2f}};
    const std::vector<Vec3> normals{{0, 1, 0}, {0, 0, 1}};
    const std::vector<JointInfluences> influences{bound(0), blend(0, 0.3f, 1, 0.7f)};
    std::vector<Vec3> p, n;
    std::vector<Vec4> t;
    skinVertices(arm.joints(), {positions, normals, {}, influences}, p, n, t);
    for (size_t v = 0; v < positions.size(); ++v) {
        expectNear(p[v], positions[v], 1e-6f, "position");
        expectNear(n[v], normals[v], 1e-6f, "normal");
    }
    EXPECT_TRUE(t.empty()) << "no tangents in, none out";
}

TEST(Skinning, ABentElbowMovesTheForearmAroundIt) {
    Arm arm;
    const float bend = 0.7f;  // radians about +z
    arm.poses[1].rotation = zRotation(bend);
    // A forearm vertex d along the arm and h above it, bound to the elbow, turns about the
    // elbow (1, 0, 0): (1 + d cos - h sin, d sin + h cos). Its up normal turns with it.
    const float d = 0.6f, h = 0.1f, c = std::cos(bend), s = std::sin(bend);
    const std::vector<Vec3> positions{{0.4f, h, 0.0f}, {1.0f + d, h, 0.0f}, {1.0f + d, 0.0f, 0.0f}};
    const std::vector<Vec3> normals{{0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
    const std::vector<Vec4> tangents{{1, 0, 0, 1}, {1, 0, 0, -1}, {1, 0, 0, 1}};
    // The third vertex half on each joint: linear blend skinning averages the two positions
    // (the shoulder's, unmoved, and the elbow's), which is why LBS shrinks bent joints.
    const std::vector<JointInfluences> influences{bound(0), bound(1), blend(0, 0.5f, 1, 0.5f)};
    std::vector<Vec3> p, n;
    std::vector<Vec4> t;
    skinVertices(arm.joints(), {positions, normals, tangents, influences}, p, n, t);
    expectNear(p[0], positions[0], 1e-6f, "upper arm: unmoved");
    expectNear(p[1], {1.0f + d * c - h * s, d * s + h * c, 0.0f}, 1e-6f, "forearm");
    expectNear(n[1], {-s, c, 0.0f}, 1e-6f, "forearm normal");
    expectNear({t[1].x, t[1].y, t[1].z}, {c, s, 0.0f}, 1e-6f, "forearm tangent");
    EXPECT_EQ(t[1].w, -1.0f) << "a rotation keeps the handedness";
    const Vec3 elbowMoved{1.0f + d * c, d * s, 0.0f};
    expectNear(p[2], (positions[2] + elbowMoved) * 0.5f, 1e-6f, "half and half");
}

TEST(Skinning, TheShoulderCarriesTheElbowAndTheMeshNodeDoesNotMoveTheSkin) {
    Arm arm;
    arm.poses[0].rotation = zRotation(float(M_PI) / 2);  // the whole arm points up
    const std::vector<Vec3> positions{{1.5f, 0.0f, 0.0f}};
    const std::vector<JointInfluences> influences{bound(1)};
    std::vector<Vec3> p, n;
    std::vector<Vec4> t;
    skinVertices(arm.joints(), {positions, {}, {}, influences}, p, n, t);
    expectNear(p[0], {0.0f, 1.5f, 0.0f}, 1e-6f, "through the parent's rotation");
    // Placed under a node moved by (5, 0, 0), the skinned vertices come out in that node's
    // space, so its instance transform puts them back where the joints say.
    const Affine3 meshNode = translationTransform({5.0f, 0.0f, 0.0f});
    skinVertices(arm.joints(meshNode), {positions, {}, {}, influences}, p, n, t);
    expectNear(meshNode.transformPoint(p[0]), {0.0f, 1.5f, 0.0f}, 1e-5f, "world position");
}

TEST(Skinning, EightInfluencesEachCount) {
    Skin skin;
    std::vector<Affine3> globals;
    for (uint32_t j = 0; j < 8; ++j) {
        skin.joints.push_back(j);
        globals.push_back(translationTransform({float(j + 1), 0.0f, 0.0f}));
    }
    JointInfluences in;
    for (uint16_t j = 0; j < 8; ++j) {
        in.joints[j] = j;
        in.weights[j] = 1.0f / 8.0f;
    }
    std::vector<Vec3> p, n;
    std::vector<Vec4> t;
    skinVertices(jointMatrices(skin, globals, Affine3{}), {{{0, 0, 0}}, {}, {}, {in}}, p, n, t);
    EXPECT_FLOAT_EQ(p[0].x, 4.5f) << "the mean of 1..8: JOINTS_1 and WEIGHTS_1 are used";
}

TEST(Skinning, AMirroringJointFlipsTheTangentsHandedness) {
    Skin skin;
    skin.joints = {0};
    const std::vector<Affine3> globals{scaleTransform({-1.0f, 1.0f, 1.0f})};
    std::vector<Vec3> p, n;
    std::vector<Vec4> t;
    skinVertices(jointMatrices(skin, globals, Affine3{}),
                 {{{0, 0, 0}}, {{0, 0, 1}}, {{1, 0, 0, 1}}, {bound(0)}}, p, n, t);
    // The bitangent w x cross(n, t) must be the mirrored bitangent: (0, 1, 0) stays (0, 1, 0).
    const Vec3 bitangent = cross(n[0], Vec3(t[0].x, t[0].y, t[0].z)) * t[0].w;
    expectNear(bitangent, {0.0f, 1.0f, 0.0f}, 1e-6f, "bitangent");
}

TEST(Skinning, WeightsAreCheckedAndNormalised) {
    std::vector<JointInfluences> influences{blend(0, 0.2f, 1, 0.2f), bound(1), JointInfluences{}};
    influences[1].joints[3] = 40;  // a junk index with zero weight is allowed
    const InfluenceCheck check = normalizeInfluences(influences, 2);
    EXPECT_EQ(check.renormalized, 1u);
    EXPECT_EQ(check.unweighted, 1u);
    EXPECT_FLOAT_EQ(influences[0].weights[0], 0.5f);
    EXPECT_FLOAT_EQ(influences[1].weights[0], 1.0f);

    std::vector<JointInfluences> past{bound(2)};
    try {
        normalizeInfluences(past, 2);
        ADD_FAILURE() << "a weighted joint past the skin was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("vertex 0: joint 2 is past the skin's 2 joints"),
                  std::string::npos)
            << e.what();
    }
    std::vector<JointInfluences> negative{blend(0, 1.5f, 1, -0.5f)};
    EXPECT_THROW(normalizeInfluences(negative, 2), std::invalid_argument);

    // An unweighted vertex stays where its mesh node puts it.
    std::vector<Vec3> p, n;
    std::vector<Vec4> t;
    skinVertices({translationTransform({9, 9, 9})}, {{{1, 2, 3}}, {}, {}, {JointInfluences{}}}, p, n, t);
    expectNear(p[0], {1.0f, 2.0f, 3.0f}, 0.0f, "unweighted");
}

TEST(Skinning, NodeHierarchiesAreCheckedForCyclesAndMissingParents) {
    std::vector<NodePose> poses(3);
    EXPECT_THROW(globalTransforms({1, 2, 0}, poses), std::invalid_argument);
    EXPECT_THROW(globalTransforms({-1, 7, 0}, poses), std::invalid_argument);
    poses[2].translation = {0, 0, 1};
    poses[0].translation = {1, 0, 0};
    // Children before their parents in the list: globals still compose down the chain.
    const std::vector<Affine3> g = globalTransforms({-1, 2, 0}, poses);
    expectNear(g[1].translation(), {1.0f, 0.0f, 1.0f}, 0.0f, "grandchild");
}

}  // namespace
}  // namespace pt
