// The CPU's four-triangle leaves (render/kernel/triangle_block.h): each lane of the SSE test
// equals the scalar watertight test bit for bit (t, u, v and whether it hits), on ordinary
// triangles, on rays through shared vertices and edges (the exact zero edge functions the
// double-precision branch redoes), on degenerate triangles and at t == tMax; and the leaf
// functor keeps the walk's rule: the closest t, ties to the lower primitive. (Hits through whole
// scenes are the Layouts suites' business: traversal, two-level and watertight tests.)
#include <gtest/gtest.h>

#include <cstring>

#include "render/bvh/bvh_test_util.h"
#include "render/bvh/triangle_block_intersect.h"

namespace pt {
namespace {

using test::Rng;

struct Triangle {
    Vec3 p[3];
};

TriangleBlock blockOf(const Triangle (&tris)[TriangleBlock::kWidth]) {
    TriangleBlock block;
    for (uint32_t lane = 0; lane < TriangleBlock::kWidth; ++lane) {
        for (int c = 0; c < 3; ++c) {
            for (int axis = 0; axis < 3; ++axis) block.corner[c][axis][lane] = tris[lane].p[c][axis];
        }
        block.primitive[lane] = lane;
    }
    return block;
}

uint32_t bits(float f) {
    uint32_t b;
    std::memcpy(&b, &f, sizeof b);
    return b;
}

// Every lane against intersectTriangle on the same ray and tMax; returns the lanes that hit.
int expectLanesMatchScalar(const Triangle (&tris)[TriangleBlock::kWidth], const Ray& ray, float tMax) {
    const WatertightRay wray = makeWatertightRay(ray.origin, ray.direction);
    __m128 t = _mm_setzero_ps(), u = t, v = t;
    const int lanes = intersectTriangleBlock(wray, tMax, blockOf(tris), t, u, v);
    alignas(16) float ts[4], us[4], vs[4];
    _mm_store_ps(ts, t), _mm_store_ps(us, u), _mm_store_ps(vs, v);
    for (uint32_t lane = 0; lane < TriangleBlock::kWidth; ++lane) {
        float st = 0.0f, su = 0.0f, sv = 0.0f;
        const bool scalar =
            intersectTriangle(wray, tMax, tris[lane].p[0], tris[lane].p[1], tris[lane].p[2], st, su, sv);
        EXPECT_EQ(scalar, ((lanes >> lane) & 1) != 0) << "lane " << lane;
        if (scalar && ((lanes >> lane) & 1)) {
            EXPECT_EQ(bits(st), bits(ts[lane])) << "lane " << lane << " t " << st << " vs " << ts[lane];
            EXPECT_EQ(bits(su), bits(us[lane])) << "lane " << lane;
            EXPECT_EQ(bits(sv), bits(vs[lane])) << "lane " << lane;
        }
    }
    return lanes;
}

TEST(TriangleBlock, LanesEqualTheScalarTestOnRandomTriangles) {
    Rng rng(5);
    int hits = 0;
    for (int i = 0; i < 20000; ++i) {
        Triangle tris[TriangleBlock::kWidth];
        for (Triangle& tri : tris) {
            const Vec3 c = rng.inBox(Vec3(-1.0f), Vec3(1.0f));
            for (Vec3& p : tri.p) p = c + rng.inBox(Vec3(-0.5f), Vec3(0.5f));
        }
        // Aimed at a point of lane 0's triangle: many hits, some behind the others.
        const float a = rng.uniform() * 0.5f, b = rng.uniform() * 0.5f;
        const Vec3 target = tris[0].p[0] * (1.0f - a - b) + tris[0].p[1] * a + tris[0].p[2] * b;
        const Vec3 origin = rng.inBox(Vec3(-3.0f), Vec3(3.0f));
        const float tMax = rng.uniform() < 0.2f ? rng.uniform(0.1f, 1.5f) : kInf;
        hits +=
            __builtin_popcount(unsigned(expectLanesMatchScalar(tris, {origin, target - origin, kInf}, tMax)));
        if (HasFailure()) return;
    }
    EXPECT_GT(hits, 15000) << "the rays should mostly hit lane 0 at least";
}

// Integer corners and rays through them: edge functions come out exactly zero, which the
// scalar test (and each lane) redoes in double.
TEST(TriangleBlock, RaysThroughSharedVerticesAndEdgesTakeTheExactBranchAlike) {
    Rng rng(9);
    int hits = 0;
    for (int i = 0; i < 5000; ++i) {
        // A quad of two triangles (a shared diagonal) and two more sharing its corner (0, 0).
        const Triangle tris[TriangleBlock::kWidth] = {
            {{{0, 0, 0}, {4, 0, 0}, {4, 4, 0}}},
            {{{0, 0, 0}, {4, 4, 0}, {0, 4, 0}}},
            {{{0, 0, 0}, {-4, 0, 0}, {0, -4, 0}}},
            {{{0, 0, 0}, {0, -4, 0}, {4, 0, 0}}},
        };
        const Vec3 targets[] = {{0, 0, 0}, {2, 2, 0},  {4, 0, 0}, {2, 0, 0},
                                {0, 2, 0}, {-2, 0, 0}, {1, -1, 0}};
        const Vec3 target = targets[rng.index(7)];
        const Vec3 origin =
            Vec3(float(int(rng.index(9)) - 4), float(int(rng.index(9)) - 4), float(1 + rng.index(5)));
        hits +=
            __builtin_popcount(unsigned(expectLanesMatchScalar(tris, {origin, target - origin, kInf}, kInf)));
        if (HasFailure()) return;
    }
    EXPECT_GT(hits, 5000) << "rays at shared corners and edges hit every triangle holding them";
}

TEST(TriangleBlock, DegenerateTrianglesAndRaysInThePlaneMissInEveryLane) {
    const Triangle tris[TriangleBlock::kWidth] = {
        {{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}},     // collinear
        {{{1, 1, 1}, {1, 1, 1}, {1, 1, 1}}},     // a point
        {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}},     // the ray lies in its plane
        {{{0, 0, -1}, {1, 0, -1}, {0, 1, -1}}},  // behind the origin
    };
    EXPECT_EQ(expectLanesMatchScalar(tris, {{-1, 0.25f, 0}, {1, 0, 0}, kInf}, kInf), 0);
    EXPECT_EQ(expectLanesMatchScalar(tris, {{0.5f, 0, 0}, {0, 0, 1}, kInf}, kInf), 0);
}

TEST(TriangleBlock, AHitAtExactlyTMaxMissesAndOneUlpFurtherHits) {
    Triangle tris[TriangleBlock::kWidth];
    for (uint32_t lane = 0; lane < TriangleBlock::kWidth; ++lane) {
        const float z = 1.0f + 0.25f * float(lane);
        tris[lane] = {{{-1, -1, z}, {1, -1, z}, {0, 1, z}}};
    }
    const Ray ray{{0, 0, 0}, {0, 0, 1}, kInf};
    EXPECT_EQ(expectLanesMatchScalar(tris, ray, kInf), 0b1111);
    EXPECT_EQ(expectLanesMatchScalar(tris, ray, 1.5f), 0b0011);  // t == 1.5 is not < 1.5
    EXPECT_EQ(expectLanesMatchScalar(tris, ray, intAsFloat(floatAsInt(1.5f) + 1)), 0b0111);
}

// The functor's answer over four lanes: the closest t, ties to the lower primitive, whatever
// lane holds it; and a tie with a hit an earlier leaf found goes to the lower primitive too.
TEST(TriangleBlock, TheLeafKeepsTheClosestHitAndTiesGoToTheLowerPrimitive) {
    Triangle tris[TriangleBlock::kWidth];
    const float z[TriangleBlock::kWidth] = {3.0f, 2.0f, 2.0f, 5.0f};
    for (uint32_t lane = 0; lane < TriangleBlock::kWidth; ++lane) {
        tris[lane] = {{{-1, -1, z[lane]}, {1, -1, z[lane]}, {0, 1, z[lane]}}};
    }
    TriangleBlock block = blockOf(tris);
    const uint32_t primitives[TriangleBlock::kWidth] = {40, 31, 17, 2};
    std::memcpy(block.primitive, primitives, sizeof primitives);
    const TraversalRay ray = makeTraversalRay({0, 0, 0}, {0, 0, 1});
    {
        Hit hit;
        TriangleBlockLeaf<NoTraversalCount> leaf{&block, ray, hit, {}, false};
        float tMax = kInf;
        ASSERT_TRUE(leaf(0, 4, tMax));
        EXPECT_EQ(tMax, 2.0f);
        EXPECT_EQ(hit.primitive, 17u) << "lanes 1 and 2 tie at t = 2: the lower primitive";
    }
    {
        // An earlier leaf hit primitive 20 at t = 2: 17 wins the tie; had it hit 10, 10 stays.
        for (const auto& [earlier, expected] : {std::pair<uint32_t, uint32_t>{20, 17}, {10, 10}}) {
            Hit hit;
            hit.t = 2.0f, hit.primitive = earlier;
            TriangleBlockLeaf<NoTraversalCount> leaf{&block, ray, hit, {}, false};
            leaf.hitHere = true;
            float tMax = 2.0f;
            leaf(0, 4, tMax);
            EXPECT_EQ(tMax, 2.0f);
            EXPECT_EQ(hit.primitive, expected);
        }
    }
    {
        // Any hit stops at the first lane it accepts (lane 0, at t = 3), and counts every
        // triangle of the leaf.
        Hit hit;
        TraversalStats stats;
        TriangleBlockLeaf<TraversalCounter> leaf{&block, ray, hit, TraversalCounter{&stats}, true};
        float tMax = kInf;
        EXPECT_TRUE(leaf(0, 3, tMax));
        EXPECT_EQ(stats.primitivesTested, 3u);
        EXPECT_EQ(hit.primitive, 40u) << "the first lane that hits, not the closest";
        EXPECT_EQ(tMax, 3.0f);
    }
}

}  // namespace
}  // namespace pt
