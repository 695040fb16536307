// Host refits (issue 16): after every vertex of a mesh moves, the refitted BLAS bounds what it
// holds (every node contains its children's boxes and its primitives) and closest hits through
// it equal brute force; a topology edit is refused. The CPU backend's use of it is in
// tests/render/backend/sync_plan_test.cpp.
#include "render/compile/host_refit.h"

#include <gtest/gtest.h>

#include <cmath>

#include "render/bvh/bvh_test_util.h"
#include "render/bvh/traversal.h"
#include "render/compile/compile_geometry.h"

namespace pt {
namespace {

using test::Rng;
using test::SoupKind;

Scene soupScene(SoupKind kind, uint32_t triangles, Rng& rng) {
    Scene scene;
    scene.meshes.push_back(test::makeSoup(kind, triangles, rng));
    Instance instance;
    instance.mesh = 0;
    scene.instances.push_back(instance);
    return scene;
}

bool contains(const BvhNode& outer, Aabb inner) {
    return inner.empty() ||
           (outer.lo.x <= inner.lo.x && outer.lo.y <= inner.lo.y && outer.lo.z <= inner.lo.z &&
            outer.hi.x >= inner.hi.x && outer.hi.y >= inner.hi.y && outer.hi.z >= inner.hi.z);
}

// Every node bounds its children and its primitives, and the root is no larger than they are.
void expectBlasBounds(const CompiledScene& compiled, uint32_t index) {
    const BlasRef& blas = compiled.blases[index];
    const BvhNode* nodes = compiled.blasNodes.data() + blas.nodeOffset;
    const uint32_t* prims = compiled.blasPrimIndices.data() + blas.primIndexOffset;
    int failures = 0;
    Aabb all;
    for (uint32_t p = 0; p < blas.primitiveCount; ++p) all.grow(primitiveBounds(compiled, blas, p));
    EXPECT_EQ(nodes[0].lo, all.lo);
    EXPECT_EQ(nodes[0].hi, all.hi);
    for (uint32_t i = 0; i < blas.nodeCount; ++i) {
        const BvhNode& node = nodes[i];
        if (node.isLeaf()) {
            for (uint32_t k = 0; k < node.count; ++k)
                failures += !contains(node, primitiveBounds(compiled, blas, prims[node.leftOrFirst + k]));
        } else {
            for (uint32_t c = 0; c < 2; ++c) {
                const BvhNode& child = nodes[node.leftOrFirst + c];
                failures += !contains(node, Aabb{child.lo, child.hi});
            }
        }
    }
    EXPECT_EQ(failures, 0);
}

TEST(HostRefit, AfterEveryVertexMovesHitsMatchBruteForce) {
    Rng rng(11);
    for (const SoupKind kind : {SoupKind::Uniform, SoupKind::Clustered, SoupKind::Needles}) {
        SCOPED_TRACE(test::soupName(kind));
        Scene scene = soupScene(kind, 3000, rng);
        CompiledScene compiled = compileRenderScene(scene);
        // A twist about y and a ripple: every box changes, the tree's topology stays.
        for (Vec3& p : scene.meshes[0].positions) {
            const float angle = 0.6f * p.y;
            p = {p.x * std::cos(angle) - p.z * std::sin(angle), p.y + 0.05f * std::sin(7.0f * p.x),
                 p.x * std::sin(angle) + p.z * std::cos(angle)};
        }
        const std::optional<std::vector<uint32_t>> moved = copyMovedMeshes(scene, TouchedIds{}, compiled);
        ASSERT_TRUE(moved.has_value());
        ASSERT_EQ(*moved, std::vector<uint32_t>{0});
        const float before = blasSahCost(compiled, 0);
        refitBlasOnHost(compiled, 0);
        EXPECT_NE(blasSahCost(compiled, 0), before);
        expectBlasBounds(compiled, 0);
        buildTlas(compiled);  // from the refitted root
        const RenderScene view = compiled.view();
        int failures = 0;
        uint32_t hits = 0;
        for (uint32_t i = 0; i < 20000; ++i) {
            const Ray ray = i % 2 ? test::randomRay(rng, Vec3(-1.5f), Vec3(1.5f))
                                  : test::rayAtTriangle(rng, scene.meshes[0], Vec3(-1.5f), Vec3(1.5f));
            hits += test::expectBvhMatchesBruteForce(view, ray, failures);
        }
        EXPECT_EQ(failures, 0);
        EXPECT_GT(hits, 5000u);
    }
}

TEST(HostRefit, UnmovedMeshesAreLeftAloneAndTopologyEditsRefused) {
    Rng rng(12);
    Scene scene = soupScene(SoupKind::Uniform, 100, rng);
    CompiledScene compiled = compileRenderScene(scene);
    EXPECT_EQ(copyMovedMeshes(scene, TouchedIds{}, compiled), std::vector<uint32_t>{});
    scene.meshes[0].positions.push_back(Vec3(0.0f));
    scene.meshes[0].indices.insert(scene.meshes[0].indices.end(), {0, 1, 300});
    EXPECT_FALSE(copyMovedMeshes(scene, TouchedIds{}, compiled).has_value()) << "a triangle more";
    scene.meshes.push_back(scene.meshes[0]);
    EXPECT_FALSE(copyMovedMeshes(scene, TouchedIds{}, compiled).has_value()) << "a mesh more";
}

// An edit that names the meshes it moved (a morph-weight drag) has only those compared and
// copied: a mesh it did not name keeps its compiled vertices until an edit names it.
TEST(HostRefit, OnlyTheMeshesAnEditNamesAreCompared) {
    Rng rng(13);
    Scene scene = soupScene(SoupKind::Uniform, 100, rng);
    scene.meshes.push_back(test::makeSoup(SoupKind::Uniform, 100, rng));
    Instance second;
    second.mesh = 1;
    scene.instances.push_back(second);
    CompiledScene compiled = compileRenderScene(scene);
    for (Mesh& mesh : scene.meshes) {
        for (Vec3& p : mesh.positions) p = p * 1.5f;
    }
    const Vec3 firstOfMesh0 = compiled.positions[0];
    EXPECT_EQ(copyMovedMeshes(scene, TouchedIds::only({1}), compiled), std::vector<uint32_t>{1});
    EXPECT_EQ(compiled.positions[0], firstOfMesh0) << "mesh 0 was not named";
    EXPECT_EQ(compiled.positions[scene.meshes[0].positions.size()], scene.meshes[1].positions[0]);
    EXPECT_EQ(copyMovedMeshes(scene, TouchedIds{}, compiled), std::vector<uint32_t>{0})
        << "an edit that names none compares them all; mesh 1 is current already";
    EXPECT_EQ(compiled.positions[0], scene.meshes[0].positions[0]);
}

}  // namespace
}  // namespace pt
