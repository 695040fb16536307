#include "render/bvh/compressed_wide_bvh.h"

#include <array>
#include <utility>

#include "render/bvh/compressed_wide_quantize.h"
#include "render/bvh/sah_collapse.h"
#include "render/bvh/wide_bvh.h"
#include "render/util/check.h"

namespace pt {

namespace {

using Slots = std::array<uint32_t, CompressedWideNode::kWidth>;

// The SAH costs the collapse weighs (sah_collapse.h): the walk tests a leaf's triangles one at a
// time, each about 0.3 of a wide node's test (Ylitie et al. 2017 weigh them so), and a leaf
// holds at most kMaxLeafSize, so that a node's eight leaves fit its 32 primitive bits. Against
// the greedy collapse (openLargestChildren) on the H200, `pt-render bench --size 1280x720
// --gpu-wide-bvh`, two alternated rounds, Mrays/s: 1M-triangle sphere primary 1946 / 1955 ->
// 1918 / 1894, diffuse 1203 / 1184 -> 1290 / 1264, shadow 968 / 948 -> 980 / 990, wavefront path
// tracing 1023 / 1016 -> 1046 / 1043 spp/s; Balloon primary 3416 / 3489 -> 3698 / 3769, diffuse
// 159 / 162 -> 173 / 174, shadow 155 / 156 -> 161 / 161, wavefront 737 / 740 -> 806 / 798 spp/s.
constexpr WideCollapseCosts kCollapseCosts{1.0f, 0.3f, 1, CompressedWideNode::kMaxLeafSize};

// Slot s points along -axis a where bit a of s is set: the slot of the child lying farthest
// that way, so a ray whose direction has the opposite signs meets it first.
float towardsSlot(Vec3 offset, uint32_t slot) {
    float sum = 0.0f;
    for (int a = 0; a < 3; ++a) sum += (slot >> a & 1u) ? -offset[a] : offset[a];
    return sum;
}

// Binary nodes `kids` placed into slots: the (child, slot) pair whose child lies farthest
// towards the slot's direction first, then the best of the rest.
Slots assignSlots(const BvhNode* nodes, uint32_t parent, const WideChildren& kids) {
    Slots slots;
    slots.fill(kNoSourceNode);
    const Vec3 centre = (nodes[parent].lo + nodes[parent].hi) * 0.5f;
    float score[WideChildren::kMaxWidth][CompressedWideNode::kWidth];
    for (uint32_t k = 0; k < kids.size(); ++k) {
        const Vec3 offset = (nodes[kids[k]].lo + nodes[kids[k]].hi) * 0.5f - centre;
        for (uint32_t s = 0; s < CompressedWideNode::kWidth; ++s) score[k][s] = towardsSlot(offset, s);
    }
    uint32_t placed = 0;  // bit k: child k has its slot
    for (uint32_t round = 0; round < kids.size(); ++round) {
        bool any = false;
        float best = 0.0f;
        uint32_t bestKid = 0, bestSlot = 0;
        for (uint32_t k = 0; k < kids.size(); ++k) {
            if ((placed >> k) & 1u) continue;
            for (uint32_t s = 0; s < CompressedWideNode::kWidth; ++s) {
                if (slots[s] != kNoSourceNode) continue;
                if (!any || score[k][s] > best) any = true, best = score[k][s], bestKid = k, bestSlot = s;
            }
        }
        placed |= 1u << bestKid;
        slots[bestSlot] = kids[bestKid];
    }
    return slots;
}

class Compressor {
public:
    Compressor(const BvhNode* nodes, uint32_t count, const uint32_t* primIndices)
        : nodes_(nodes), count_(count), primIndices_(primIndices), sah_(nodes, count, kCollapseCosts) {}

    CompressedWideBvh run() {
        out_.nodes.push_back(CompressedWideNode{});
        out_.sourceNodes.assign(CompressedWideNode::kWidth, kNoSourceNode);
        if (count_ == 0 || isLeaf(0) || nodes_[0].leftOrFirst + 1 >= count_) {
            // A lone leaf (or the empty root) in slot 0 of the root.
            Slots slots;
            slots.fill(kNoSourceNode);
            if (count_ > 0 && isLeaf(0)) slots[0] = 0;
            fill(0, slots);
            return std::move(out_);
        }
        pending_.push_back({0, 0});
        while (!pending_.empty()) {
            const auto [wide, binary] = pending_.back();
            pending_.pop_back();
            fill(wide, assignSlots(nodes_, binary, sah_.childrenOf(binary)));
        }
        return std::move(out_);
    }

private:
    bool isLeaf(uint32_t binary) const { return sah_.isLeaf(binary); }

    // Wide node `wide` over the binary nodes in `slots`: its interior children are appended
    // as new nodes (to be filled in turn), its leaves' primitives to the primitive list.
    void fill(uint32_t wide, const Slots& slots) {
        CompressedWideNode node{};
        node.childBase = uint32_t(out_.nodes.size());
        node.primBase = uint32_t(out_.primIndices.size());
        for (uint32_t s = 0; s < CompressedWideNode::kWidth; ++s) {
            out_.sourceNodes[size_t(wide) * CompressedWideNode::kWidth + s] = slots[s];
            if (slots[s] == kNoSourceNode) continue;
            if (!isLeaf(slots[s])) {
                node.interiorMask |= uint8_t(1u << s);
                pending_.push_back({uint32_t(out_.nodes.size()), slots[s]});
                out_.nodes.push_back(CompressedWideNode{});
                out_.sourceNodes.resize(out_.sourceNodes.size() + CompressedWideNode::kWidth, kNoSourceNode);
                continue;
            }
            const uint32_t count = sah_.leafCount(slots[s]), first = sah_.leafFirst(slots[s]);
            PT_CHECK(count <= CompressedWideNode::kMaxLeafSize);
            const uint32_t offset = uint32_t(out_.primIndices.size()) - node.primBase;
            node.leafMeta[s] = uint8_t(count << 5 | offset);
            out_.primIndices.insert(out_.primIndices.end(), primIndices_ + first,
                                    primIndices_ + first + count);
        }
        quantizeWideBoxes(node, nodes_, slots.data());
        out_.nodes[wide] = node;
    }

    const BvhNode* nodes_;
    uint32_t count_;
    const uint32_t* primIndices_;
    SahCollapse sah_;
    // (wide node, binary node) to fill, taken last first: depth first, so the binary nodes are
    // read about in their (depth-first) memory order (1M triangles: 104 ms, breadth first 118).
    std::vector<std::pair<uint32_t, uint32_t>> pending_;
    CompressedWideBvh out_;
};

}  // namespace

CompressedWideBvh compressToWide(const BvhNode* nodes, uint32_t count, const uint32_t* primIndices) {
    return Compressor(nodes, count, primIndices).run();
}

void rebaseCompressedNodes(CompressedWideBvh& wide, uint32_t firstNode, uint32_t firstPrim) {
    for (CompressedWideNode& node : wide.nodes) {
        node.childBase += firstNode;
        node.primBase += firstPrim;
    }
}

void requantizeWideBoxes(const BvhNode* binary, const uint32_t* sourceNodes, CompressedWideNode* wide,
                         uint32_t wideCount) {
    for (uint32_t n = 0; n < wideCount; ++n) {
        quantizeWideBoxes(wide[n], binary, sourceNodes + size_t(n) * CompressedWideNode::kWidth);
    }
}

}  // namespace pt
