// CompileOptions::deferBlasesFrom: a mesh at or over the threshold gets a stand-in BLAS (one
// leaf over all its primitives: exact, as brute force is), whose boxes the caller computes for
// its own build (primitiveBoundsOf); smaller meshes and the merged BLAS are built as ever.
#include <gtest/gtest.h>

#include "render/bvh/bvh_test_util.h"
#include "render/compile/compile_geometry.h"
#include "render/compile/compile_scene.h"
#include "render/compile/wide_blases.h"

namespace pt {
namespace {

using test::InstanceSpec;

// A large soup drawn once, a small one drawn at two places (merged where small enough).
CompiledScene compileTwoSoups(uint32_t deferFrom, const Mesh& large, const Mesh& small, bool wideBvh = false,
                              bool compressedWideBvh = false) {
    CompileOptions options;
    options.deferBlasesFrom = deferFrom;
    options.wideBvh = wideBvh;
    options.compressedWideBvh = compressedWideBvh;
    return test::compileTestScene({large, small},
                                  {{0, Affine3{}},
                                   {1, translationTransform(Vec3(3.0f, 0.0f, 0.0f))},
                                   {1, translationTransform(Vec3(-3.0f, 0.0f, 0.0f))}},
                                  options);
}

TEST(DeferredBlas, ALargeMeshGetsAStandInAndItsBoxes) {
    test::Rng rng(12);
    const Mesh large = test::makeSoup(test::SoupKind::Uniform, 5000, rng);
    const Mesh small = test::makeSoup(test::SoupKind::Clustered, 200, rng);
    const CompiledScene built = compileTwoSoups(0, large, small);
    const CompiledScene deferred = compileTwoSoups(1000, large, small);
    EXPECT_TRUE(built.deferredBlases.empty());
    ASSERT_EQ(deferred.deferredBlases.size(), 1u);
    const DeferredBlas& d = deferred.deferredBlases[0];
    EXPECT_EQ(d.blas, 0u);
    // The boxes the caller's build takes, computed in parallel: primitive p's at p.
    const LargeArray<Aabb> boxes = primitiveBoundsOf(deferred, deferred.blases[d.blas]);
    ASSERT_EQ(boxes.size(), 5000u);
    for (uint32_t p = 0; p < 5000; p += 499) {
        const Aabb expected = primitiveBounds(deferred, deferred.blases[0], p);
        EXPECT_EQ(boxes[p].lo, expected.lo);
        EXPECT_EQ(boxes[p].hi, expected.hi);
    }
    // The stand-in: one leaf over every primitive, in order, with the built tree's root box.
    const BlasRef& standIn = deferred.blases[0];
    ASSERT_EQ(standIn.nodeCount, 1u);
    const BvhNode& leaf = deferred.blasNodes[standIn.nodeOffset];
    const BvhNode& root = built.blasNodes[built.blases[0].nodeOffset];
    EXPECT_EQ(leaf.count, 5000u);
    EXPECT_EQ(leaf.leftOrFirst, 0u);
    EXPECT_EQ(leaf.lo, root.lo);
    EXPECT_EQ(leaf.hi, root.hi);
    for (uint32_t p = 0; p < 5000; ++p) ASSERT_EQ(deferred.blasPrimIndices[standIn.primIndexOffset + p], p);
    // The small mesh is built here, as without deferral.
    EXPECT_EQ(deferred.blases[1].nodeCount, built.blases[1].nodeCount);
    EXPECT_GT(deferred.blases[1].nodeCount, 1u);
}

// Also as the CPU's 8-wide form, whose leaf of 3000 triangles is 750 consecutive blocks.
class DeferredBlasLayouts : public ::testing::TestWithParam<bool> {};
INSTANTIATE_TEST_SUITE_P(WideBvh, DeferredBlasLayouts, ::testing::Bool());

TEST_P(DeferredBlasLayouts, TheStandInFindsTheBruteForceHits) {
    test::Rng rng(13);
    const Mesh large = test::makeSoup(test::SoupKind::Uniform, 3000, rng);
    const Mesh small = test::makeSoup(test::SoupKind::Clustered, 300, rng);
    const CompiledScene deferred = compileTwoSoups(1000, large, small, GetParam());
    EXPECT_EQ(deferred.blasWideNodes.empty(), !GetParam());
    const RenderScene view = deferred.view();
    int failures = 0, hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const Ray ray = i % 2 ? test::rayAtTriangle(rng, large, Vec3(-5.0f), Vec3(5.0f))
                              : test::randomRay(rng, Vec3(-5.0f), Vec3(5.0f));
        hits += test::expectBvhMatchesBruteForce(view, ray, failures);
    }
    EXPECT_GT(hits, 200) << "too few rays hit to test anything";
}

// With the GPU's compressed nodes too: the stand-in leaf holds more primitives than a compressed
// leaf can, so the deferred BLAS gets an empty compressed tree (its caller walks the binary tree
// it builds: the CUDA backend drops the compressed root), and the others their compressed trees.
TEST(DeferredBlas, WithCompressedNodesADeferredMeshGetsAnEmptyCompressedTree) {
    test::Rng rng(15);
    const Mesh large = test::makeSoup(test::SoupKind::Uniform, 3000, rng);
    const Mesh small = test::makeSoup(test::SoupKind::Clustered, 300, rng);
    const CompiledScene deferred = compileTwoSoups(1000, large, small, false, true);
    ASSERT_EQ(deferred.deferredBlases.size(), 1u);
    const uint32_t standIn = deferred.deferredBlases[0].blas;
    ASSERT_EQ(deferred.blasCompressedRoots.size(), deferred.blases.size());
    for (uint32_t b = 0; b < deferred.blases.size(); ++b) {
        const auto [first, end] = compressedPrimRange(deferred, b);
        EXPECT_EQ(end - first, b == standIn ? 0u : deferred.blases[b].primitiveCount) << "BLAS " << b;
    }
    // The CUDA backend's view of it: the deferred BLAS's binary nodes, the others' compressed.
    std::vector<uint32_t> roots = deferred.blasCompressedRoots;
    roots[standIn] = kNoCompressedRoot;
    RenderScene view = deferred.view();
    view.blasCompressedRoots = {roots.data(), uint32_t(roots.size())};
    int failures = 0, hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const Ray ray = i % 2 ? test::rayAtTriangle(rng, i % 4 == 1 ? large : small, Vec3(-5.0f), Vec3(5.0f))
                              : test::randomRay(rng, Vec3(-5.0f), Vec3(5.0f));
        hits += test::expectBvhMatchesBruteForce(view, ray, failures);
    }
    EXPECT_GT(hits, 200) << "too few rays hit to test anything";
}

TEST(DeferredBlas, TheMergedBlasIsNeverDeferred) {
    test::Rng rng(14);
    const Mesh large = test::makeSoup(test::SoupKind::Uniform, 2000, rng);
    const Mesh small = test::makeSoup(test::SoupKind::Clustered, 1500, rng);
    const CompiledScene deferred = compileTwoSoups(1000, large, small);
    ASSERT_TRUE(deferred.merged.active()) << "no merged BLAS to test";
    ASSERT_GE(deferred.blases[deferred.merged.blas].primitiveCount, 1000u);
    for (const DeferredBlas& d : deferred.deferredBlases) EXPECT_NE(d.blas, deferred.merged.blas);
    EXPECT_GT(deferred.blases[deferred.merged.blas].nodeCount, 1u);
}

}  // namespace
}  // namespace pt
