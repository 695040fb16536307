// The SAH leaf rule over a built tree (render/bvh/subtree_collapse.h): each node's choice
// against a plain recursive dynamic programme written here, on hand-made trees and on the
// binned builder's trees of one-primitive leaves; the leaves of a small subtree in order; and the
// rule's total on those trees against the binned builder's own leaves of up to four.
#include "render/bvh/subtree_collapse.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <tuple>

#include "render/bvh/bvh_test_util.h"
#include "render/bvh/sah_cost.h"

namespace pt {
namespace {

using test::Rng;
using test::SoupKind;

// The optimum by recursion over the whole subtree: primitives, cost in units of area, leaf.
struct Optimum {
    uint32_t primitives = 0;
    float cost = 0.0f;
    bool asLeaf = false;
};

Optimum optimum(const std::vector<BvhNode>& nodes, uint32_t index) {
    const BvhNode& node = nodes[index];
    const float area = nodeSurfaceArea(node);
    if (node.isLeaf()) return {node.count, area * float(node.count), true};
    const Optimum left = optimum(nodes, node.leftOrFirst), right = optimum(nodes, node.leftOrFirst + 1);
    const uint32_t primitives = left.primitives + right.primitives;
    const float split = area + (left.cost + right.cost);
    const float leaf = area * float(primitives);
    const bool asLeaf = primitives <= kMaxCollapsedLeaf && leaf <= split;
    return {primitives, asLeaf ? leaf : split, asLeaf};
}

BvhNode interior(Vec3 lo, Vec3 hi, uint32_t left) { return {lo, left, hi, 0}; }
BvhNode leaf(Vec3 lo, Vec3 hi, uint32_t first, uint32_t count = 1) { return {lo, first, hi, count}; }

TEST(SubtreeCollapse, TwoTrianglesSharingTheirBoxBecomeOneLeaf) {
    // The two halves of a unit square: both boxes are the square's, so the split costs 3 areas
    // and the leaf 2.
    const std::vector<BvhNode> nodes{interior({0, 0, 0}, {1, 1, 0}, 1), leaf({0, 0, 0}, {1, 1, 0}, 0),
                                     leaf({0, 0, 0}, {1, 1, 0}, 1)};
    const SubtreeChoice choice = collapseChoice(nodes.data(), 0);
    EXPECT_EQ(choice.primitives, 2u);
    EXPECT_TRUE(choice.asLeaf);
    EXPECT_FLOAT_EQ(choice.cost, 2.0f * 2.0f);  // two tests of the square (area 2)
}

TEST(SubtreeCollapse, TwoSmallFarBoxesStaySplit) {
    // Unit cubes 10 apart: the parent's box (area 2 * (11 + 11 + 1) = 46) costs more as a leaf
    // of two (92) than as a split (46 + 6 + 6).
    const std::vector<BvhNode> nodes{interior({0, 0, 0}, {11, 1, 1}, 1), leaf({0, 0, 0}, {1, 1, 1}, 0),
                                     leaf({10, 0, 0}, {11, 1, 1}, 1)};
    const SubtreeChoice choice = collapseChoice(nodes.data(), 0);
    EXPECT_EQ(choice.primitives, 2u);
    EXPECT_FALSE(choice.asLeaf);
    EXPECT_FLOAT_EQ(choice.cost, 46.0f + 6.0f + 6.0f);
}

TEST(SubtreeCollapse, SubtreesOfMoreThanTheLimitReportNoChoice) {
    // A chain of five leaves: node 2k (k < 4) is interior, with a leaf at 2k + 1 and the rest of
    // the chain at 2k + 2; node 8 is the last leaf. And a leaf of five primitives.
    const Vec3 lo(0.0f), hi(1.0f);
    std::vector<BvhNode> chain;
    for (uint32_t k = 0; k < 4; ++k) {
        chain.push_back(interior(lo, hi, 2 * k + 1));
        chain.push_back(leaf(lo, hi, k));
    }
    chain.push_back(leaf(lo, hi, 4));
    ASSERT_EQ(chain.size(), 9u);
    EXPECT_EQ(collapseChoice(chain.data(), 0).primitives, 0u) << "five primitives";
    EXPECT_EQ(collapseChoice(chain.data(), 2).primitives, 4u);
    EXPECT_EQ(collapseChoice(chain.data(), 6).primitives, 2u);
    const std::vector<BvhNode> big{leaf(lo, hi, 0, 5)};
    EXPECT_EQ(collapseChoice(big.data(), 0).primitives, 0u);
    const std::vector<BvhNode> pairOfTwos{interior(lo, hi, 1), leaf(lo, hi, 0, 2), leaf(lo, hi, 2, 3)};
    EXPECT_EQ(collapseChoice(pairOfTwos.data(), 0).primitives, 0u) << "two leaves of five primitives in all";
}

// A leaf over the limit (a tree built elsewhere): it and every node above it report no choice,
// while a small subtree beside it still gets its own.
TEST(SubtreeCollapse, ALeafOverTheLimitLeavesItsSmallNeighboursTheirChoice) {
    const Vec3 lo(0.0f), hi(1.0f);
    // 0 -> (1, 2); 1: a leaf of five; 2 -> (3, 4), two leaves sharing one box.
    const std::vector<BvhNode> nodes{interior(lo, hi, 1), leaf(lo, hi, 0, 5), interior(lo, hi, 3),
                                     leaf(lo, hi, 5), leaf(lo, hi, 6)};
    EXPECT_EQ(collapseChoice(nodes.data(), 1).primitives, 0u);
    EXPECT_EQ(collapseChoice(nodes.data(), 0).primitives, 0u);
    const SubtreeChoice small = collapseChoice(nodes.data(), 2);
    EXPECT_EQ(small.primitives, 2u);
    EXPECT_TRUE(small.asLeaf);
    EXPECT_EQ(optimum(nodes, 2).cost, small.cost);
}

TEST(SubtreeCollapse, EveryNodeOfBuiltTreesMatchesTheRecursiveOptimum) {
    Rng rng(31);
    BvhBuildOptions oneALeaf;
    oneALeaf.maxLeafSize = 1;
    BvhBuildOptions twoALeaf;
    twoALeaf.maxLeafSize = 2;
    for (SoupKind kind :
         {SoupKind::Uniform, SoupKind::Clustered, SoupKind::Needles, SoupKind::CoincidentCentroids}) {
        for (const BvhBuildOptions& options : {oneALeaf, twoALeaf}) {
            SCOPED_TRACE(std::string(test::soupName(kind)) + " leaves of " +
                         std::to_string(options.maxLeafSize));
            const std::vector<Aabb> boxes = test::triangleBounds(test::makeSoup(kind, 3000, rng));
            const Bvh bvh = buildBinnedSahBvh(boxes.data(), uint32_t(boxes.size()), options);
            uint32_t small = 0, leaves = 0;
            for (uint32_t i = 0; i < bvh.nodes.size(); ++i) {
                const Optimum want = optimum(bvh.nodes, i);
                const SubtreeChoice got = collapseChoice(bvh.nodes.data(), i);
                if (want.primitives > kMaxCollapsedLeaf) {
                    ASSERT_EQ(got.primitives, 0u) << "node " << i;
                    continue;
                }
                ASSERT_EQ(got.primitives, want.primitives) << "node " << i;
                ASSERT_EQ(got.cost, want.cost) << "node " << i;  // the same float operations
                ASSERT_EQ(got.asLeaf, want.asLeaf) << "node " << i;
                ++small;
                leaves += !bvh.nodes[i].isLeaf() && got.asLeaf;
            }
            EXPECT_GT(small, bvh.nodes.size() / 4);
            EXPECT_GT(leaves, 0u) << "no subtree collapsed: the test would not see a wrong choice";
        }
    }
}

TEST(SubtreeCollapse, LeavesOfASmallSubtreeComeLeftToRight) {
    Rng rng(32);
    BvhBuildOptions oneALeaf;
    oneALeaf.maxLeafSize = 1;
    const std::vector<Aabb> boxes = test::triangleBounds(test::makeSoup(SoupKind::Clustered, 2000, rng));
    const Bvh bvh = buildBinnedSahBvh(boxes.data(), uint32_t(boxes.size()), oneALeaf);
    uint32_t checked = 0;
    for (uint32_t i = 0; i < bvh.nodes.size(); ++i) {
        if (collapseChoice(bvh.nodes.data(), i).primitives == 0) continue;
        // Depth first, left before right: the binned builder's leaves of a subtree are
        // consecutive entries of primIndices in that order.
        std::vector<uint32_t> firsts;
        forEachSmallSubtreeLeaf(bvh.nodes.data(), i,
                                [&](const BvhNode& l) { firsts.push_back(l.leftOrFirst); });
        ASSERT_FALSE(firsts.empty());
        for (size_t k = 1; k < firsts.size(); ++k) ASSERT_EQ(firsts[k], firsts[k - 1] + 1) << "node " << i;
        checked += firsts.size() > 1;
    }
    EXPECT_GT(checked, 100u);
}

// Applied to the binned builder's one-primitive leaves, the rule's optimum is what that builder
// reaches by itself with leaves of up to four: within 1% on a sphere and on soups.
TEST(SubtreeCollapse, OnOnePrimitiveLeavesItReachesTheBinnedBuildersLeafCost) {
    Rng rng(33);
    BvhBuildOptions oneALeaf;
    oneALeaf.maxLeafSize = 1;
    // The gain it must show: 2.1% on the icosphere's tessellation, where neighbouring triangles
    // share most of their boxes, 0.4% on a soup of random triangles, where few do.
    const std::tuple<const char*, Mesh, float> meshes[] = {
        {"icosphere", test::makeIcosphere(5), 0.985f},
        {"uniform", test::makeSoup(SoupKind::Uniform, 20000, rng), 0.999f}};
    for (const auto& [name, mesh, mostOfTheCost] : meshes) {
        SCOPED_TRACE(name);
        const std::vector<Aabb> boxes = test::triangleBounds(mesh);
        const uint32_t n = uint32_t(boxes.size());
        const Bvh ones = buildBinnedSahBvh(boxes.data(), n, oneALeaf);
        const Bvh fours = buildBinnedSahBvh(boxes.data(), n);
        const float rootArea = nodeSurfaceArea(ones.nodes[0]);
        const float collapsed = optimum(ones.nodes, 0).cost / rootArea;
        std::printf("[ sah      ] %s: one-primitive leaves %.4f, collapsed %.4f, binned leaves of 4 %.4f\n",
                    name, sahCost(ones), collapsed, sahCost(fours));
        EXPECT_LT(collapsed, mostOfTheCost * sahCost(ones))
            << "the rule should pay on a tree of single leaves";
        EXPECT_NEAR(collapsed / sahCost(fours), 1.0f, 0.01f);
    }
}

}  // namespace
}  // namespace pt
