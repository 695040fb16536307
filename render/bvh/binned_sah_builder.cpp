#include "render/bvh/binned_sah_builder.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <cassert>
#include <memory>

#include "render/bvh/bvh_walk.h"
#include "render/bvh/sah_split.h"
#include "render/util/large_array.h"

// Sections: the recursive builder / compaction into the canonical depth-first layout /
// entry point. Split selection and partitioning live in sah_split.{h,cpp}.

namespace pt {

namespace {

using sah::Box4;
using sah::PrimRange;
using sah::SahSplit;

constexpr uint32_t kParallelTaskSize = 4096;  // nodes this large build their children as tasks
constexpr uint32_t kGrain = 1u << 14;
// Marks an interior node in the scratch array (a leaf's count is at most maxLeafSize).
constexpr uint32_t kInteriorFlag = 1u << 31;
constexpr uint32_t kParallelCompactSize = 1u << 13;  // subtrees of this many nodes compact as tasks

// BvhNode's 32 bytes without its initialisers, for the uninitialised scratch array: 2n - 1 of
// them are reserved, and every page the build touches is one the kernel clears first (10M
// triangles: a fifth of the build's time, with the 40-byte nodes this scratch held before).
struct RawNode {
    float lo[3];
    uint32_t leftOrFirst;
    float hi[3];
    uint32_t count;
};
static_assert(sizeof(RawNode) == sizeof(BvhNode), "RawNode: BvhNode's layout");

RawNode rawNode(const Box4& box, uint32_t leftOrFirst, uint32_t count) {
    return {{box.lo[0], box.lo[1], box.lo[2]}, leftOrFirst, {box.hi[0], box.hi[1], box.hi[2]}, count};
}

// ---- the recursive builder -------------------------------------------------------------------

struct NodeTask {
    uint32_t slot;        // this node's scratch slot
    uint32_t begin, end;  // its primitive range
    uint32_t depth;       // root: 0
    uint32_t childBase;   // first of the 2n - 2 scratch slots reserved for its descendants
    Box4 bounds;          // of the primitive boxes
    Box4 centroids;       // of the doubled centroids, where centroidsKnown
    bool centroidsKnown;  // false below a sweep's split, where only a median split reads them
};

uint32_t ceilLog2(uint32_t n) { return n <= 1 ? 0u : 32u - uint32_t(__builtin_clz(n - 1)); }

class BinnedSahBuilder {
public:
    BinnedSahBuilder(Box4* boxes, uint32_t* indices, RawNode* nodes, const BvhBuildOptions& options)
        : boxes_(boxes),
          indices_(indices),
          nodes_(nodes),
          options_(options),
          binCount_(std::clamp(options.binCount, 2u, sah::kMaxBins)),
          maxLeafSize_(std::max(options.maxLeafSize, 1u)) {}

    // Builds the subtree of `task` and returns its node count. An interior node's scratch
    // `count` holds kInteriorFlag | the node count of its left subtree, which is where the
    // compaction puts its right child's descendants.
    uint32_t build(const NodeTask& task) {
        NodeTask left, right;
        if (!split(task, left, right)) {
            nodes_[task.slot] = rawNode(task.bounds, task.begin, task.end - task.begin);
            for (uint32_t i = task.begin; i < task.end; ++i) indices_[i] = boxes_[i].primitive();
            if (options_.onLeaf) options_.onLeaf(task.end - task.begin);
            return 1;
        }
        uint32_t leftNodes = 0, rightNodes = 0;
        if (task.end - task.begin >= kParallelTaskSize) {
            tbb::task_group group;
            group.run([&] { leftNodes = build(left); });
            rightNodes = build(right);
            group.wait();
        } else {
            leftNodes = build(left);
            rightNodes = build(right);
        }
        nodes_[task.slot] = rawNode(task.bounds, task.childBase, kInteriorFlag | leftNodes);
        return 1 + leftNodes + rightNodes;
    }

private:
    enum class Choice { Leaf, Sah, Median };

    PrimRange range(uint32_t begin, uint32_t end) const { return {boxes_ + begin, end - begin}; }

    Choice choose(const NodeTask& task, const sah::BinMapping& m, SahSplit& split) const {
        const uint32_t n = task.end - task.begin;
        const float area = task.bounds.halfArea();
        if (n == 1) return Choice::Leaf;
        if (area > 0.0f && n <= sah::kSweepSize) {
            split = sah::findSweepSplit(range(task.begin, task.end));
        } else if (area > 0.0f && m.separable()) {
            split = sah::findBinnedSplit(range(task.begin, task.end), m);
        }
        if (split.axis < 0) return n <= maxLeafSize_ ? Choice::Leaf : Choice::Median;
        const float splitCost = options_.traversalCost + options_.intersectionCost * split.cost / area;
        if (n <= maxLeafSize_ && options_.intersectionCost * float(n) <= splitCost) return Choice::Leaf;
        // Take the SAH split only if halving from the larger child still fits the stack.
        const uint32_t larger = std::max(split.leftCount, n - split.leftCount);
        const bool fits = task.depth + 1 + ceilLog2(larger) <= kBvhStackSize;
        return fits ? Choice::Sah : Choice::Median;
    }

    // Partitions the node's range and describes both children; false: make a leaf.
    bool split(const NodeTask& task, NodeTask& left, NodeTask& right) {
        // Nodes small enough for the sweep are never binned (choose).
        const sah::BinMapping m = task.end - task.begin > sah::kSweepSize
                                      ? sah::BinMapping(task.centroids, binCount_)
                                      : sah::BinMapping::none();
        SahSplit sahSplit;
        const Choice choice = choose(task, m, sahSplit);
        if (choice == Choice::Leaf) return false;
        const PrimRange prims = range(task.begin, task.end);
        uint32_t leftCount;
        bool boundsKnown = false;
        left.centroidsKnown = right.centroidsKnown = true;
        if (choice == Choice::Median) {
            Box4 bounds, centroids = task.centroids;
            if (!task.centroidsKnown) sah::boundsOf(prims, bounds, centroids);
            leftCount = sah::partitionByMedian(prims, centroids);
        } else if (sahSplit.sorted) {
            // The sweep's prefix and suffix are the children's boxes; their centroids are left
            // unknown, as their children are split by sweeps too.
            leftCount = sahSplit.leftCount;
            left.bounds = sahSplit.leftBounds;
            right.bounds = sahSplit.rightBounds;
            left.centroidsKnown = right.centroidsKnown = false;
            boundsKnown = true;
        } else {
            leftCount = sah::partitionByBin(prims, m, sahSplit, left.centroids, right.centroids);
            // Binning and partitioning share their arithmetic (BinMapping::coordinates), so the
            // counts agree and the bins' boxes are the children's; were that ever broken, the
            // boxes below come from the actual ranges and the tree stays exact.
            assert(leftCount == sahSplit.leftCount && "partition disagrees with the bins");
            boundsKnown = leftCount == sahSplit.leftCount;
            if (leftCount == 0 || leftCount == prims.count)
                leftCount = sah::partitionByMedian(prims, task.centroids);
            left.bounds = sahSplit.leftBounds;
            right.bounds = sahSplit.rightBounds;
        }
        if (!boundsKnown) {
            sah::boundsOf(prims.sub(0, leftCount), left.bounds, left.centroids);
            sah::boundsOf(prims.sub(leftCount, prims.count - leftCount), right.bounds, right.centroids);
        }
        // Children at childBase and childBase + 1; a subtree of k primitives has at most
        // 2k - 2 descendants, which fixes where each child's own reservation starts.
        left.slot = task.childBase;
        right.slot = task.childBase + 1;
        left.begin = task.begin;
        left.end = right.begin = task.begin + leftCount;
        right.end = task.end;
        left.depth = right.depth = task.depth + 1;
        left.childBase = task.childBase + 2;
        right.childBase = task.childBase + 2 * leftCount;
        return true;
    }

    Box4* boxes_;
    uint32_t* indices_;  // the output's primIndices, written as each leaf is made
    RawNode* nodes_;
    BvhBuildOptions options_;
    uint32_t binCount_, maxLeafSize_;
};

// ---- compaction into the canonical layout ----------------------------------------------------

BvhNode toBvhNode(const RawNode& raw) {
    BvhNode node;
    node.lo = {raw.lo[0], raw.lo[1], raw.lo[2]};
    node.hi = {raw.hi[0], raw.hi[1], raw.hi[2]};
    node.leftOrFirst = raw.leftOrFirst;
    node.count = raw.count;
    return node;
}

// The scratch array has gaps (reservations are upper bounds); this renumbers the reachable
// nodes depth first, sibling pairs adjacent, which is also the cache-friendly order: node `src`
// of the scratch goes to out[dst], and its descendants from out[next] on. Each interior node
// knows its left subtree's node count, so both subtrees are placed at once and large ones are
// copied as parallel tasks.
void compactSubtree(const RawNode* scratch, uint32_t src, BvhNode* out, uint32_t dst, uint32_t next) {
    const RawNode& raw = scratch[src];
    out[dst] = toBvhNode(raw);
    if (!(raw.count & kInteriorFlag)) return;
    out[dst].count = 0;
    out[dst].leftOrFirst = next;
    const uint32_t leftNodes = raw.count & ~kInteriorFlag;
    // The children at next and next + 1; the left one's descendants (leftNodes - 1 of them)
    // first, then the right one's.
    const auto left = [&] { compactSubtree(scratch, raw.leftOrFirst, out, next, next + 2); };
    const auto right = [&] {
        compactSubtree(scratch, raw.leftOrFirst + 1, out, next + 1, next + 1 + leftNodes);
    };
    if (leftNodes >= kParallelCompactSize) {
        tbb::task_group group;
        group.run(left);
        right();
        group.wait();
    } else {
        left();
        right();
    }
}

std::vector<BvhNode> compactNodes(const RawNode* scratch, uint32_t nodeCount) {
    std::vector<BvhNode> out;
    out.reserve(nodeCount);
    adviseHugePages(out.data(), nodeCount * sizeof(BvhNode));
    out.resize(nodeCount);
    compactSubtree(scratch, 0, out.data(), 0, 1);
    return out;
}

// ---- entry point -----------------------------------------------------------------------------

// Copies the input into the build arrays and returns the root task (bounds in parallel).
NodeTask prepareRoot(const Aabb* primBounds, uint32_t count, Box4* boxes) {
    struct Bounds {
        Box4 box = Box4::empty(), centroids = Box4::empty();
    };
    using Range = tbb::blocked_range<uint32_t>;
    const Bounds root = tbb::parallel_reduce(
        Range(0, count, kGrain), Bounds{},
        [&](const Range& r, Bounds acc) {
            for (uint32_t i = r.begin(); i != r.end(); ++i) {
                boxes[i] = Box4::ofPrimitive(primBounds[i].lo, primBounds[i].hi, i);
                acc.box.grow(boxes[i]);
                acc.centroids.grow(boxes[i].centroidPoint());
            }
            return acc;
        },
        [](Bounds a, const Bounds& b) {
            a.box.grow(b.box);
            a.centroids.grow(b.centroids);
            return a;
        });
    return {0, 0, count, 0, 1, root.box, root.centroids, true};
}

}  // namespace

Bvh buildBinnedSahBvh(const Aabb* primBounds, uint32_t count, const BvhBuildOptions& options) {
    Bvh bvh;
    if (count == 0) {
        bvh.nodes.resize(1);  // the empty box of a default Aabb: lo = +inf, hi = -inf
        bvh.nodes[0].lo = Aabb{}.lo;
        bvh.nodes[0].hi = Aabb{}.hi;
        bvh.nodes[0].leftOrFirst = 0;
        bvh.nodes[0].count = 0;
        return bvh;
    }
    const LargeArray<Box4> boxes(count);
    bvh.primIndices.resize(count);
    const LargeArray<RawNode> scratch(2 * size_t(count) - 1);
    const NodeTask root = prepareRoot(primBounds, count, boxes.data());
    BinnedSahBuilder builder(boxes.data(), bvh.primIndices.data(), scratch.data(), options);
    const uint32_t nodeCount = builder.build(root);
    bvh.nodes = compactNodes(scratch.data(), nodeCount);
    return bvh;
}

}  // namespace pt
