// SAH cost (render/bvh/sah_cost.h) on hand-made trees, and the quality of the binned builder
// against two references written here: a full-sweep SAH builder (every centroid-sorted split
// on every axis; the quality bound binning approximates) and an object-median builder.
#include "render/bvh/sah_cost.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <numeric>

#include "render/bvh/bvh_test_util.h"

namespace pt {
namespace {

using test::Rng;
using test::SoupKind;

TEST(SahCost, SingleLeafCostsOneTestPerPrimitive) {
    const std::vector<Aabb> boxes{Aabb{{0, 0, 0}, {1, 1, 1}}, Aabb{{0.5f, 0, 0}, {2, 1, 1}}};
    BvhBuildOptions options;
    options.maxLeafSize = 4;
    options.traversalCost = 100.0f;  // splitting never pays
    const Bvh bvh = buildBinnedSahBvh(boxes.data(), 2, options);
    ASSERT_EQ(bvh.nodes.size(), 1u);
    EXPECT_FLOAT_EQ(sahCost(bvh, options), 2.0f);
    EXPECT_FLOAT_EQ(sahCost(Bvh{}), 0.0f);
}

TEST(SahCost, HandBuiltTree) {
    Bvh bvh;
    // Root [0,2]x[0,1]x[0,1] (area 10), leaves [0,1]^3 (area 6) with 1 and 3 primitives.
    bvh.nodes.resize(3);
    bvh.nodes[0] = {{0, 0, 0}, 1, {2, 1, 1}, 0};
    bvh.nodes[1] = {{0, 0, 0}, 0, {1, 1, 1}, 1};
    bvh.nodes[2] = {{1, 0, 0}, 1, {2, 1, 1}, 3};
    bvh.primIndices = {0, 1, 2, 3};
    BvhBuildOptions options;
    options.traversalCost = 2.0f;
    options.intersectionCost = 0.5f;
    EXPECT_FLOAT_EQ(sahCost(bvh, options), (2.0f * 10 + 0.5f * 6 * 1 + 0.5f * 6 * 3) / 10);
}

// ---- reference builders ------------------------------------------------------------------------

struct RefBuilder {
    const std::vector<Aabb>& bounds;
    BvhBuildOptions options;
    bool sweep;  // true: full-sweep SAH; false: object median
    Bvh bvh;

    float centroid(uint32_t p, int axis) const { return bounds[p].center()[axis]; }

    // Best full-sweep split of prims [begin, end): sets axis and left count, returns its cost.
    float bestSweep(uint32_t begin, uint32_t end, int& bestAxis, uint32_t& bestLeft) {
        const uint32_t n = end - begin;
        float best = kInf;
        std::vector<float> rightArea(n);
        for (int axis = 0; axis < 3; ++axis) {
            std::sort(bvh.primIndices.begin() + begin, bvh.primIndices.begin() + end,
                      [&](uint32_t a, uint32_t b) { return centroid(a, axis) < centroid(b, axis); });
            Aabb acc;
            for (uint32_t i = n - 1; i > 0; --i) {
                acc.grow(bounds[bvh.primIndices[begin + i]]);
                rightArea[i] = acc.surfaceArea();
            }
            acc = Aabb{};
            for (uint32_t i = 1; i < n; ++i) {
                acc.grow(bounds[bvh.primIndices[begin + i - 1]]);
                const float cost = acc.surfaceArea() * float(i) + rightArea[i] * float(n - i);
                if (cost < best) best = cost, bestAxis = axis, bestLeft = i;
            }
        }
        return best;
    }

    void build(uint32_t slot, uint32_t begin, uint32_t end) {
        Aabb box;
        for (uint32_t i = begin; i < end; ++i) box.grow(bounds[bvh.primIndices[i]]);
        const uint32_t n = end - begin;
        bvh.nodes[slot] = {box.lo, begin, box.hi, n};
        if (n == 1) return;
        int axis = box.extent().x >= box.extent().y ? (box.extent().x >= box.extent().z ? 0 : 2)
                                                    : (box.extent().y >= box.extent().z ? 1 : 2);
        uint32_t left = n / 2;
        if (sweep) {
            const float cost = bestSweep(begin, end, axis, left);
            const float split = options.traversalCost + options.intersectionCost * cost / box.surfaceArea();
            if (n <= options.maxLeafSize && options.intersectionCost * float(n) <= split) return;
        } else if (n <= options.maxLeafSize) {
            return;
        }
        std::sort(bvh.primIndices.begin() + begin, bvh.primIndices.begin() + end,
                  [&](uint32_t a, uint32_t b) { return centroid(a, axis) < centroid(b, axis); });
        const uint32_t child = uint32_t(bvh.nodes.size());
        bvh.nodes.resize(child + 2);
        bvh.nodes[slot].leftOrFirst = child;
        bvh.nodes[slot].count = 0;
        build(child, begin, begin + left);
        build(child + 1, begin + left, end);
    }

    Bvh run() {
        bvh.primIndices.resize(bounds.size());
        std::iota(bvh.primIndices.begin(), bvh.primIndices.end(), 0u);
        bvh.nodes.resize(1);
        build(0, 0, uint32_t(bounds.size()));
        return bvh;
    }
};

TEST(SahCost, BinnedIsCloseToFullSweepAndBeatsMedian) {
    Rng rng(21);
    for (SoupKind kind :
         {SoupKind::Uniform, SoupKind::Clustered, SoupKind::Needles, SoupKind::CoincidentCentroids}) {
        const std::vector<Aabb> bounds = test::triangleBounds(test::makeSoup(kind, 20000, rng));
        const BvhBuildOptions options;
        const float binned =
            sahCost(buildBinnedSahBvh(bounds.data(), uint32_t(bounds.size()), options), options);
        const float sweep = sahCost(RefBuilder{bounds, options, true, {}}.run(), options);
        const float median = sahCost(RefBuilder{bounds, options, false, {}}.run(), options);
        std::printf(
            "[ BVH      ] SAH cost %-21s binned %7.2f  sweep %7.2f  median %7.2f  binned/sweep %.3f\n",
            test::soupName(kind), binned, sweep, median, binned / sweep);
        EXPECT_LT(binned, 1.3f * sweep) << test::soupName(kind);
        EXPECT_LT(binned, median) << test::soupName(kind);
    }
}

}  // namespace
}  // namespace pt
