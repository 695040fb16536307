#pragma once
// The stack walk shared by BLAS and TLAS traversal: a ray prepared once per space
// (TraversalRay), the robust slab test, and a non-recursive, near-child-first loop over the
// canonical BvhNode layout that hands leaves to a caller-supplied functor.
#include <cassert>
#include <cstdint>

#include "render/bvh/triangle_intersect.h"
#include "render/kernel/bvh_node.h"

namespace pt {

// Entries of the fixed traversal stack. Builders guarantee that no leaf lies deeper than
// this (root at depth 0), so the stack never overflows.
constexpr uint32_t kBvhStackSize = 64;

// Work counters for the BVH-cost AOV and benchmarks; optional everywhere (nullptr: off).
struct TraversalStats {
    uint32_t nodesVisited = 0;      // nodes whose contents were examined (interior or leaf)
    uint32_t primitivesTested = 0;  // primitive intersection tests
};
static_assert(sizeof(TraversalStats) == 8, "TraversalStats: 8 bytes (an AOV buffer element)");

// How a walk counts its work. The choice is made once per query (traversal.h), not per node:
// the walk is compiled once with TraversalCounter and once with NoTraversalCount, whose calls
// vanish, so rays nobody counts run exactly the code they ran before counters existed.
// stats() hands the choice to a walk compiled apart (wide_walk_simd.h), as a pointer.
struct NoTraversalCount {
    PT_HD void node() const {}
    PT_HD void primitive() const {}
    PT_HD TraversalStats* stats() const { return nullptr; }
};
struct TraversalCounter {
    TraversalStats* counts;  // never null
    PT_HD void node() const { ++counts->nodesVisited; }
    PT_HD void primitive() const { ++counts->primitivesTested; }
    PT_HD TraversalStats* stats() const { return counts; }
};

// A Count for a walk that shares its call site with other work: the megakernel's fused step
// (intersectScene), where a warp's threads reach the walk from shading as well. There the
// compressed walk does not postpone leaves (compressed_wide_walk.h): it cost the megakernel 5%
// where it gave the ray-tracing kernels up to 36%. (The rare walks a fused step makes through
// intersectClosest, past alpha-tested blockers of a shadow ray, still postpone.)
template <class Count>
struct SharedSiteCount : Count {};
template <class Count>
constexpr bool kSharedSite = false;
template <class Count>
constexpr bool kSharedSite<SharedSiteCount<Count>> = true;

// Whether fewer than a fifth of the warp's active threads have `mine` set: a vote, so every
// active thread must reach it (false on the host). A walk's thread with leaf work to do while
// the rest of its warp walks on postpones it: it would leave them idle (Ylitie, Karras and
// Laine 2017, section 4).
PT_HD bool rareInWarp(bool mine) {
#if defined(__CUDA_ARCH__)
    const uint32_t active = __activemask();
    return __popc(__ballot_sync(active, mine)) * 5 < __popc(active);
#else
    (void)mine;
    return false;
#endif
}

// min/max for inputs that are never NaN, where the comparison and fminf/fmaxf agree. On x86
// the comparison is one minss/maxss, where fminf's NaN rules cost extra instructions; on the
// GPU fminf/fmaxf are one FMNMX, where ptxas keeps the comparison's NaN rule with a compare
// and a select, two (they were a fifth of the ray kernel's instructions, ncu: FSETP 10.8%,
// FSEL 10.7%; H200, camera rays of a 1M-triangle sphere). With FMNMX, and the compressed node
// test's permutes and hit bits (compressed_wide_walk.h), that launch went from 413M to 358M
// instructions, and bench's rays at 1080p (Mrays/s, camera / diffuse / shadow, two runs) from
// 3188-3197 / 1801-1817 / 1425-1439 to 3483-3524 / 2045-2048 / 1594-1598 on the compressed
// walk, from 2841-2874 / 1616-1617 / 1038-1041 to 2899-2955 / 1672 / 1052-1057 on this one.
PT_HD float minFast(float a, float b) {
#if defined(__CUDA_ARCH__)
    return fminf(a, b);
#else
    return a < b ? a : b;
#endif
}
PT_HD float maxFast(float a, float b) {
#if defined(__CUDA_ARCH__)
    return fmaxf(a, b);
#else
    return a > b ? a : b;
#endif
}

// A ray in one space (world for the TLAS, object space of one instance for a BLAS), with what
// the slab and triangle tests precompute.
//
// Zero axes: a direction component below kMinDirection in magnitude (zero, or NaN) would make
// 1/d infinite, and (plane - o) * inf is NaN for an origin on a box face. Such an axis gets the
// finite inverse +-1e30 instead, and the slab test measures its planes from the origin moved
// out by a pad (slabOriginLo = o + pad for the lower planes, slabOriginHi = o - pad for the
// upper), so that an origin inside the slab or on either face gives t in (-huge, +huge), never
// NaN, and an origin outside it by more than the pad gives only huge or negative t: the box
// test stays inclusive on faces, as an axis-aligned ray needs, and at worst admits a box the
// ray misses at t ~ 1e24, which a finite tMax culls. On every other axis the pad is zero and
// both origins are the origin, so ordinary rays compute exactly what a plain slab test does.
// This keeps the box test one branch-free sequence: a separate zero-axis test at every call
// site had doubled the walk's code (2,925 -> 1,566 SASS instructions of bvh_walk.h in the
// textured megakernel without it), and its removal sped the Cornell-box megakernel up 12%
// (73.4 -> 82.5 spp/s at 1080p on an H100). Primitive tests use
// the unmodified direction, so box tests stay conservative for the very ray the primitives
// see, in world and object space alike.
struct TraversalRay {
    WatertightRay watertight;  // origin and shear of the triangle test
    Vec3 direction;
    Vec3 invDirection;  // finite; nonzero but for an infinite direction component
    Vec3 slabOriginLo;  // where lower box planes are measured from (see above)
    Vec3 slabOriginHi;  // where upper box planes are measured from
};
static_assert(sizeof(TraversalRay) == 84, "TraversalRay: 84 bytes of registers per level");

constexpr float kMinDirection = 1e-30f;
// The zero-axis pad, relative to the origin's magnitude (at least 1): 8 ulps, so o +- pad
// differs from o, and pad * 1e30 is far beyond any distance in a scene.
constexpr float kZeroAxisPad = 1.0f / (1 << 20);

PT_HD TraversalRay makeTraversalRay(const Vec3& origin, const Vec3& direction) {
    TraversalRay r;
    r.watertight = makeWatertightRay(origin, direction);
    r.direction = direction;
    for (int a = 0; a < 3; ++a) {
        // Selects, not branches (makeWatertightRay says why); maxf, not fmaxf, which GCC calls
        // in libm. Both give 1 for a NaN origin.
        const bool zero = !(fabsf(direction[a]) >= kMinDirection);
        r.invDirection[a] = 1.0f / (zero ? copysignf(kMinDirection, direction[a]) : direction[a]);
        const float pad = maxf(fabsf(origin[a]), 1.0f) * kZeroAxisPad;
        r.slabOriginLo[a] = origin[a] + (zero ? pad : 0.0f);
        r.slabOriginHi[a] = origin[a] - (zero ? pad : 0.0f);
    }
    return r;
}

// 1 + 2 gamma(3), gamma(n) = n u / (1 - n u), u = 2^-24: the factor by which the exit
// distance is enlarged so that rounding in the slab test never culls a box the ray enters
// (Ize, "Robust BVH Ray Traversal", JCGT 2(2), 2013; pbrt-v3 section 3.9.2).
constexpr float kSlabExitScale = 1.0f + 2.0f * gammaBound(3);

// Slab test against [0, tMax]; on a hit, tEntry is where the ray enters the box (>= 0). Never
// produces NaN (finite, nonzero inverse direction); an empty box (lo > hi, e.g. the root of an
// empty BVH) always misses.
PT_HD bool intersectBox(const TraversalRay& ray, Vec3 lo, Vec3 hi, float tMax, float& tEntry) {
    const Vec3 oLo = ray.slabOriginLo, oHi = ray.slabOriginHi, inv = ray.invDirection;
    const float x0 = (lo.x - oLo.x) * inv.x, x1 = (hi.x - oHi.x) * inv.x;
    const float y0 = (lo.y - oLo.y) * inv.y, y1 = (hi.y - oHi.y) * inv.y;
    const float z0 = (lo.z - oLo.z) * inv.z, z1 = (hi.z - oHi.z) * inv.z;
    const float tNear = maxFast(maxFast(minFast(x0, x1), minFast(y0, y1)), maxFast(minFast(z0, z1), 0.0f));
    const float tFar = minFast(maxFast(x0, x1), minFast(maxFast(y0, y1), maxFast(z0, z1))) * kSlabExitScale;
    tEntry = tNear;
    // tMax gets the same slack as the exit: a hit an ulp nearer than the current closest one
    // must not be culled by the rounding of tNear, or the closest hit would depend on the
    // order subtrees are visited in.
    return tNear <= minFast(tFar, tMax * kSlabExitScale);
}

// Walks the BVH `nodes` (root at index 0), nearest child first. `leaf(first, count, tMax)`
// tests a leaf's primitives, lowers tMax on a closer hit and returns whether it hit; with
// anyHit the walk stops at the first hit. Subtrees whose entry distance is beyond the current
// tMax when popped are skipped. `count` is NoTraversalCount or TraversalCounter. anyHit is a
// run-time argument so that one walk serves closest-hit and shadow rays alike (the megakernel
// traces both through one call site; path_tracer.h); constant arguments fold away when inlined.
template <class LeafFn, class Count>
PT_HD bool walkBvh(const BvhNode* nodes, const TraversalRay& ray, float& tMax, LeafFn& leaf, Count count,
                   bool anyHit) {
    uint32_t stackNode[kBvhStackSize];
    float stackEntry[kBvhStackSize];
    uint32_t size = 0;
    float entry = 0.0f;
    if (!intersectBox(ray, nodes[0].lo, nodes[0].hi, tMax, entry)) return false;
    bool found = false;
    uint32_t current = 0;
    for (;;) {
        const BvhNode& node = nodes[current];
        count.node();
        if (node.isLeaf()) {
            if (leaf(node.leftOrFirst, node.count, tMax)) {
                found = true;
                if (anyHit) return true;
            }
        } else {
            const uint32_t left = node.leftOrFirst;
            float tLeft = 0.0f, tRight = 0.0f;
            const bool hitLeft = intersectBox(ray, nodes[left].lo, nodes[left].hi, tMax, tLeft);
            const bool hitRight = intersectBox(ray, nodes[left + 1].lo, nodes[left + 1].hi, tMax, tRight);
            if (hitLeft && hitRight) {
                assert(size < kBvhStackSize && "BVH deeper than the traversal stack");
                const bool leftFirst = tLeft <= tRight;
                stackNode[size] = leftFirst ? left + 1 : left;
                stackEntry[size++] = leftFirst ? tRight : tLeft;
                current = leftFirst ? left : left + 1;
                continue;
            }
            if (hitLeft || hitRight) {
                current = hitLeft ? left : left + 1;
                continue;
            }
        }
        do {
            if (size == 0) return found;
            --size;
        } while (stackEntry[size] > tMax * kSlabExitScale);
        current = stackNode[size];
    }
}

}  // namespace pt
