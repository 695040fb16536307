// The AVX2 leaf functor (avx2::TriangleBlockLeaf: render/bvh/triangle_lanes.inl through
// wide_walk_avx2.h), which tests two blocks of a leaf in one pass, against SSE2's, which tests
// them one after another: the same closest hit (t, u and v bit for bit, the primitive, tMax),
// the same work counted, and the same any-hit answer, on leaves of 1 to 12 triangles (a third
// block is tested with itself), with ties at one t within and across the two blocks of a pass,
// and ties with a hit an earlier leaf found.
#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <vector>

#include "render/bvh/bvh_test_util.h"
#include "render/bvh/triangle_block_intersect.h"
#include "render/bvh/wide_walk.h"
#include "render/bvh/wide_walk_simd.h"

namespace pt {
namespace {

// One leaf query's answer and what it counted.
struct LeafAnswer {
    bool found = false;
    Hit hit;
    float tMax = kInf;
    TraversalStats stats;
};

// The query both functors answer: leaf (0, count) of `blocks`, after an earlier leaf's hit
// `prior` where `afterHit`.
struct LeafQuery {
    const TriangleBlock* blocks;
    uint32_t count;
    TraversalRay ray;
    bool anyHit;
    bool afterHit = false;
    Hit prior{};
};

template <class Leaf>
LeafAnswer answer(const LeafQuery& q) {
    LeafAnswer a;
    a.hit = q.prior;
    a.tMax = q.afterHit ? q.prior.t : kInf;
    Leaf leaf{q.blocks, q.ray, a.hit, TraversalCounter{&a.stats}, q.anyHit};
    leaf.hitHere = q.afterHit;
    a.found = leaf(0, q.count, a.tMax);
    return a;
}

LeafAnswer sse2Answer(const LeafQuery& q) { return answer<TriangleBlockLeaf<TraversalCounter>>(q); }

}  // namespace
}  // namespace pt

// clang-format off
#include "render/bvh/avx2_target_begin.h"
#include "render/bvh/wide_walk_avx2.h"
// clang-format on
namespace pt {
namespace {
// Compiled for AVX2, and called only where the processor runs it.
LeafAnswer avx2Answer(const LeafQuery& q) { return answer<avx2::TriangleBlockLeaf<TraversalCounter>>(q); }
}  // namespace
}  // namespace pt
#include "render/bvh/avx2_target_end.h"

namespace pt {
namespace {

using test::Rng;

uint32_t bits(float f) {
    uint32_t b;
    std::memcpy(&b, &f, sizeof b);
    return b;
}

// Lane `lane` of `block`: a triangle across the z axis at depth z, turned by `angle` in its
// plane and shifted by `shift` (a large shift puts it beside the ray).
void setLane(TriangleBlock& block, uint32_t lane, float z, float angle, Vec3 shift, uint32_t primitive) {
    for (int c = 0; c < 3; ++c) {
        const float a = angle + float(c) * 2.0943951f;
        const Vec3 p = Vec3(2.0f * std::cos(a), 2.0f * std::sin(a), z) + shift;
        for (int axis = 0; axis < 3; ++axis) block.corner[c][axis][lane] = p[axis];
    }
    block.primitive[lane] = primitive;
}

// A leaf of `count` triangles at a few shared depths (so that ties happen), lanes past the
// count repeating the last block's first triangle, as the compiler lays leaves out.
std::vector<TriangleBlock> randomLeaf(Rng& rng, uint32_t count) {
    std::vector<TriangleBlock> blocks((count + TriangleBlock::kWidth - 1) / TriangleBlock::kWidth);
    for (uint32_t i = 0; i < count; ++i) {
        const float z = 2.0f + 0.5f * float(rng.index(3));
        const Vec3 shift = rng.uniform() < 0.25f ? Vec3(5.0f, 0.0f, 0.0f) : Vec3(0.0f);
        setLane(blocks[i / TriangleBlock::kWidth], i % TriangleBlock::kWidth, z,
                rng.uniform(0.0f, 6.2831853f), shift, rng.index(1000));
    }
    TriangleBlock& last = blocks.back();
    for (uint32_t lane = count - (blocks.size() - 1) * TriangleBlock::kWidth; lane < TriangleBlock::kWidth;
         ++lane) {
        for (int c = 0; c < 3; ++c) {
            for (int axis = 0; axis < 3; ++axis) last.corner[c][axis][lane] = last.corner[c][axis][0];
        }
        last.primitive[lane] = last.primitive[0];
    }
    return blocks;
}

TEST(TriangleLanesAvx2, ALeafTestedTwoBlocksAPassFindsTheHitsOfOneBlockAtATime) {
    if (supportedSimdLevel() != SimdLevel::Avx2) GTEST_SKIP() << "this processor runs no AVX2";
    Rng rng(43);
    uint32_t found = 0, ties = 0, closest = 0;
    for (int trial = 0; trial < 30000; ++trial) {
        const uint32_t count = 1 + uint32_t(trial) % 12;
        const std::vector<TriangleBlock> blocks = randomLeaf(rng, count);
        const Vec3 origin = rng.inBox(Vec3(-0.3f, -0.3f, -1.0f), Vec3(0.3f, 0.3f, 0.0f));
        const Vec3 direction = Vec3(rng.uniform(-0.1f, 0.1f), rng.uniform(-0.1f, 0.1f), 1.0f);
        LeafQuery q{blocks.data(), count, makeTraversalRay(origin, direction), trial % 3 == 0};
        if (trial % 4 == 1) {
            // An earlier leaf's hit at one of the shared depths' distances: ties with it.
            const LeafAnswer first = sse2Answer(q);
            if (first.found) {
                q.afterHit = true;
                q.prior = first.hit;
                q.prior.primitive = rng.index(1000);
                ++ties;
            }
        }
        const LeafAnswer sse2 = sse2Answer(q), avx2 = avx2Answer(q);
        ASSERT_EQ(sse2.found, avx2.found) << "trial " << trial << ", " << count << " triangles";
        if (q.anyHit) continue;  // the first hit a test accepts: a pass of two blocks may accept another
        ++closest;
        found += sse2.found;
        EXPECT_EQ(bits(sse2.tMax), bits(avx2.tMax)) << "trial " << trial;
        EXPECT_EQ(bits(sse2.hit.t), bits(avx2.hit.t)) << "trial " << trial;
        EXPECT_EQ(bits(sse2.hit.u), bits(avx2.hit.u)) << "trial " << trial;
        EXPECT_EQ(bits(sse2.hit.v), bits(avx2.hit.v)) << "trial " << trial;
        EXPECT_EQ(sse2.hit.primitive, avx2.hit.primitive)
            << "trial " << trial << ", " << count << " triangles";
        EXPECT_EQ(sse2.stats.primitivesTested, avx2.stats.primitivesTested) << "trial " << trial;
        if (HasFailure()) return;
    }
    EXPECT_GT(found, closest / 2) << "most rays should hit the leaf";
    EXPECT_GT(ties, 1000u) << "earlier hits to tie with";
}

}  // namespace
}  // namespace pt
