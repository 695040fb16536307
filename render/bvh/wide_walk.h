#pragma once
// The CPU's walk of a 4-wide BVH (wide_bvh.h; issue 21): one SSE slab test takes a node's four
// child boxes together, the children hit are visited nearest first, and leaves go to the same
// leaf functor the binary walk (bvh_walk.h) calls, so the primitives tested and the hits found
// are the binary walk's. Each lane computes exactly what intersectBox computes for that box
// (the same zero-axis origins, the same exit scale, min/max with the same operand order), so
// the box test is as conservative as the binary one and hits stay exact. Host only: SSE2 is
// part of every x86-64 CPU, so no dispatch is needed.
#if defined(__CUDACC__)
#error "wide_walk.h is CPU code: CUDA translation units walk the binary BVH"
#endif
#include <emmintrin.h>

#include <cstdint>

#include "render/bvh/bvh_walk.h"
#include "render/kernel/wide_bvh_node.h"

namespace pt {

// Entries on the wide walk's stack: a node (count 0) or a leaf, with where the ray enters it.
// Each node pushes at most three entries beyond the one it replaces, and no leaf lies deeper
// than kBvhStackSize binary levels, so 3 * kBvhStackSize + 4 entries always suffice.
constexpr uint32_t kWideStackSize = 3 * kBvhStackSize + 4;

struct WideSlabRay {
    __m128 oLoX, oLoY, oLoZ, oHiX, oHiY, oHiZ, invX, invY, invZ;
};

inline WideSlabRay wideSlabRay(const TraversalRay& ray) {
    return {
        _mm_set1_ps(ray.slabOriginLo.x), _mm_set1_ps(ray.slabOriginLo.y), _mm_set1_ps(ray.slabOriginLo.z),
        _mm_set1_ps(ray.slabOriginHi.x), _mm_set1_ps(ray.slabOriginHi.y), _mm_set1_ps(ray.slabOriginHi.z),
        _mm_set1_ps(ray.invDirection.x), _mm_set1_ps(ray.invDirection.y), _mm_set1_ps(ray.invDirection.z)};
}

// intersectBox on four boxes: the lanes that hit, as a 4-bit mask, and their entry distances.
inline int intersectWideBoxes(const WideSlabRay& r, const WideBvhNode& n, float tMax, __m128& tEntry) {
    const __m128 x0 = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(n.loX), r.oLoX), r.invX);
    const __m128 x1 = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(n.hiX), r.oHiX), r.invX);
    const __m128 y0 = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(n.loY), r.oLoY), r.invY);
    const __m128 y1 = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(n.hiY), r.oHiY), r.invY);
    const __m128 z0 = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(n.loZ), r.oLoZ), r.invZ);
    const __m128 z1 = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(n.hiZ), r.oHiZ), r.invZ);
    // _mm_min_ps(a, b) is a < b ? a : b and _mm_max_ps(a, b) a > b ? a : b: minFast and maxFast.
    const __m128 tNear = _mm_max_ps(_mm_max_ps(_mm_min_ps(x0, x1), _mm_min_ps(y0, y1)),
                                    _mm_max_ps(_mm_min_ps(z0, z1), _mm_setzero_ps()));
    const __m128 tFar =
        _mm_mul_ps(_mm_min_ps(_mm_max_ps(x0, x1), _mm_min_ps(_mm_max_ps(y0, y1), _mm_max_ps(z0, z1))),
                   _mm_set1_ps(kSlabExitScale));
    const __m128 limit = _mm_min_ps(tFar, _mm_set1_ps(tMax * kSlabExitScale));
    // Unused slots (count kEmpty) never hit, whatever their boxes give.
    const __m128i unused = _mm_cmpeq_epi32(_mm_load_si128(reinterpret_cast<const __m128i*>(n.count)),
                                           _mm_set1_epi32(int(WideBvhNode::kEmpty)));
    tEntry = tNear;
    return _mm_movemask_ps(_mm_andnot_ps(_mm_castsi128_ps(unused), _mm_cmple_ps(tNear, limit)));
}

// An entry of the wide walk: a node (count 0) or a leaf, with where the ray enters it.
struct WideWalkEntry {
    uint32_t child, count;
    float entry;
};

// walkBvh over the wide tree `nodes` from node `root`: `leaf(first, count, tMax)` as there. The
// nearest child hit is taken next without a trip through the stack (a node whose ray hits one
// child only pushes nothing); the order of visits is the binary walk's nearest-first order.
template <class LeafFn, class Count>
bool walkWideBvh(const WideBvhNode* nodes, uint32_t root, const TraversalRay& ray, float& tMax, LeafFn& leaf,
                 Count count, bool anyHit) {
    const WideSlabRay slab = wideSlabRay(ray);
    WideWalkEntry stack[kWideStackSize];
    uint32_t size = 0;
    WideWalkEntry current{root, 0, 0.0f};
    bool found = false;
    for (;;) {
        count.node();
        if (current.count > 0) {
            if (leaf(current.child, current.count, tMax)) {
                found = true;
                if (anyHit) return true;
            }
        } else {
            const WideBvhNode& node = nodes[current.child];
            __m128 entries;
            int hits = intersectWideBoxes(slab, node, tMax, entries);
            if (hits != 0) {
                alignas(16) float entry[WideBvhNode::kWidth];
                _mm_store_ps(entry, entries);
                // The hit children farthest first (an insertion sort of at most four): all but
                // the nearest go on the stack, so the nearest of them is popped next.
                uint32_t order[WideBvhNode::kWidth], n = 0;
                for (; hits != 0; hits &= hits - 1) {
                    const uint32_t slot = uint32_t(__builtin_ctz(unsigned(hits)));
                    uint32_t at = n++;
                    while (at > 0 && entry[order[at - 1]] < entry[slot]) {
                        order[at] = order[at - 1];
                        --at;
                    }
                    order[at] = slot;
                }
                assert(size + n - 1 <= kWideStackSize && "BVH deeper than the wide traversal stack");
                for (uint32_t i = 0; i + 1 < n; ++i) {
                    const uint32_t slot = order[i];
                    stack[size++] = {node.child[slot], node.count[slot], entry[slot]};
                }
                const uint32_t nearest = order[n - 1];
                current = {node.child[nearest], node.count[nearest], entry[nearest]};
                continue;
            }
        }
        // Next: the nearest entry left that the ray can still reach before tMax.
        do {
            if (size == 0) return found;
            current = stack[--size];
        } while (current.entry > tMax * kSlabExitScale);
    }
}

}  // namespace pt
