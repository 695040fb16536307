#pragma once
// Collapsing a binary BVH into the compressed 8-wide form the CUDA traversal walks
// (render/kernel/compressed_wide_node.h; Ylitie, Karras and Laine 2017). Which binary nodes
// become wide nodes, which leaves (a leaf may gather a subtree of up to kMaxLeafSize
// primitives) and which fill each wide node's slots is the paper's SAH-optimal choice
// (sah_collapse.h). A node's interior children are made together, so they are consecutive; its
// leaves' primitives are copied next to each other into a primitive list of the compressed
// tree's own. Children are placed in slots by the direction they lie in from the node's centre
// (the paper's section 3.1), a greedy assignment of the best (child, slot) pair first. Each slot
// remembers its binary node, so a refit of the binary tree is requantised in one pass instead
// of collapsed again.
#include <cstdint>
#include <vector>

#include "render/kernel/bvh_node.h"
#include "render/kernel/compressed_wide_node.h"

namespace pt {

struct CompressedWideBvh {
    std::vector<CompressedWideNode> nodes;  // nodes[0] is the root; childBase counts from it
    // The leaves' entries of the binary tree's primitive-index list, in the order the wide
    // leaves use them; primBase counts from its first entry.
    std::vector<uint32_t> primIndices;
    std::vector<uint32_t> sourceNodes;  // per slot (node * 8 + slot): its binary node, or kNoSourceNode
};

// The compressed form of the binary tree `nodes` (canonical layout, root at 0, `count` nodes,
// leaves of at most CompressedWideNode::kMaxLeafSize primitives) whose leaves index
// `primIndices`. An empty tree gives one node with no used slot.
CompressedWideBvh compressToWide(const BvhNode* nodes, uint32_t count, const uint32_t* primIndices);

// Makes `wide`'s child and primitive bases absolute, for a scene array whose nodes and entries
// it joins at `firstNode` and `firstPrim`.
void rebaseCompressedNodes(CompressedWideBvh& wide, uint32_t firstNode, uint32_t firstPrim);

// Requantises the boxes of `wideCount` compressed nodes from the binary nodes their slots came
// from (after a refit of `binary`).
void requantizeWideBoxes(const BvhNode* binary, const uint32_t* sourceNodes, CompressedWideNode* wide,
                         uint32_t wideCount);

}  // namespace pt
