#include "render/bvh/binned_sah_builder.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <atomic>
#include <cassert>
#include <memory>

#include "render/bvh/bvh_walk.h"
#include "render/bvh/sah_split.h"

// Sections: the recursive builder / compaction into the canonical depth-first layout /
// entry point. Split selection and partitioning live in sah_split.{h,cpp}.

namespace pt {

namespace {

using sah::Box4;
using sah::PrimRange;
using sah::SahSplit;

constexpr uint32_t kParallelTaskSize = 4096;  // nodes this large build their children as tasks
constexpr uint32_t kGrain = 1u << 14;

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
    Box4 centroids;       // of the doubled centroids
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

    // Nodes made so far: a binary tree of L leaves has 2L - 1.
    uint32_t nodeCount() const { return 2 * leaves_.load() - 1; }

    void build(const NodeTask& task) {
        NodeTask left, right;
        if (!split(task, left, right)) {
            nodes_[task.slot] = rawNode(task.bounds, task.begin, task.end - task.begin);
            leaves_.fetch_add(1, std::memory_order_relaxed);
            if (options_.onLeaf) options_.onLeaf(task.end - task.begin);
            return;
        }
        nodes_[task.slot] = rawNode(task.bounds, task.childBase, 0);
        if (task.end - task.begin >= kParallelTaskSize) {
            tbb::task_group group;
            group.run([&] { build(left); });
            build(right);
            group.wait();
        } else {
            build(left);
            build(right);
        }
    }

private:
    enum class Choice { Leaf, Sah, Median };

    PrimRange range(uint32_t begin, uint32_t end) const {
        return {boxes_ + begin, indices_ + begin, end - begin};
    }

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
        const sah::BinMapping m(task.centroids, binCount_);
        SahSplit sahSplit;
        const Choice choice = choose(task, m, sahSplit);
        if (choice == Choice::Leaf) return false;
        const PrimRange prims = range(task.begin, task.end);
        uint32_t leftCount;
        bool boundsKnown = false;
        if (choice == Choice::Median) {
            leftCount = sah::partitionByMedian(prims, task.centroids);
        } else if (sahSplit.sorted) {
            leftCount = sahSplit.leftCount;
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
    uint32_t* indices_;
    RawNode* nodes_;
    BvhBuildOptions options_;
    uint32_t binCount_, maxLeafSize_;
    std::atomic<uint32_t> leaves_{0};
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
// nodes (`nodeCount` of them) depth first, sibling pairs adjacent, which is also the
// cache-friendly order. Reserved at their exact number: reserving 2n - 1 and shrinking after
// copied the whole tree once more.
std::vector<BvhNode> compactNodes(const RawNode* scratch, uint32_t nodeCount) {
    std::vector<BvhNode> out;
    out.reserve(nodeCount);
    out.push_back(toBvhNode(scratch[0]));
    struct Pending {
        uint32_t src, dst;
    };
    std::vector<Pending> stack{{0, 0}};
    while (!stack.empty()) {
        const Pending p = stack.back();
        stack.pop_back();
        const RawNode& raw = scratch[p.src];
        out[p.dst] = toBvhNode(raw);
        if (raw.count > 0) continue;
        const uint32_t left = uint32_t(out.size());
        out[p.dst].leftOrFirst = left;
        out.resize(out.size() + 2);
        stack.push_back({raw.leftOrFirst + 1, left + 1});
        stack.push_back({raw.leftOrFirst, left});
    }
    assert(out.size() == nodeCount && "every node made is reachable");
    return out;
}

// ---- entry point -----------------------------------------------------------------------------

// Copies the input into the build arrays and returns the root task (bounds in parallel).
NodeTask prepareRoot(const Aabb* primBounds, uint32_t count, Box4* boxes, uint32_t* indices) {
    struct Bounds {
        Box4 box = Box4::empty(), centroids = Box4::empty();
    };
    using Range = tbb::blocked_range<uint32_t>;
    const Bounds root = tbb::parallel_reduce(
        Range(0, count, kGrain), Bounds{},
        [&](const Range& r, Bounds acc) {
            for (uint32_t i = r.begin(); i != r.end(); ++i) {
                const Aabb& b = primBounds[i];
                boxes[i] = {{b.lo.x, b.lo.y, b.lo.z, 0.0f}, {b.hi.x, b.hi.y, b.hi.z, 0.0f}};
                indices[i] = i;
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
    return {0, 0, count, 0, 1, root.box, root.centroids};
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
    std::unique_ptr<Box4[]> boxes(new Box4[count]);
    bvh.primIndices.resize(count);
    std::unique_ptr<RawNode[]> scratch(new RawNode[2 * size_t(count) - 1]);
    const NodeTask root = prepareRoot(primBounds, count, boxes.get(), bvh.primIndices.data());
    BinnedSahBuilder builder(boxes.get(), bvh.primIndices.data(), scratch.get(), options);
    builder.build(root);
    bvh.nodes = compactNodes(scratch.get(), builder.nodeCount());
    return bvh;
}

}  // namespace pt
