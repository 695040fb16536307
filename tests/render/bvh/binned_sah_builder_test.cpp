// Binned SAH builder (render/bvh/binned_sah_builder.h): the invariants the header promises,
// on soups, degenerate input and input built to defeat the depth bound; and its speed.
#include "render/bvh/binned_sah_builder.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <cstdio>
#include <cstring>

#include "render/bvh/bvh_test_util.h"
#include "render/bvh/bvh_walk.h"

namespace pt {
namespace {

using test::Rng;
using test::SoupKind;

bool contains(const BvhNode& outer, Vec3 lo, Vec3 hi) {
    return outer.lo.x <= lo.x && outer.lo.y <= lo.y && outer.lo.z <= lo.z && outer.hi.x >= hi.x &&
           outer.hi.y >= hi.y && outer.hi.z >= hi.z;
}

struct TreeShape {
    uint32_t maxDepth = 0, leaves = 0, largestLeaf = 0;
};

// Walks the whole tree and checks every promise of binned_sah_builder.h.
TreeShape checkInvariants(const Bvh& bvh, const std::vector<Aabb>& bounds, const BvhBuildOptions& options) {
    TreeShape shape;
    const uint32_t n = uint32_t(bounds.size());
    EXPECT_EQ(bvh.primIndices.size(), n);
    std::vector<uint32_t> seenPrim(n, 0), seenNode(bvh.nodes.size(), 0);
    struct Item {
        uint32_t node, depth;
    };
    std::vector<Item> stack{{0, 0}};
    while (!stack.empty()) {
        const Item item = stack.back();
        stack.pop_back();
        EXPECT_LT(item.node, bvh.nodes.size());
        if (item.node >= bvh.nodes.size() || seenNode[item.node]++) {
            ADD_FAILURE() << "node " << item.node << " out of range or reached twice";
            return shape;
        }
        const BvhNode& node = bvh.nodes[item.node];
        shape.maxDepth = std::max(shape.maxDepth, item.depth);
        Aabb exact;
        if (node.isLeaf()) {
            ++shape.leaves;
            shape.largestLeaf = std::max(shape.largestLeaf, node.count);
            EXPECT_LE(node.count, options.maxLeafSize);
            EXPECT_LE(size_t(node.leftOrFirst) + node.count, bvh.primIndices.size());
            for (uint32_t i = node.leftOrFirst; i < node.leftOrFirst + node.count && i < n; ++i) {
                const uint32_t prim = bvh.primIndices[i];
                EXPECT_LT(prim, n);
                if (prim < n) {
                    ++seenPrim[prim];
                    exact.grow(bounds[prim]);
                }
            }
        } else {
            EXPECT_LT(node.leftOrFirst + 1, bvh.nodes.size());
            for (uint32_t c = 0; c < 2 && node.leftOrFirst + c < bvh.nodes.size(); ++c) {
                const BvhNode& child = bvh.nodes[node.leftOrFirst + c];
                EXPECT_TRUE(contains(node, child.lo, child.hi)) << "child outside its parent";
                exact.grow(Aabb{child.lo, child.hi});
                stack.push_back({node.leftOrFirst + c, item.depth + 1});
            }
        }
        EXPECT_TRUE(exact.lo == node.lo && exact.hi == node.hi) << "node box is not the exact union";
    }
    for (uint32_t p = 0; p < n; ++p) EXPECT_EQ(seenPrim[p], 1u) << "primitive " << p;
    for (size_t i = 0; i < seenNode.size(); ++i) EXPECT_EQ(seenNode[i], 1u) << "unreachable node " << i;
    EXPECT_LE(shape.maxDepth, kBvhStackSize);
    return shape;
}

TEST(BinnedSahBuilder, EmptyInputGivesOneEmptyRoot) {
    const Bvh bvh = buildBinnedSahBvh(nullptr, 0);
    ASSERT_EQ(bvh.nodes.size(), 1u);
    EXPECT_TRUE(bvh.primIndices.empty());
    EXPECT_EQ(bvh.nodes[0].count, 0u);
    EXPECT_GT(bvh.nodes[0].lo.x, bvh.nodes[0].hi.x) << "empty box, so no ray enters it";
}

TEST(BinnedSahBuilder, OneAndTwoPrimitives) {
    const std::vector<Aabb> one{Aabb{{0, 0, 0}, {1, 1, 1}}};
    const Bvh a = buildBinnedSahBvh(one.data(), 1);
    ASSERT_EQ(a.nodes.size(), 1u);
    EXPECT_EQ(a.nodes[0].count, 1u);
    checkInvariants(a, one, {});
    const std::vector<Aabb> two{Aabb{{0, 0, 0}, {1, 1, 1}}, Aabb{{5, 0, 0}, {6, 1, 1}}};
    checkInvariants(buildBinnedSahBvh(two.data(), 2), two, {});
    BvhBuildOptions single;
    single.maxLeafSize = 1;
    EXPECT_EQ(checkInvariants(buildBinnedSahBvh(two.data(), 2, single), two, single).leaves, 2u);
}

TEST(BinnedSahBuilder, IdenticalBoxesTerminateWithSmallLeaves) {
    for (uint32_t n : {2u, 5u, 1000u, 100000u}) {
        const std::vector<Aabb> boxes(n, Aabb{{1, 2, 3}, {4, 5, 6}});
        const TreeShape shape = checkInvariants(buildBinnedSahBvh(boxes.data(), n), boxes, {});
        EXPECT_LE(shape.maxDepth, 32u) << "coincident centroids split by count, not one at a time";
    }
}

TEST(BinnedSahBuilder, PointBoxesTerminate) {
    Rng rng(3);
    std::vector<Aabb> points(5000);
    for (size_t i = 0; i < points.size(); ++i) {
        const Vec3 p = i % 2 ? Vec3(0.5f) : rng.inBox(Vec3(-1.0f), Vec3(1.0f));  // half coincide
        points[i] = Aabb{p, p};
    }
    checkInvariants(buildBinnedSahBvh(points.data(), uint32_t(points.size())), points, {});
    std::vector<Aabb> line(3000);  // zero-area root: all on one axis
    for (size_t i = 0; i < line.size(); ++i) line[i] = Aabb{{float(i), 0, 0}, {float(i), 0, 0}};
    checkInvariants(buildBinnedSahBvh(line.data(), uint32_t(line.size())), line, {});
}

// A node small enough for the sweep whose primitives are two clusters of coincident points: the
// sweep separates the clusters, and each cluster (no area, more than a leaf holds) is split by
// count around the centroid bounds it works out itself (the sweep's children do not carry them).
TEST(BinnedSahBuilder, CoincidentPointsBelowASweepSplitSplitByCount) {
    for (const uint32_t first : {5u, 10u, 13u}) {
        std::vector<Aabb> points(16, Aabb{{0.25f, 0.5f, 0.75f}, {0.25f, 0.5f, 0.75f}});
        for (uint32_t i = first; i < 16; ++i) points[i] = Aabb{{2, 1, 3}, {2, 1, 3}};
        const TreeShape shape =
            checkInvariants(buildBinnedSahBvh(points.data(), uint32_t(points.size())), points, {});
        EXPECT_LE(shape.largestLeaf, 4u);
        EXPECT_GE(shape.leaves, 4u) << first << " and " << 16 - first << " points need leaves of at most 4";
    }
}

TEST(BinnedSahBuilder, SoupsKeepInvariantsForSeveralOptions) {
    Rng rng(11);
    for (SoupKind kind :
         {SoupKind::Uniform, SoupKind::Clustered, SoupKind::Needles, SoupKind::CoincidentCentroids}) {
        const std::vector<Aabb> bounds = test::triangleBounds(test::makeSoup(kind, 30000, rng));
        for (uint32_t bins : {2u, 8u, 16u, 64u, 1000u}) {
            for (uint32_t leaf : {1u, 4u, 16u}) {
                BvhBuildOptions options;
                options.binCount = bins;
                options.maxLeafSize = leaf;
                SCOPED_TRACE(std::string(test::soupName(kind)) + " bins " + std::to_string(bins) + " leaf " +
                             std::to_string(leaf));
                checkInvariants(buildBinnedSahBvh(bounds.data(), uint32_t(bounds.size()), options), bounds,
                                options);
            }
        }
    }
}

// Boxes at x = 2^i: the SAH's best split peels off the farthest box each time, a chain 120
// deep; the builder must fall back to halving to stay within the traversal stack.
TEST(BinnedSahBuilder, ChainInputStaysWithinTheStackDepth) {
    std::vector<Aabb> boxes;
    for (int i = 0; i < 120; ++i) {
        const float x = std::ldexp(1.0f, i);
        for (int k = 0; k < 3; ++k) boxes.push_back(Aabb{{x, float(k), 0}, {x * 1.5f, float(k) + 1, 1}});
    }
    BvhBuildOptions options;
    options.maxLeafSize = 1;
    const TreeShape shape =
        checkInvariants(buildBinnedSahBvh(boxes.data(), uint32_t(boxes.size()), options), boxes, options);
    EXPECT_GT(shape.maxDepth, 20u) << "the input should have produced a deep, SAH-driven tree";
    EXPECT_LE(shape.maxDepth, kBvhStackSize);
}

// The same tree from run to run and with one thread or all: the subtrees are built and
// compacted as parallel tasks, each into places fixed before it starts.
TEST(BinnedSahBuilder, DeterministicAcrossRunsAndThreadCounts) {
    Rng rng(5);
    const std::vector<Aabb> bounds = test::triangleBounds(test::makeSoup(SoupKind::Clustered, 200000, rng));
    const Bvh a = buildBinnedSahBvh(bounds.data(), uint32_t(bounds.size()));
    const Bvh b = buildBinnedSahBvh(bounds.data(), uint32_t(bounds.size()));
    Bvh serial;
    tbb::task_arena(1).execute([&] { serial = buildBinnedSahBvh(bounds.data(), uint32_t(bounds.size())); });
    for (const Bvh* other : {&b, static_cast<const Bvh*>(&serial)}) {
        ASSERT_EQ(a.nodes.size(), other->nodes.size());
        EXPECT_EQ(0, std::memcmp(a.nodes.data(), other->nodes.data(), a.nodes.size() * sizeof(BvhNode)));
        EXPECT_EQ(a.primIndices, other->primIndices);
    }
}

// Nodes of 2^17 primitives or more are partitioned in parallel chunks, whose stray primitives
// are then swapped across the split: every kind of soup keeps the tree's invariants through it,
// among them splits that leave few primitives on one side (needles, coincident centroids).
TEST(BinnedSahBuilder, LargeNodesPartitionedInParallelKeepTheInvariants) {
    Rng rng(17);
    for (SoupKind kind : {SoupKind::Clustered, SoupKind::Needles, SoupKind::CoincidentCentroids}) {
        SCOPED_TRACE(test::soupName(kind));
        const std::vector<Aabb> bounds = test::triangleBounds(test::makeSoup(kind, 300000, rng));
        checkInvariants(buildBinnedSahBvh(bounds.data(), uint32_t(bounds.size())), bounds, {});
    }
}

// Prints the build rate the DESIGN asks for (Mtris/s) on a 1M-triangle random soup.
TEST(BinnedSahBuilder, MillionTriangleSoupBuildRate) {
    Rng rng(1);
    const std::vector<Aabb> bounds = test::triangleBounds(test::makeSoup(SoupKind::Uniform, 1000000, rng));
    double best = 1e30;
    Bvh bvh;
    for (int run = 0; run < 3; ++run) {
        const auto start = std::chrono::steady_clock::now();
        bvh = buildBinnedSahBvh(bounds.data(), uint32_t(bounds.size()));
        best =
            std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    std::printf("[ BVH      ] binned SAH, 1M-triangle uniform soup: %.1f ms, %.2f Mtris/s, %zu nodes\n",
                best * 1e3, 1.0 / best, bvh.nodes.size());
    checkInvariants(bvh, bounds, {});
}

}  // namespace
}  // namespace pt
