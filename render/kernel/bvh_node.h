#pragma once
// The canonical BVH node every builder writes and the shared traversal reads (STYLE.md rule
// 8). 32 bytes: two per 64-byte cache line.
#include <cstdint>

#include "render/math/vec.h"

namespace pt {

struct BvhNode {
    Vec3 lo;
    uint32_t leftOrFirst;  // interior: index of the left child (right = left + 1);
                           // leaf: first entry in the BVH's primitive-index list
    Vec3 hi;
    uint32_t count;  // 0: interior node; > 0: leaf with this many primitives

    PT_HD bool isLeaf() const { return count > 0; }
};
static_assert(sizeof(BvhNode) == 32, "BvhNode must stay 32 bytes");

}  // namespace pt
