// applyMorphWeights on hand-made meshes: exact sums, zero weights restoring the base vertices
// bit for bit, renormalized normals, and a broken invariant reported instead of read past.
#include "render/scene/morph.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <stdexcept>

namespace pt {
namespace {

bool sameBits(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}

// Two vertices, two targets; all values dyadic so that every sum below is exact.
Mesh twoTargetMesh() {
    Mesh mesh;
    mesh.name = "hand";
    mesh.basePositions = {{1.0f, 2.0f, 3.0f}, {-0.0f, 0.1f, -4.0f}};
    mesh.baseNormals = {{0.0f, 0.0f, 1.0f}, {0.6f, 0.0f, 0.8f}};
    mesh.positions = mesh.basePositions;
    mesh.normals = mesh.baseNormals;
    mesh.morphTargets = {
        {"a", {{2.0f, 0.0f, 0.0f}, {0.0f, 0.5f, 0.0f}}, {{1.0f, 0.0f, -1.0f}, {0.0f, 0.0f, 0.0f}}},
        {"b", {{0.0f, 1.0f, 0.5f}, {0.25f, 0.0f, 1.0f}}, {}},
    };
    mesh.morphWeights = {0.0f, 0.0f};
    return mesh;
}

TEST(Morph, PositionsAreBasePlusWeightedDeltas) {
    Mesh mesh = twoTargetMesh();
    mesh.morphWeights = {0.5f, -2.0f};  // glTF allows weights outside [0, 1]
    applyMorphWeights(mesh);
    // (1, 2, 3) + 0.5 (2, 0, 0) - 2 (0, 1, 0.5); (-0, 0.1, -4) + 0.5 (0, 0.5, 0) - 2 (0.25, 0, 1)
    EXPECT_EQ(mesh.positions[0], Vec3(2.0f, 0.0f, 2.0f));
    EXPECT_EQ(mesh.positions[1], Vec3(-0.5f, 0.1f + 0.25f, -6.0f));
}

TEST(Morph, ZeroWeightsRestoreTheBaseBitForBit) {
    Mesh mesh = twoTargetMesh();
    mesh.morphWeights = {0.7f, 0.3f};
    applyMorphWeights(mesh);
    EXPECT_FALSE(sameBits(mesh.positions, mesh.basePositions));
    EXPECT_FALSE(sameBits(mesh.normals, mesh.baseNormals));
    mesh.morphWeights = {0.0f, 0.0f};
    applyMorphWeights(mesh);
    EXPECT_TRUE(sameBits(mesh.positions, mesh.basePositions)) << "the -0 coordinate must stay -0";
    EXPECT_TRUE(sameBits(mesh.normals, mesh.baseNormals)) << "unit normals must not be renormalized";
}

TEST(Morph, NormalsAreRenormalized) {
    Mesh mesh = twoTargetMesh();
    mesh.morphWeights = {0.5f, 0.0f};
    applyMorphWeights(mesh);
    // (0, 0, 1) + 0.5 (1, 0, -1) = (0.5, 0, 0.5): unit length after renormalizing.
    const float half = std::sqrt(0.5f);
    EXPECT_NEAR(mesh.normals[0].x, half, 1e-6f);
    EXPECT_EQ(mesh.normals[0].y, 0.0f);
    EXPECT_NEAR(mesh.normals[0].z, half, 1e-6f);
    EXPECT_NEAR(length(mesh.normals[1]), 1.0f, 1e-6f);
    EXPECT_NEAR(mesh.normals[1].x, 0.6f, 1e-6f) << "a zero normal delta leaves the normal's direction";
}

TEST(Morph, AZeroNormalKeepsTheBaseNormal) {
    Mesh mesh = twoTargetMesh();
    mesh.morphTargets[0].normalDeltas[0] = {0.0f, 0.0f, -1.0f};
    mesh.morphWeights = {1.0f, 0.0f};
    applyMorphWeights(mesh);
    EXPECT_EQ(mesh.normals[0], Vec3(0.0f, 0.0f, 1.0f));
}

TEST(Morph, AMeshWithoutTargetsIsLeftUntouched) {
    Mesh mesh;
    mesh.positions = {{1.0f, 2.0f, 3.0f}};
    mesh.normals = {{0.0f, 1.0f, 0.0f}};
    EXPECT_FALSE(hasMorphTargets(mesh));
    applyMorphWeights(mesh);
    EXPECT_EQ(mesh.positions[0], Vec3(1.0f, 2.0f, 3.0f));
    EXPECT_EQ(mesh.normals[0], Vec3(0.0f, 1.0f, 0.0f));
    EXPECT_TRUE(hasMorphTargets(twoTargetMesh()));
}

TEST(Morph, MismatchedWeightsOrDeltasAreRefused) {
    Mesh mesh = twoTargetMesh();
    mesh.morphWeights = {1.0f};
    EXPECT_THROW(applyMorphWeights(mesh), std::invalid_argument);
    mesh = twoTargetMesh();
    mesh.morphTargets[1].positionDeltas.pop_back();
    EXPECT_THROW(applyMorphWeights(mesh), std::invalid_argument);
}

}  // namespace
}  // namespace pt
