// The runtime choice of the CPU wide walk's SIMD level (render/bvh/wide_walk_simd.h): it starts
// at the widest level the processor runs, a level it does not run is refused, and every level
// finds the same hits, bit for bit, walking the same nodes but where a ray grazes a box (the
// levels' node tests round differently), and testing the same triangles (except that an
// any-hit query that hits may count up to one block more at AVX2, which tests a leaf's two
// blocks at once). (Each level against brute force: the Layouts suites' Wide and
// WideSse2.)
#include "render/bvh/wide_walk_simd.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "render/bvh/bvh_test_util.h"
#include "render/math/float_error.h"

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
        uint32_t hits = 0, differ = 0, visitsDiffer = 0, anyDiffer = 0, anyMore = 0;
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
                      hit[0].instance != hit[1].instance || any[0] != any[1];
            // The levels' node tests round differently (AVX2's fused planes, wide_walk_avx2.h):
            // both conservative, so a box a ray grazes within a few float steps may be entered
            // at one level and culled at the other, and the visits may differ by a node or so.
            visitsDiffer += stats[0].nodesVisited != stats[1].nodesVisited ||
                            stats[0].primitivesTested != stats[1].primitivesTested ||
                            anyStats[0].nodesVisited != anyStats[1].nodesVisited;
            // An any-hit query ends at the first test that hits: AVX2 tests a leaf's two blocks
            // at once, SSE2 the first alone, so where it hits AVX2 may count up to a block more,
            // never fewer; where it misses, both test every leaf they reach in full.
            const uint32_t sse2Tested = anyStats[0].primitivesTested,
                           avx2Tested = anyStats[1].primitivesTested;
            // (Where the walks visited the same nodes.)
            if (anyStats[0].nodesVisited == anyStats[1].nodesVisited) {
                anyDiffer += any[0]
                                 ? avx2Tested < sse2Tested || avx2Tested > sse2Tested + TriangleBlock::kWidth
                                 : avx2Tested != sse2Tested;
            }
            anyMore += avx2Tested > sse2Tested;
        }
        EXPECT_EQ(differ, 0u);
        EXPECT_LE(visitsDiffer, 20u) << "of 20000 rays: the levels' tests should differ only at grazes";
        EXPECT_EQ(anyDiffer, 0u);
        EXPECT_GT(anyMore, 0u) << "some any-hit rays should stop in a leaf's first block";
        EXPECT_GT(hits, 5000u) << "the rays should hit often enough to test something";
    }
}

// The node test at each level against exact arithmetic: eight boxes a node, each built
// around a point of the ray (which it must enter, whatever the roundings, at a distance no
// farther than that point's), off the ray, behind its origin or past tMax by a clear margin
// (which it must cull), or unused (an empty box, never entered). Rays from origins of every
// scale, with zero axes, and from 1e9 along a zero axis, whose plane offsets overflow and which
// AVX2 tests unfused (wide_walk_avx2.h).
TEST(WideWalkSimd, NodeTestsEnterEveryBoxOnTheRayAndCullThoseOffIt) {
    Rng rng(2121);
    const double kScales[] = {1e-3, 1.0, 1e3, 1e6, 1e9};
    const bool avx2 = supportedSimdLevel() == SimdLevel::Avx2;
    uint32_t missedEntered[2] = {0, 0}, keptMissed[2] = {0, 0}, enteredUnused[2] = {0, 0};
    uint32_t entryBeyond[2] = {0, 0};
    uint32_t onRay = 0, offRay = 0;
    for (int i = 0; i < 20000; ++i) {
        const double scale = kScales[rng.index(5)];
        const Vec3 origin = rng.inBox(Vec3(-2.0f), Vec3(2.0f)) * float(scale);
        Vec3 direction = rng.unitVector();
        if (i % 4 == 0) direction[int(rng.index(3))] = rng.uniform() < 0.5f ? 0.0f : -0.0f;
        const float tMax = i % 3 == 0 ? rng.uniform(0.0f, 4.0f) * float(scale) : kInf;
        const TraversalRay ray = makeTraversalRay(origin, direction);
        const double reach = std::min(double(tMax), 4.0 * scale);
        WideBvhNode node{};
        enum Kind { kOnRay, kOffRay, kBehind, kPastTMax, kUnused } kinds[WideBvhNode::kWidth];
        double pointAt[WideBvhNode::kWidth];
        for (uint32_t s = 0; s < WideBvhNode::kWidth; ++s) {
            Kind kind = Kind(rng.index(5));
            if (kind == kPastTMax && tMax == kInf) kind = kOffRay;
            kinds[s] = kind;
            node.child[s] = 0, node.count[s] = kind == kUnused ? WideBvhNode::kEmpty : 1u;
            if (kind == kUnused) {
                node.loX[s] = node.loY[s] = node.loZ[s] = kInf;
                node.hiX[s] = node.hiY[s] = node.hiZ[s] = -kInf;
                continue;
            }
            // A point of the exact line, in double, and a box around it: for one on the ray, a
            // margin far above double's rounding (and some boxes flat on an axis); off the ray,
            // moved away across the direction by more than the box's half diagonal; behind the
            // origin, smaller than its distance along the direction's largest axis, so that
            // the ray leaves that slab before t = 0; past tMax, a hundredth of tMax beyond.
            const double t = kind == kPastTMax ? double(tMax) * 1.01 + 1e-3 * scale
                             : kind == kBehind ? -(1e-3 * scale + 1e-5 + rng.uniform() * reach)
                                               : rng.uniform() * reach;
            pointAt[s] = t;
            double point[3], away[3] = {0.0, 0.0, 0.0}, half = 0.0;
            for (int a = 0; a < 3; ++a) point[a] = double(origin[a]) + t * double(direction[a]);
            if (kind == kOffRay) {
                const Vec3 side = normalize(cross(direction, rng.unitVector()));
                // At least ten times a zero axis's padding (2^-20 of max(|origin|, 1), bvh_walk.h),
                // within which the slab test enters boxes by design.
                const double gap = 1e-3 * (scale + t) + 1e-5;
                for (int a = 0; a < 3; ++a) away[a] = double(side[a]) * gap;
                half = 0.25 * gap;
            } else if (kind == kBehind) {
                const Vec3 a = vabs(direction);
                half = -0.25 * t * double(std::max(a.x, std::max(a.y, a.z)));
            } else if (kind == kPastTMax) {
                half = 1e-4 * double(tMax);
            } else {
                half = rng.uniform() < 0.3f ? 0.0 : double(rng.uniform()) * scale;
            }
            float lo[3], hi[3];
            for (int a = 0; a < 3; ++a) {
                const double margin = 1e-12 * (std::fabs(point[a]) + scale);
                const double low = point[a] + away[a] - half - (kind == kOnRay ? margin : 0.0);
                const double high = point[a] + away[a] + half + (kind == kOnRay ? margin : 0.0);
                lo[a] = float(low), hi[a] = float(high);
                if (double(lo[a]) > low) lo[a] = nextFloatDown(lo[a]);
                if (double(hi[a]) < high) hi[a] = nextFloatUp(hi[a]);
            }
            node.loX[s] = lo[0], node.loY[s] = lo[1], node.loZ[s] = lo[2];
            node.hiX[s] = hi[0], node.hiY[s] = hi[1], node.hiZ[s] = hi[2];
            onRay += kind == kOnRay;
            offRay += kind != kOnRay;
        }
        for (int level = 0; level < (avx2 ? 2 : 1); ++level) {
            float entry[WideBvhNode::kWidth];
            const int hits = level ? simd_detail::intersectWideNodeAvx2(node, ray, tMax, entry)
                                   : simd_detail::intersectWideNodeSse2(node, ray, tMax, entry);
            for (uint32_t s = 0; s < WideBvhNode::kWidth; ++s) {
                const bool entered = hits >> s & 1;
                missedEntered[level] += kinds[s] == kOnRay && !entered;
                // The exact entry is at most the point's distance; the test's, rounded up to a
                // few float steps beyond it.
                entryBeyond[level] +=
                    kinds[s] == kOnRay && entered &&
                    !(entry[s] >= 0.0f && double(entry[s]) <= pointAt[s] * (1.0 + 1e-6) + 1e-30);
                keptMissed[level] += kinds[s] != kOnRay && kinds[s] != kUnused && entered;
                enteredUnused[level] += kinds[s] == kUnused && entered;
            }
        }
    }
    for (int level = 0; level < (avx2 ? 2 : 1); ++level) {
        SCOPED_TRACE(level ? "AVX2" : "SSE2");
        EXPECT_EQ(missedEntered[level], 0u) << "boxes the ray enters, culled";
        EXPECT_EQ(entryBeyond[level], 0u) << "entries beyond the point the box was built around";
        EXPECT_EQ(keptMissed[level], 0u) << "boxes off the ray, behind it or past tMax, entered";
        EXPECT_EQ(enteredUnused[level], 0u) << "unused slots entered";
    }
    EXPECT_GT(onRay, 20000u);
    EXPECT_GT(offRay, 60000u);
}

// Directions with infinite components (an inverse of 0, whose plane distances are inf * 0 =
// NaN) and NaN ones: an unused slot is never entered at either level, however the NaNs fall.
TEST(WideWalkSimd, NodeTestsNeverEnterUnusedSlotsOfNaNRays) {
    const float inf = kInf, nan = std::numeric_limits<float>::quiet_NaN();
    const Vec3 directions[] = {{1.0f, inf, inf},    {inf, inf, inf},   {-inf, 0.0f, 1.0f},
                               {0.0f, -inf, -0.0f}, {nan, 1.0f, 0.0f}, {inf, nan, -inf}};
    WideBvhNode node{};
    for (uint32_t s = 0; s < WideBvhNode::kWidth; ++s) {
        node.loX[s] = node.loY[s] = node.loZ[s] = kInf;
        node.hiX[s] = node.hiY[s] = node.hiZ[s] = -kInf;
        node.count[s] = WideBvhNode::kEmpty;
    }
    const bool avx2 = supportedSimdLevel() == SimdLevel::Avx2;
    for (const Vec3& direction : directions) {
        for (const float tMax : {1.0f, kInf}) {
            const TraversalRay ray = makeTraversalRay(Vec3(0.25f, -0.5f, 2.0f), direction);
            float entry[WideBvhNode::kWidth];
            EXPECT_EQ(simd_detail::intersectWideNodeSse2(node, ray, tMax, entry), 0);
            if (avx2) {
                EXPECT_EQ(simd_detail::intersectWideNodeAvx2(node, ray, tMax, entry), 0);
            }
        }
    }
}

}  // namespace
}  // namespace pt
