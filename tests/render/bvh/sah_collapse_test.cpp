// The SAH-optimal wide collapse (render/bvh/sah_collapse.h): on small trees its cost is the
// optimum that trying every way of filling the wide nodes finds; on large ones it is never
// above the greedy collapse's; the tree it describes (childrenOf, isLeaf) costs what it says;
// its leaves keep to their limit.
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

constexpr WideCollapseCosts kCosts{1.0f, 0.3f, 1, 4};

Bvh soupBvh(test::SoupKind kind, uint32_t triangles, uint32_t maxLeafSize, Rng& rng) {
    const Mesh mesh = test::makeSoup(kind, triangles, rng);
    const std::vector<Aabb> boxes = test::triangleBounds(mesh);
    BvhBuildOptions options;
    options.maxLeafSize = maxLeafSize;
    return buildBinnedSahBvh(boxes.data(), uint32_t(boxes.size()), options);
}

float halfArea(const BvhNode& n) {
    const Vec3 d = n.hi - n.lo;
    return std::max(d.x * d.y + d.y * d.z + d.z * d.x, 0.0f);
}

uint32_t primitivesUnder(const Bvh& bvh, uint32_t n) {
    const BvhNode& node = bvh.nodes[n];
    return node.isLeaf()
               ? node.count
               : primitivesUnder(bvh, node.leftOrFirst) + primitivesUnder(bvh, node.leftOrFirst + 1);
}

double leafCost(const Bvh& bvh, uint32_t n, uint32_t primitives) {
    return double(halfArea(bvh.nodes[n])) * kCosts.leafPass *
           double((primitives + kCosts.passWidth - 1) / kCosts.passWidth);
}

// Every way to cover binary subtree `n` with at most eight slots (a set of its nodes that
// every leaf lies under exactly once), by brute force; and the cheapest way for a node to fill
// one slot, trying each of them.
class Exhaustive {
public:
    explicit Exhaustive(const Bvh& bvh) : bvh_(bvh) {}

    double bestSlot(uint32_t n) {
        if (const auto it = best_.find(n); it != best_.end()) return it->second;
        const BvhNode& node = bvh_.nodes[n];
        const uint32_t primitives = primitivesUnder(bvh_, n);
        double best = node.isLeaf() || primitives <= kCosts.maxLeaf ? leafCost(bvh_, n, primitives)
                                                                    : std::numeric_limits<double>::infinity();
        if (!node.isLeaf()) {
            for (const std::vector<uint32_t>& left : covers(node.leftOrFirst)) {
                for (const std::vector<uint32_t>& right : covers(node.leftOrFirst + 1)) {
                    if (left.size() + right.size() > 8) continue;
                    double sum = double(halfArea(node)) * kCosts.node;
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
    std::map<uint32_t, double> best_;
    std::map<uint32_t, std::vector<std::vector<uint32_t>>> covers_;
};

// The cost of the wide tree the collapse describes, node `n` filling one slot, walked through
// its own answers.
double describedCost(const Bvh& bvh, const SahCollapse& collapse, uint32_t n) {
    if (collapse.isLeaf(n)) {
        EXPECT_TRUE(bvh.nodes[n].isLeaf() || collapse.leafCount(n) <= kCosts.maxLeaf);
        EXPECT_EQ(collapse.leafCount(n), primitivesUnder(bvh, n));
        return leafCost(bvh, n, collapse.leafCount(n));
    }
    const WideChildren kids = collapse.childrenOf(n);
    EXPECT_GE(kids.size(), 2u);
    EXPECT_LE(kids.size(), 8u);
    double sum = double(halfArea(bvh.nodes[n])) * kCosts.node;
    uint32_t primitives = 0;
    for (uint32_t s = 0; s < kids.size(); ++s) {
        sum += describedCost(bvh, collapse, kids[s]);
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
    double sum = double(halfArea(node)) * kCosts.node;
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
            const SahCollapse collapse(bvh.nodes.data(), uint32_t(bvh.nodes.size()), kCosts);
            const double area = halfArea(bvh.nodes[0]);
            const double optimum = Exhaustive(bvh).bestSlot(0) / area;
            EXPECT_NEAR(collapse.rootCost(), optimum, 1e-5 * optimum);
            EXPECT_NEAR(describedCost(bvh, collapse, 0) / area, optimum, 1e-5 * optimum);
        }
    }
}

TEST(SahCollapse, LargeTreesCostNoMoreThanTheGreedyCollapse) {
    Rng rng(23);
    for (const test::SoupKind kind : {test::SoupKind::Uniform, test::SoupKind::Clustered,
                                      test::SoupKind::Needles, test::SoupKind::CoincidentCentroids}) {
        const Bvh bvh = soupBvh(kind, 20000, 4, rng);
        const SahCollapse collapse(bvh.nodes.data(), uint32_t(bvh.nodes.size()), kCosts);
        const double area = halfArea(bvh.nodes[0]);
        const double greedy = greedyCost(bvh, 0) / area, optimal = collapse.rootCost();
        std::cout << "[ figures  ] " << test::soupName(kind) << ", 20000 triangles: SAH cost greedy "
                  << greedy << ", optimal " << optimal << " (" << optimal / greedy << "x)\n";
        EXPECT_LE(optimal, greedy * (1.0 + 1e-5)) << test::soupName(kind);
        EXPECT_NEAR(describedCost(bvh, collapse, 0) / area, optimal, 1e-4 * optimal) << test::soupName(kind);
    }
}

}  // namespace
}  // namespace pt
