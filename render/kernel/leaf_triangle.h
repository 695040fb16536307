#pragma once
// A triangle of a compressed 8-wide BVH's leaves (render/kernel/compressed_wide_node.h) with its
// three corners copied beside it, in the order the leaves list their primitives, so that the
// CUDA walk tests it from three 16-byte loads where the index path takes four dependent ones
// (the primitive's entry, its vertex indices, then its corners). The corners are the positions'
// own floats, so the watertight test gives bit for bit the hits of the index path. Ylitie,
// Karras and Laine 2017 store their leaves' triangles the same way (section 4).
#include <cstdint>

#include "render/math/vec.h"

namespace pt {

struct alignas(16) LeafTriangle {
    Vec3 p0;
    uint32_t primitive;  // mesh-local, as the BLAS's primitive-index lists hold it
    Vec3 p1;
    uint32_t unused1;
    Vec3 p2;
    uint32_t unused2;
};
static_assert(sizeof(LeafTriangle) == 48, "LeafTriangle: three 16-byte loads");

PT_HD LeafTriangle makeLeafTriangle(Vec3 p0, Vec3 p1, Vec3 p2, uint32_t primitive) {
    return {p0, primitive, p1, 0u, p2, 0u};
}

// Entry `i` of `triangles`, through the read-only path on the GPU.
PT_HD LeafTriangle loadLeafTriangle(const LeafTriangle* triangles, uint32_t i) {
#if defined(__CUDA_ARCH__)
    const float4* from = reinterpret_cast<const float4*>(triangles + i);
    const float4 a = __ldg(from), b = __ldg(from + 1), c = __ldg(from + 2);
    return {Vec3(a.x, a.y, a.z), __float_as_uint(a.w), Vec3(b.x, b.y, b.z), 0u, Vec3(c.x, c.y, c.z), 0u};
#else
    return triangles[i];
#endif
}

}  // namespace pt
