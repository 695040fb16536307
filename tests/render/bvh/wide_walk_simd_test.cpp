// The runtime choice of the CPU wide walk's SIMD level (render/bvh/wide_walk_simd.h): it starts
// at the widest level the processor runs, a level it does not run is refused, and every level
// walks the same nodes, tests the same triangles (except that an any-hit query that hits may
// count up to one block more at AVX2, which tests a leaf's two blocks at once) and finds the
// same hits, bit for bit. (Each level against brute force: the Layouts suites' Wide and
// WideSse2.)
#include "render/bvh/wide_walk_simd.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "render/bvh/bvh_test_util.h"

namespace pt {
namespace {

using test::Rng;

TEST(WideWalkSimd, TheWalkStartsAtTheWidestLevelTheProcessorRuns) {
    EXPECT_EQ(wideWalkSimdLevel(), supportedSimdLevel());
    {
        const ScopedSimdLevel sse2(SimdLevel::Sse2);
        EXPECT_EQ(wideWalkSimdLevel(), SimdLevel::Sse2);
    }
    EXPECT_EQ(wideWalkSimdLevel(), supportedSimdLevel());
    if (supportedSimdLevel() == SimdLevel::Sse2) {
        EXPECT_THROW(setWideWalkSimdLevel(SimdLevel::Avx2), std::invalid_argument);
        EXPECT_EQ(wideWalkSimdLevel(), SimdLevel::Sse2);
    }
    EXPECT_STREQ(simdLevelName(SimdLevel::Avx2), "AVX2");
}

// Closest and any hits, and the work counted, at SSE2 and at AVX2, on soups that stress the
// walk differently and on rays of every kind (hits behind others, misses, finite segments,
// rays along axes).
TEST(WideWalkSimd, EveryLevelWalksTheSameNodesToTheSameHits) {
    if (supportedSimdLevel() != SimdLevel::Avx2) GTEST_SKIP() << "this processor runs no AVX2";
    Rng rng(21);
    for (const test::SoupKind kind :
         {test::SoupKind::Uniform, test::SoupKind::Clustered, test::SoupKind::Needles}) {
        SCOPED_TRACE(test::soupName(kind));
        const Mesh mesh = test::makeSoup(kind, 20000, rng);
        const CompiledScene compiled = test::compileSingleMesh(mesh, test::Layout::Wide);
        const RenderScene scene = compiled.view();
        uint32_t hits = 0, differ = 0, anyDiffer = 0, anyMore = 0;
        for (int i = 0; i < 20000; ++i) {
            Ray ray = i % 2 ? test::randomRay(rng, Vec3(-1.2f), Vec3(1.2f))
                            : test::rayAtTriangle(rng, mesh, Vec3(-1.2f), Vec3(1.2f));
            if (i % 5 == 0) ray.tMax = rng.uniform(0.0f, 1.5f);
            if (i % 3 == 0) {
                // Along one or two axes: zero components of either sign, whose slab test
                // measures from padded origins (bvh_walk.h), and whose nearer plane AVX2 picks by
                // the sign of the inverse.
                const int kept = int(rng.index(3));
                for (int a = 0; a < 3; ++a) {
                    if (a != kept && rng.uniform(0.0f, 1.0f) < 0.6f)
                        ray.direction[a] = rng.uniform(0.0f, 1.0f) < 0.5f ? 0.0f : -0.0f;
                }
            }
            Hit hit[2];
            TraversalStats stats[2], anyStats[2];
            bool any[2];
            for (const SimdLevel level : {SimdLevel::Sse2, SimdLevel::Avx2}) {
                const ScopedSimdLevel scoped(level);
                const int l = level == SimdLevel::Avx2;
                intersectClosest(scene, ray, hit[l], &stats[l]);
                any[l] = intersectAny(scene, ray, &anyStats[l]);
            }
            hits += hit[0].valid();
            differ += hit[0].valid() != hit[1].valid() || hit[0].t != hit[1].t || hit[0].u != hit[1].u ||
                      hit[0].v != hit[1].v || hit[0].primitive != hit[1].primitive ||
                      hit[0].instance != hit[1].instance || any[0] != any[1] ||
                      stats[0].nodesVisited != stats[1].nodesVisited ||
                      stats[0].primitivesTested != stats[1].primitivesTested ||
                      anyStats[0].nodesVisited != anyStats[1].nodesVisited;
            // An any-hit query ends at the first test that hits: AVX2 tests a leaf's two blocks
            // at once, SSE2 the first alone, so where it hits AVX2 may count up to a block more,
            // never fewer; where it misses, both test every leaf they reach in full.
            const uint32_t sse2Tested = anyStats[0].primitivesTested,
                           avx2Tested = anyStats[1].primitivesTested;
            anyDiffer += any[0] ? avx2Tested < sse2Tested || avx2Tested > sse2Tested + TriangleBlock::kWidth
                                : avx2Tested != sse2Tested;
            anyMore += avx2Tested > sse2Tested;
        }
        EXPECT_EQ(differ, 0u);
        EXPECT_EQ(anyDiffer, 0u);
        EXPECT_GT(anyMore, 0u) << "some any-hit rays should stop in a leaf's first block";
        EXPECT_GT(hits, 5000u) << "the rays should hit often enough to test something";
    }
}

}  // namespace
}  // namespace pt
