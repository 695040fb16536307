#pragma once
// Object-space boxes of BLAS primitives, the builders' input: shared by the CPU scene compiler,
// the GPU box kernels and the benchmark, so every side builds from the same boxes, bit for bit.
#include "render/bvh/aabb.h"

namespace pt {

PT_HD Aabb triangleBounds(Vec3 p0, Vec3 p1, Vec3 p2) {
    Aabb box;
    box.grow(p0);
    box.grow(p1);
    box.grow(p2);
    return box;
}

// xyz = centre, w = radius.
PT_HD Aabb sphereBounds(Vec4 sphere) {
    Aabb box;
    box.grow(sphere.xyz() - Vec3(sphere.w));
    box.grow(sphere.xyz() + Vec3(sphere.w));
    return box;
}

}  // namespace pt
