#pragma once
// The leaf rule of a top-down SAH build, applied to a tree built without it (host and device).
//
// The GPU builders (LBVH, PLOC, H-PLOC) end every branch in a leaf of one primitive, where the
// binned SAH builder stops splitting once a leaf of up to kMaxCollapsedLeaf primitives is
// cheaper than the split (MacDonald and Booth 1990). Measured by sah_cost.h that costs a
// tessellated sphere 2-4% more (0.4% on a soup of random triangles, whose neighbours share less
// of their boxes), paid again by every ray in the extra nodes it visits. The SAH-optimal choice of
// which subtrees to turn into leaves is a bottom-up dynamic programme over the built tree (as
// Karras and Aila 2013 and Meister and Bittner 2018 finish their trees): a subtree of n <= the
// leaf limit primitives costs
//     min(A * n, A + cost(left) + cost(right))      (traversal and intersection cost 1),
// in units of surface area, and becomes a leaf where the first term is the smaller (or equal:
// fewer nodes). Only subtrees of at most kMaxCollapsedLeaf primitives can collapse, so the
// programme ends three levels above the leaves: on the device each leaf's thread climbs at most
// that far (render/backend/cuda/bvh_leaf_collapse.cu), and collapseChoice decides any one node
// alone, looking at most three levels down (the host's reference, in the tests).
#include <cstdint>

#include "render/bvh/aabb.h"
#include "render/kernel/bvh_node.h"
#include "render/math/hd.h"

namespace pt {

// The binned SAH builder's default leaf limit (BvhBuildOptions::maxLeafSize), which the GPU's
// walks already meet in trees built on the host.
constexpr uint32_t kMaxCollapsedLeaf = 4;
// A binary subtree of at most kMaxCollapsedLeaf primitives has at most this many nodes.
constexpr uint32_t kMaxCollapsedNodes = 2 * kMaxCollapsedLeaf - 1;

// What collapseChoice finds of a subtree of at most kMaxCollapsedLeaf primitives.
struct SubtreeChoice {
    uint32_t primitives = 0;  // 0: more than kMaxCollapsedLeaf (nothing else is filled in)
    float cost = 0.0f;        // its optimal SAH cost, in units of surface area
    bool asLeaf = false;      // that optimum makes it one leaf (always so for a leaf)
};

PT_HD float nodeSurfaceArea(const BvhNode& node) {
    Aabb box;
    box.lo = node.lo;
    box.hi = node.hi;
    return box.surfaceArea();
}

// One step of the programme: the choice for an interior node of `area` with `primitives` (at
// most kMaxCollapsedLeaf) below it, from its children's optimal costs. The device's bottom-up
// pass and collapseChoice both take it, so they agree bit for bit.
PT_HD SubtreeChoice leafOrSplit(float area, uint32_t primitives, float leftCost, float rightCost) {
    const float splitCost = area + (leftCost + rightCost);
    const float leafCost = area * float(primitives);
    SubtreeChoice choice;
    choice.primitives = primitives;
    choice.asLeaf = leafCost <= splitCost;
    choice.cost = choice.asLeaf ? leafCost : splitCost;
    return choice;
}

// The cost of a leaf's own primitives.
PT_HD float leafCost(const BvhNode& leaf) { return nodeSurfaceArea(leaf) * float(leaf.count); }

// The choice for the subtree of `nodes` under `root`. A leaf of more than kMaxCollapsedLeaf
// primitives, or an interior node above more, reports primitives = 0.
PT_HD SubtreeChoice collapseChoice(const BvhNode* nodes, uint32_t root) {
    // Pre-order, so that every node's children come after it: the costs are then worked out
    // back to front.
    uint32_t order[kMaxCollapsedNodes];
    uint32_t stack[kMaxCollapsedLeaf];
    uint32_t count = 0, depth = 0, primitives = 0;
    stack[depth++] = root;
    while (depth > 0) {
        const uint32_t index = stack[--depth];
        const BvhNode node = nodes[index];
        order[count++] = index;
        if (node.isLeaf()) {
            primitives += node.count;
            if (primitives > kMaxCollapsedLeaf) return {};
            continue;
        }
        // n leaves make 2n - 1 nodes: an interior node with nodes still to come past the limit
        // (or a full stack) has too many primitives below.
        if (count + depth + 2 > kMaxCollapsedNodes || depth + 2 > kMaxCollapsedLeaf) return {};
        stack[depth++] = node.leftOrFirst + 1;  // right popped after the whole left subtree
        stack[depth++] = node.leftOrFirst;
    }
    // Children: a node's left child is the next in pre-order; its right child follows the left
    // child's subtree. Sizes back to front give both.
    uint32_t size[kMaxCollapsedNodes];
    SubtreeChoice choice[kMaxCollapsedNodes];
    for (uint32_t k = count; k-- > 0;) {
        const BvhNode node = nodes[order[k]];
        if (node.isLeaf()) {
            size[k] = 1;
            choice[k].primitives = node.count;
            choice[k].cost = leafCost(node);
            choice[k].asLeaf = true;
            continue;
        }
        const uint32_t left = k + 1, right = left + size[left];
        size[k] = 1 + size[left] + size[right];
        choice[k] = leafOrSplit(nodeSurfaceArea(node), choice[left].primitives + choice[right].primitives,
                                choice[left].cost, choice[right].cost);
    }
    return choice[0];
}

// Calls visit(leaf) for each leaf under `root`, left to right: the leaves of a subtree that
// collapseChoice found to hold at most kMaxCollapsedLeaf primitives.
template <class Visit>
PT_HD void forEachSmallSubtreeLeaf(const BvhNode* nodes, uint32_t root, Visit&& visit) {
    uint32_t stack[kMaxCollapsedLeaf];
    uint32_t depth = 0;
    stack[depth++] = root;
    while (depth > 0) {
        const BvhNode node = nodes[stack[--depth]];
        if (node.isLeaf()) {
            visit(node);
        } else if (depth + 2 <= kMaxCollapsedLeaf) {  // always, below a small subtree's root
            stack[depth++] = node.leftOrFirst + 1;
            stack[depth++] = node.leftOrFirst;
        }
    }
}

}  // namespace pt
