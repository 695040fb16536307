// The SAH-optimal wide collapse (render/bvh/sah_collapse.h): on small trees its cost is the
// optimum that trying every way of filling the wide nodes finds (leaves tested one primitive a
// pass, and four); on large ones it is never above the greedy collapse's; the tree it
// describes (childrenOf, isLeaf) costs what it says; its leaves keep to their limit and to one
// range of entries; empty and one-leaf trees.
#include "render/bvh/sah_collapse.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "render/bvh/binned_sah_builder.h"
#include "render/bvh/bvh_test_util.h"

namespace pt {
namespace {

using test::Rng;

// The GPU's costs, and blocks of four tested at a time (as the CPU's leaves are).
constexpr WideCollapseCosts kCosts{1.0f, 0.3f, 1, 4};
constexpr WideCollapseCosts kBlockCosts{1.0f, 0.5f, 4, 8};

Bvh soupBvh(test::SoupKind kind, uint32_t triangles, uint32_t maxLeafSize, Rng& rng) {
    const Mesh mesh = test::makeSoup(kind, triangles, rng);
    const std::vector<Aabb> boxes = test::triangleBounds(mesh);
    BvhBuildOptions options;
    options.maxLeafSize = maxLeafSize;
    return buildBinnedSahBvh(boxes.data(), uint32_t(boxes.size()), options);
}

float boxArea(const BvhNode& n) { return Aabb{n.lo, n.hi}.surfaceArea(); }

uint32_t primitivesUnder(const Bvh& bvh, uint32_t n) {
    const BvhNode& node = bvh.nodes[n];
    return node.isLeaf()
               ? node.count
               : primitivesUnder(bvh, node.leftOrFirst) + primitivesUnder(bvh, node.leftOrFirst + 1);
}

double leafCost(const Bvh& bvh, uint32_t n, uint32_t primitives, const WideCollapseCosts& costs = kCosts) {
    return double(boxArea(bvh.nodes[n])) * costs.leafPass *
           double((primitives + costs.passWidth - 1) / costs.passWidth);
}

// Every way to cover binary subtree `n` with at most eight slots (a set of its nodes that
// every leaf lies under exactly once), by brute force; and the cheapest way for a node to fill
// one slot, trying each of them.
class Exhaustive {
public:
    Exhaustive(const Bvh& bvh, const WideCollapseCosts& costs) : bvh_(bvh), costs_(costs) {}

    double bestSlot(uint32_t n) {
        if (const auto it = best_.find(n); it != best_.end()) return it->second;
        const BvhNode& node = bvh_.nodes[n];
        const uint32_t primitives = primitivesUnder(bvh_, n);
        double best = node.isLeaf() || primitives <= costs_.maxLeaf ? leafCost(bvh_, n, primitives, costs_)
                                                                    : std::numeric_limits<double>::infinity();
        if (!node.isLeaf()) {
            for (const std::vector<uint32_t>& left : covers(node.leftOrFirst)) {
                for (const std::vector<uint32_t>& right : covers(node.leftOrFirst + 1)) {
                    if (left.size() + right.size() > 8) continue;
                    double sum = double(boxArea(node)) * costs_.node;
                    for (const uint32_t s : left) sum += bestSlot(s);
                    for (const uint32_t s : right) sum += bestSlot(s);
                    best = std::min(best, sum);
                }
            }
        }
        return best_[n] = best;
    }

private:
    const std::vector<std::vector<uint32_t>>& covers(uint32_t n) {
        if (const auto it = covers_.find(n); it != covers_.end()) return it->second;
        std::vector<std::vector<uint32_t>> all{{n}};
        const BvhNode& node = bvh_.nodes[n];
        if (!node.isLeaf()) {
            const std::vector<std::vector<uint32_t>> left = covers(node.leftOrFirst),
                                                     right = covers(node.leftOrFirst + 1);
            for (const std::vector<uint32_t>& l : left) {
                for (const std::vector<uint32_t>& r : right) {
                    if (l.size() + r.size() > 8) continue;
                    std::vector<uint32_t> both = l;
                    both.insert(both.end(), r.begin(), r.end());
                    all.push_back(both);
                }
            }
        }
        return covers_[n] = all;
    }

    const Bvh& bvh_;
    WideCollapseCosts costs_;
    std::map<uint32_t, double> best_;
    std::map<uint32_t, std::vector<std::vector<uint32_t>>> covers_;
};

// The cost of the wide tree the collapse describes, node `n` filling one slot, walked through
// its own answers.
double describedCost(const Bvh& bvh, const SahCollapse& collapse, uint32_t n,
                     const WideCollapseCosts& costs = kCosts) {
    if (collapse.isLeaf(n)) {
        EXPECT_TRUE(bvh.nodes[n].isLeaf() || collapse.leafCount(n) <= costs.maxLeaf);
        EXPECT_EQ(collapse.leafCount(n), primitivesUnder(bvh, n));
        return leafCost(bvh, n, collapse.leafCount(n), costs);
    }
    const WideChildren kids = collapse.childrenOf(n);
    EXPECT_GE(kids.size(), 2u);
    EXPECT_LE(kids.size(), 8u);
    double sum = double(boxArea(bvh.nodes[n])) * costs.node;
    uint32_t primitives = 0;
    for (uint32_t s = 0; s < kids.size(); ++s) {
        sum += describedCost(bvh, collapse, kids[s], costs);
        primitives += primitivesUnder(bvh, kids[s]);
    }
    EXPECT_EQ(primitives, primitivesUnder(bvh, n)) << "the slots cover the subtree once";
    return sum;
}

// The greedy collapse's cost (openLargestChildren, the binary leaves as leaves).
double greedyCost(const Bvh& bvh, uint32_t n) {
    const BvhNode& node = bvh.nodes[n];
    if (node.isLeaf()) return leafCost(bvh, n, node.count);
    const WideChildren kids = openLargestChildren(bvh.nodes.data(), n, 8);
    double sum = double(boxArea(node)) * kCosts.node;
    for (uint32_t s = 0; s < kids.size(); ++s) sum += greedyCost(bvh, kids[s]);
    return sum;
}

TEST(SahCollapse, SmallTreesGetTheOptimumThatTryingEveryCollapseFinds) {
    Rng rng(17);
    for (const test::SoupKind kind :
         {test::SoupKind::Uniform, test::SoupKind::Clustered, test::SoupKind::Needles}) {
        for (uint32_t triangles = 2; triangles <= 14; triangles += 3) {
            SCOPED_TRACE(std::to_string(triangles) + " triangles, " + test::soupName(kind));
            const Bvh bvh = soupBvh(kind, triangles, 1, rng);  // leaves of one: the collapse makes the leaves
            const double area = boxArea(bvh.nodes[0]);
            for (const WideCollapseCosts& costs : {kCosts, kBlockCosts}) {
                const SahCollapse collapse(bvh.nodes.data(), uint32_t(bvh.nodes.size()), costs);
                const double optimum = Exhaustive(bvh, costs).bestSlot(0) / area;
                EXPECT_NEAR(collapse.rootCost(), optimum, 1e-5 * optimum) << "pass width " << costs.passWidth;
                EXPECT_NEAR(describedCost(bvh, collapse, 0, costs) / area, optimum, 1e-5 * optimum);
            }
        }
    }
}

TEST(SahCollapse, LargeTreesCostNoMoreThanTheGreedyCollapse) {
    Rng rng(23);
    for (const test::SoupKind kind : {test::SoupKind::Uniform, test::SoupKind::Clustered,
                                      test::SoupKind::Needles, test::SoupKind::CoincidentCentroids}) {
        const Bvh bvh = soupBvh(kind, 20000, 4, rng);
        const SahCollapse collapse(bvh.nodes.data(), uint32_t(bvh.nodes.size()), kCosts);
        const double area = boxArea(bvh.nodes[0]);
        const double greedy = greedyCost(bvh, 0) / area, optimal = collapse.rootCost();
        std::cout << "[ figures  ] " << test::soupName(kind) << ", 20000 triangles: SAH cost greedy "
                  << greedy << ", optimal " << optimal << " (" << optimal / greedy << "x)\n";
        EXPECT_LE(optimal, greedy * (1.0 + 1e-5)) << test::soupName(kind);
        EXPECT_NEAR(describedCost(bvh, collapse, 0) / area, optimal, 1e-4 * optimal) << test::soupName(kind);
    }
}

// No tree, a lone leaf, and an empty root cost nothing to describe and are read in bounds.
TEST(SahCollapse, EmptyAndSingleLeafTreesAreLeaves) {
    Rng rng(3);
    for (const uint32_t triangles : {0u, 1u}) {
        const Bvh bvh = soupBvh(test::SoupKind::Uniform, triangles, 4, rng);
        const SahCollapse collapse(bvh.nodes.data(), uint32_t(bvh.nodes.size()), kCosts);
        EXPECT_EQ(collapse.leafCount(0), triangles);
        EXPECT_EQ(collapse.isLeaf(0), triangles == 1);
        // One triangle: one test under the root box; none: nothing.
        EXPECT_NEAR(collapse.rootCost(), triangles == 1 ? kCosts.leafPass : 0.0f, 1e-6f);
    }
    const SahCollapse none(nullptr, 0, kCosts);
    EXPECT_EQ(none.rootCost(), 0.0f);
}

// Hand-made trees: a binary leaf larger than the limit stays one leaf, and two leaves whose
// entries are not one range are never gathered into one, however cheap that would be.
TEST(SahCollapse, LeavesKeepToTheirLimitAndToOneRange) {
    const auto box = [](float lo, float hi) { return BvhNode{{lo, 0, 0}, 0, {hi, 1, 1}, 0}; };
    std::vector<BvhNode> nodes = {box(0, 2), box(0, 1), box(1, 2)};
    nodes[0].leftOrFirst = 1;
    nodes[1].leftOrFirst = 0, nodes[1].count = 6;  // past kCosts.maxLeaf
    nodes[2].leftOrFirst = 6, nodes[2].count = 1;
    const SahCollapse big(nodes.data(), 3, kCosts);
    EXPECT_TRUE(big.isLeaf(1));
    EXPECT_EQ(big.leafCount(1), 6u);
    EXPECT_FALSE(big.isLeaf(0)) << "7 primitives, past the limit";
    EXPECT_EQ(big.leafCount(0), 0u);

    nodes[1].count = 1, nodes[1].leftOrFirst = 5;  // entries 5 and 6: one range
    const SahCollapse joined(nodes.data(), 3, kCosts);
    EXPECT_EQ(joined.leafCount(0), 2u);
    EXPECT_EQ(joined.leafFirst(0), 5u);
    EXPECT_TRUE(joined.isLeaf(0)) << "two primitives under one box cost less than a wide node";
    nodes[1].leftOrFirst = 3;  // entries 3 and 6: not
    const SahCollapse apart(nodes.data(), 3, kCosts);
    EXPECT_EQ(apart.leafCount(0), 0u);
    EXPECT_FALSE(apart.isLeaf(0));
    const WideChildren kids = apart.childrenOf(0);
    ASSERT_EQ(kids.size(), 2u);
    EXPECT_TRUE(apart.isLeaf(kids[0]) && apart.isLeaf(kids[1]));
}

}  // namespace
}  // namespace pt
