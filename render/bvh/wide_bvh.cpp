#include "render/bvh/wide_bvh.h"

#include <algorithm>
#include <limits>

#include "render/util/check.h"

namespace pt {

namespace {

void setSlot(WideBvhNode& wide, uint32_t slot, const BvhNode& box) {
    wide.loX[slot] = box.lo.x, wide.loY[slot] = box.lo.y, wide.loZ[slot] = box.lo.z;
    wide.hiX[slot] = box.hi.x, wide.hiY[slot] = box.hi.y, wide.hiZ[slot] = box.hi.z;
}

WideBvhNode emptyNode() {
    WideBvhNode n{};
    const float inf = std::numeric_limits<float>::infinity();
    for (uint32_t s = 0; s < WideBvhNode::kWidth; ++s) {
        n.loX[s] = n.loY[s] = n.loZ[s] = inf;
        n.hiX[s] = n.hiY[s] = n.hiZ[s] = -inf;
        n.child[s] = 0;
        n.count[s] = WideBvhNode::kEmpty;
    }
    return n;
}

// Per binary node, the primitives of the one wide leaf it becomes (0: it stays interior), and
// where they start in the primitive list: binary leaves as they are, and interior nodes over at
// most `limit` primitives in one contiguous range.
struct WideLeaves {
    std::vector<uint32_t> count, first;

    WideLeaves(const BvhNode* nodes, uint32_t nodeCount, uint32_t limit)
        : count(nodeCount, 0), first(nodeCount, 0) {
        if (nodeCount > 0) visit(nodes, nodeCount, 0, limit);
    }

private:
    // Post order (depth <= kBvhStackSize, the builders' bound). The empty root (count 0, no
    // children) stays interior.
    void visit(const BvhNode* nodes, uint32_t nodeCount, uint32_t n, uint32_t limit) {
        const BvhNode& node = nodes[n];
        if (node.isLeaf()) {
            count[n] = node.count, first[n] = node.leftOrFirst;
            return;
        }
        const uint32_t left = node.leftOrFirst, right = left + 1;
        if (right >= nodeCount) return;
        visit(nodes, nodeCount, left, limit);
        visit(nodes, nodeCount, right, limit);
        const bool contiguous =
            count[left] > 0 && count[right] > 0 && first[left] + count[left] == first[right];
        if (contiguous && count[left] + count[right] <= limit) {
            count[n] = count[left] + count[right], first[n] = first[left];
        }
    }
};

class Collapser {
public:
    Collapser(const BvhNode* nodes, uint32_t count, uint32_t leafPrimitives)
        : nodes_(nodes), count_(count), leaves_(nodes, leafPrimitives > 0 ? count : 0, leafPrimitives) {}

    WideBvh run() {
        if (count_ == 0 || isLeaf(0) || nodes_[0].leftOrFirst + 1 >= count_) {
            // A lone leaf (or the empty root) under a root of one slot.
            out_.nodes.push_back(emptyNode());
            out_.sourceNodes.assign(WideBvhNode::kWidth, WideBvhNode::kEmpty);
            if (count_ > 0 && isLeaf(0)) {
                WideChildren root;
                root.node[root.count++] = 0;
                fill(0, root);
            }
            return std::move(out_);
        }
        out_.nodes.push_back(emptyNode());
        out_.sourceNodes.assign(WideBvhNode::kWidth, WideBvhNode::kEmpty);
        collapse(0, 0);
        return std::move(out_);
    }

private:
    bool merging() const { return !leaves_.count.empty(); }
    bool isLeaf(uint32_t binary) const {
        return merging() ? leaves_.count[binary] > 0 : nodes_[binary].isLeaf();
    }

    // Sets wide node `wide`'s slots to binary nodes `kids`; returns the interior ones' slots.
    std::vector<uint32_t> fill(uint32_t wide, const WideChildren& kids) {
        std::vector<uint32_t> interior;
        for (uint32_t s = 0; s < kids.size(); ++s) {
            const uint32_t kid = kids[s];
            setSlot(out_.nodes[wide], s, nodes_[kid]);
            out_.sourceNodes[size_t(wide) * WideBvhNode::kWidth + s] = kid;
            const bool leaf = isLeaf(kid);
            out_.nodes[wide].count[s] = !leaf ? 0 : merging() ? leaves_.count[kid] : nodes_[kid].count;
            out_.nodes[wide].child[s] = !leaf ? 0 : merging() ? leaves_.first[kid] : nodes_[kid].leftOrFirst;
            if (!leaf) interior.push_back(s);
        }
        return interior;
    }

    void collapse(uint32_t wide, uint32_t binary) {
        const WideChildren kids = openLargestChildren(nodes_, binary, WideBvhNode::kWidth,
                                                      merging() ? leaves_.count.data() : nullptr);
        for (const uint32_t slot : fill(wide, kids)) {
            const uint32_t next = uint32_t(out_.nodes.size());
            out_.nodes.push_back(emptyNode());
            out_.sourceNodes.resize(out_.sourceNodes.size() + WideBvhNode::kWidth, WideBvhNode::kEmpty);
            out_.nodes[wide].child[slot] = next;
            collapse(next, kids[slot]);
        }
    }

    const BvhNode* nodes_;
    uint32_t count_;
    WideLeaves leaves_;  // empty without merging
    WideBvh out_;
};

}  // namespace

WideChildren openLargestChildren(const BvhNode* nodes, uint32_t binary, uint32_t width,
                                 const uint32_t* leafCounts) {
    const auto area = [nodes](uint32_t n) {
        const Vec3 d = nodes[n].hi - nodes[n].lo;
        return d.x * d.y + d.y * d.z + d.z * d.x;
    };
    width = std::min(width, WideChildren::kMaxWidth);
    WideChildren kids;
    float areas[WideChildren::kMaxWidth];
    const auto add = [&](uint32_t n) {
        const bool leaf = leafCounts ? leafCounts[n] > 0 : nodes[n].isLeaf();
        areas[kids.count] = leaf ? -1.0f : area(n);  // leaves are never opened
        kids.node[kids.count++] = n;
    };
    add(nodes[binary].leftOrFirst);
    add(nodes[binary].leftOrFirst + 1);
    while (kids.count < width) {
        uint32_t open = kids.count;
        for (uint32_t k = 0; k < kids.count; ++k) {
            if (areas[k] >= 0.0f && (open == kids.count || areas[k] > areas[open])) open = k;
        }
        if (open == kids.count) break;
        const uint32_t opened = kids.node[open];
        // The opened node's place goes to the last child, keeping the others' order.
        for (uint32_t k = open; k + 1 < kids.count; ++k)
            kids.node[k] = kids.node[k + 1], areas[k] = areas[k + 1];
        --kids.count;
        add(nodes[opened].leftOrFirst);
        add(nodes[opened].leftOrFirst + 1);
    }
    return kids;
}

WideBvh collapseToWide(const BvhNode* nodes, uint32_t count, uint32_t leafPrimitives) {
    return Collapser(nodes, count, leafPrimitives).run();
}

void refreshWideBoxes(const BvhNode* binary, const uint32_t* sourceNodes, WideBvhNode* wide,
                      uint32_t wideCount) {
    for (uint32_t n = 0; n < wideCount; ++n) {
        for (uint32_t s = 0; s < WideBvhNode::kWidth; ++s) {
            const uint32_t source = sourceNodes[size_t(n) * WideBvhNode::kWidth + s];
            if (source != WideBvhNode::kEmpty) setSlot(wide[n], s, binary[source]);
        }
    }
}

}  // namespace pt
