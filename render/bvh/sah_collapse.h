#pragma once
// The SAH-optimal collapse of a binary BVH into an 8-wide one (Ylitie, Karras and Laine 2017,
// "Efficient Incoherent Ray Traversal on GPUs Through Compressed Wide BVHs", section 3.1). A
// dynamic programme over the binary nodes, bottom-up, finds for each node and each number of
// slots i = 1..8 the cheapest way for its subtree to fill at most i slots of the wide node
// above it: one slot as a leaf (its primitives, if few enough), one slot as a wide node of its
// own, or its two children sharing the i slots. The greedy collapse (openLargestChildren) opens
// the largest subtrees first whatever they cost below, so where subtrees are small its wide
// nodes keep slots empty (a third of them on a 1M-triangle sphere), and its leaves are whatever
// size a subtree under the limit happens to have. The GPU's compressed tree is collapsed so
// (compressed_wide_bvh.cpp has the figures: 3-8% more rays a second but on the 1M sphere's
// camera rays, 1.5-3% fewer). The CPU's
// 8-wide tree keeps the greedy collapse: there this one filled the nodes (6213 empty slots of
// 281088 against 107083 of 307728, 1M-triangle sphere) but traced diffuse rays no faster (one
// thread, three alternated runs: 4.56 / 4.57 / 4.59 Mrays/s greedy, 4.58 / 4.46 / 4.86 with
// blocks of eight a pass at half a node's cost, 4.50 / 4.45 / 4.65 with blocks of four at a
// quarter), its walk being bound by the loads of triangle blocks.
#include <cstdint>
#include <vector>

#include "render/bvh/wide_bvh.h"
#include "render/kernel/bvh_node.h"

namespace pt {

// The SAH costs the programme weighs, per unit of surface area (the chance that a ray which
// reaches the parent also reaches the box).
// The defaults are the GPU's compressed walk's (compressed_wide_bvh.cpp).
struct WideCollapseCosts {
    float node = 1.0f;       // one wide node's test (all its boxes at once)
    float leafPass = 0.3f;   // one pass over a leaf's primitives, `passWidth` at a time
    uint32_t passWidth = 1;  // primitives a pass tests together
    uint32_t maxLeaf = 4;    // the most primitives a leaf gathers from a subtree (one contiguous range)
};

class SahCollapse {
public:
    // Over binary tree `nodes` (root at 0, `count` nodes, each subtree's primitives a contiguous
    // range of the primitive list, as the binned builder lays them out). Binary leaves of more
    // than costs.maxLeaf primitives stay leaves.
    SahCollapse(const BvhNode* nodes, uint32_t count, const WideCollapseCosts& costs);

    // Whether binary node `n`, where it fills a slot, is a leaf; its primitives then.
    bool isLeaf(uint32_t n) const { return leafCount_[n] > 0 && choice(n, 1) == kLeaf; }
    uint32_t leafCount(uint32_t n) const { return leafCount_[n]; }
    uint32_t leafFirst(uint32_t n) const { return leafFirst_[n]; }
    // The up to eight slots of the wide node made of binary interior node `n`.
    WideChildren childrenOf(uint32_t n) const;
    // The wide tree's SAH cost relative to the root's area: its expected cost for a ray that
    // hits the root box.
    float rootCost() const;

private:
    static constexpr uint32_t kSlots = WideChildren::kMaxWidth;
    // choice(n, 1): kLeaf or kWideNode; choice(n, i > 1): kFewerSlots (as with i - 1) or the
    // slots given to the left child (1 .. i - 1), the right one taking the rest.
    static constexpr uint8_t kLeaf = 0, kWideNode = 1, kFewerSlots = 0;

    float& cost(uint32_t n, uint32_t slots) { return cost_[size_t(n) * kSlots + slots - 1]; }
    float cost(uint32_t n, uint32_t slots) const { return cost_[size_t(n) * kSlots + slots - 1]; }
    uint8_t& choice(uint32_t n, uint32_t slots) { return choice_[size_t(n) * kSlots + slots - 1]; }
    uint8_t choice(uint32_t n, uint32_t slots) const { return choice_[size_t(n) * kSlots + slots - 1]; }
    void solve(uint32_t n, float area);
    void collect(uint32_t n, uint32_t slots, WideChildren& out) const;

    const BvhNode* nodes_;
    uint32_t count_;
    WideCollapseCosts costs_;
    std::vector<float> cost_;
    std::vector<uint8_t> choice_;
    // Per node: the primitives of the one leaf it can become (0: none, too many or not one
    // contiguous range) and where they start.
    std::vector<uint32_t> leafCount_, leafFirst_;
};

}  // namespace pt
