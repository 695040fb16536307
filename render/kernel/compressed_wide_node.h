#pragma once
// An 8-wide BVH node with quantised child boxes for the CUDA traversal (issue 21): Ylitie,
// Karras and Laine, "Efficient Incoherent Ray Traversal on GPUs Through Compressed Wide BVHs",
// HPG 2017. Eight child boxes in 80 bytes (against 8 x 32 bytes of binary nodes): each box
// corner is origin + 2^exponent * q with q an 8-bit integer, rounded outwards, so a box test
// against the quantised box admits every ray the exact box admits. Collapsed from the
// canonical binary tree (render/bvh/compressed_wide_bvh.h), which stays the source of truth:
// builders and refits write BvhNode, and the quantised boxes are recomputed from it.
//
// Children are stored for a walk without per-node sorting: the interior children of a node
// are consecutive nodes from childBase (in slot order), the primitives of its leaf children
// consecutive entries from primBase, and slot s holds the child that lies farthest towards
// the octant whose axis a is negative where bit a of s is set, so a ray visits the slots in
// the order of s XOR its octant (render/bvh/compressed_wide_walk.h).
#include <cstdint>

#include "render/math/vec.h"

namespace pt {

struct alignas(16) CompressedWideNode {
    static constexpr uint32_t kWidth = 8;
    // Leaves hold at most this many primitives (the binned-SAH builder's maxLeafSize), so the
    // eight leaves of a node fill at most 32 primitive bits of the walk's leaf mask.
    static constexpr uint32_t kMaxLeafSize = 4;

    Vec3 origin;           // the quantisation grid's corner (object space)
    uint8_t exponent[3];   // per axis, the grid step 2^(exponent - 127): a float's biased exponent
    uint8_t interiorMask;  // bit s: slot s holds an interior child
    uint32_t childBase;    // the first interior child's node index
    uint32_t primBase;     // the first of the leaves' entries in the compressed primitive list
    // Per slot: a leaf's (count << 5) | offset from primBase; 0 for an interior or unused slot.
    uint8_t leafMeta[kWidth];
    // Box corners in grid steps from origin, grouped by half node: planes[h][p][k] is plane p
    // (BoxPlane) of slot 4 h + k, so the walk takes a half's 24 bytes in two loads, not six.
    uint8_t planes[2][6][4];

    enum BoxPlane : uint32_t { kLoX, kLoY, kLoZ, kHiX, kHiY, kHiZ };
    PT_HD uint8_t& plane(BoxPlane p, uint32_t slot) { return planes[slot >> 2][p][slot & 3u]; }
    PT_HD uint8_t plane(BoxPlane p, uint32_t slot) const { return planes[slot >> 2][p][slot & 3u]; }
    PT_HD uint32_t leafCount(uint32_t slot) const { return uint32_t(leafMeta[slot]) >> 5; }
    PT_HD uint32_t leafOffset(uint32_t slot) const { return uint32_t(leafMeta[slot]) & 31u; }
};
static_assert(sizeof(CompressedWideNode) == 80, "CompressedWideNode: 80 bytes (five 16-byte loads)");

// A scene's compressed primitive list holds fewer entries than this: the walk marks a postponed
// primitive group's base on its stack with this bit (compressed_wide_walk.h).
constexpr uint32_t kCompressedPrimitiveLimit = 0x80000000u;

// A BLAS without a compressed form (RenderScene::blasCompressedRoots): its binary nodes are walked.
constexpr uint32_t kNoCompressedRoot = 0xffffffffu;

}  // namespace pt
