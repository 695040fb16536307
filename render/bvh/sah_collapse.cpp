#include "render/bvh/sah_collapse.h"

#include <algorithm>
#include <limits>

#include "render/bvh/aabb.h"
#include "render/util/check.h"

namespace pt {

namespace {

constexpr float kNever = std::numeric_limits<float>::infinity();

// 0 for the empty root's inverted box.
float boxArea(const BvhNode& n) { return Aabb{n.lo, n.hi}.surfaceArea(); }

}  // namespace

SahCollapse::SahCollapse(const BvhNode* nodes, uint32_t count, const WideCollapseCosts& costs)
    : nodes_(nodes),
      count_(count),
      costs_(costs),
      cost_(size_t(count) * kSlots, kNever),
      choice_(size_t(count) * kSlots, kFewerSlots),
      leafCount_(count, 0),
      leafFirst_(count, 0) {
    PT_CHECK(costs.passWidth > 0);
    if (count == 0) return;
    // Pre-order by an explicit stack (the builders' trees are at most kBvhStackSize deep, but
    // their layouts need not put children after parents); solved in reverse, children first.
    std::vector<uint32_t> order, stack{0};
    order.reserve(count);
    while (!stack.empty()) {
        const uint32_t n = stack.back();
        stack.pop_back();
        order.push_back(n);
        const BvhNode& node = nodes[n];
        if (!node.isLeaf() && node.leftOrFirst + 1 < count) {
            stack.push_back(node.leftOrFirst);
            stack.push_back(node.leftOrFirst + 1);
        }
    }
    for (auto it = order.rbegin(); it != order.rend(); ++it) solve(*it, boxArea(nodes[*it]));
}

void SahCollapse::solve(uint32_t n, float area) {
    const BvhNode& node = nodes_[n];
    const auto leafCost = [&](uint32_t primitives) {
        return area * costs_.leafPass * float((primitives + costs_.passWidth - 1) / costs_.passWidth);
    };
    if (node.isLeaf() || node.leftOrFirst + 1 >= count_) {
        // A binary leaf is a leaf in any number of slots (the empty root: one of nothing).
        leafCount_[n] = node.isLeaf() ? node.count : 0;
        leafFirst_[n] = node.leftOrFirst;
        for (uint32_t i = 1; i <= kSlots; ++i) cost(n, i) = node.isLeaf() ? leafCost(node.count) : 0.0f;
        choice(n, 1) = kLeaf;
        return;
    }
    const uint32_t left = node.leftOrFirst, right = left + 1;
    const uint32_t gathered = leafCount_[left] + leafCount_[right];
    const bool oneRange = leafCount_[left] > 0 && leafCount_[right] > 0 &&
                          leafFirst_[left] + leafCount_[left] == leafFirst_[right];
    if (oneRange && gathered <= costs_.maxLeaf) leafCount_[n] = gathered, leafFirst_[n] = leafFirst_[left];
    // The children sharing i slots, the left one taking k of them.
    float shared[kSlots + 1];
    uint8_t leftSlots[kSlots + 1] = {};
    for (uint32_t i = 2; i <= kSlots; ++i) {
        shared[i] = kNever;
        for (uint32_t k = 1; k < i; ++k) {
            const float c = cost(left, k) + cost(right, i - k);
            if (c < shared[i]) shared[i] = c, leftSlots[i] = uint8_t(k);
        }
    }
    const float asLeaf = leafCount_[n] > 0 ? leafCost(leafCount_[n]) : kNever;
    const float asWideNode = area * costs_.node + shared[kSlots];
    cost(n, 1) = std::min(asLeaf, asWideNode);
    choice(n, 1) = asLeaf <= asWideNode ? kLeaf : kWideNode;
    for (uint32_t i = 2; i <= kSlots; ++i) {
        // Ties take the slots: under boxes of no area every way costs 0, and fewer slots would
        // make chains of two-wide nodes.
        const bool split = shared[i] <= cost(n, i - 1);
        cost(n, i) = split ? shared[i] : cost(n, i - 1);
        choice(n, i) = split ? leftSlots[i] : kFewerSlots;
    }
}

void SahCollapse::collect(uint32_t n, uint32_t slots, WideChildren& out) const {
    while (slots > 1 && choice(n, slots) == kFewerSlots) --slots;
    if (slots == 1) {
        out.node[out.count++] = n;
        return;
    }
    const uint32_t left = nodes_[n].leftOrFirst, k = choice(n, slots);
    collect(left, k, out);
    collect(left + 1, slots - k, out);
}

WideChildren SahCollapse::childrenOf(uint32_t n) const {
    PT_CHECK(n < count_ && !nodes_[n].isLeaf() && nodes_[n].leftOrFirst + 1 < count_);
    // The best way for n's children to share all eight slots (not choice(n, 8), which may
    // make n itself one slot).
    const uint32_t left = nodes_[n].leftOrFirst, right = left + 1;
    uint32_t best = 1;
    for (uint32_t k = 2; k < kSlots; ++k) {
        if (cost(left, k) + cost(right, kSlots - k) < cost(left, best) + cost(right, kSlots - best)) best = k;
    }
    WideChildren kids;
    collect(left, best, kids);
    collect(right, kSlots - best, kids);
    return kids;
}

float SahCollapse::rootCost() const {
    const float area = count_ > 0 ? boxArea(nodes_[0]) : 0.0f;
    if (!(area > 0.0f)) return 0.0f;  // no tree, or the empty root
    if (nodes_[0].isLeaf() || isLeaf(0) || nodes_[0].leftOrFirst + 1 >= count_) return cost(0, 1) / area;
    const WideChildren kids = childrenOf(0);
    float total = area * costs_.node;
    for (uint32_t s = 0; s < kids.size(); ++s) total += cost(kids[s], 1);
    return total / area;
}

}  // namespace pt
