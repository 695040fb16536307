#pragma once
// World-space box of an instance for the TLAS: its BLAS root box through objectToWorld, padded.
// Shared by the CPU scene compiler and the CUDA backend's TLAS input, so both backends pad alike
// and a TLAS built on either side bounds the same geometry with the same boxes, bit for bit
// (with -ffp-contract=off and nvcc's -fmad=false, both compilers round every step alike).
#include "render/bvh/aabb.h"
#include "render/kernel/bvh_node.h"
#include "render/math/affine.h"

namespace pt {

// `blasRoot` is node 0 of the instance's BLAS (object space); the result is in world space.
PT_HD Aabb instanceBounds(const BvhNode& blasRoot, const Affine3& objectToWorld) {
    Aabb box;
    for (int c = 0; c < 8; ++c) {
        const Vec3 corner{c & 1 ? blasRoot.hi.x : blasRoot.lo.x, c & 2 ? blasRoot.hi.y : blasRoot.lo.y,
                          c & 4 ? blasRoot.hi.z : blasRoot.lo.z};
        box.grow(objectToWorld.transformPoint(corner));
    }
    // The corners are rounded once more by the transform; pad by a few ulps of the largest
    // coordinate so the box never ends up inside the geometry it bounds.
    const float pad = 4.0f * 1.2e-7f * maxf(maxComponent(vabs(box.lo)), maxComponent(vabs(box.hi)));
    box.lo -= Vec3(pad);
    box.hi += Vec3(pad);
    return box;
}

}  // namespace pt
