#pragma once
#include "render/math/float_error.h"

namespace pt {

struct Ray {
    Vec3 origin;
    Vec3 direction;  // not necessarily unit length in object space
    float tMax = kInf;
};

// Moves surface point `p` off its surface along the unit geometric normal `n` (to the side of
// n, or of -n), far enough that rounding cannot put the new origin back on or behind the
// surface, and no farther. `pError` bounds, per axis, how far the float `p` may lie from the
// true surface point, including every rounding that tracing a ray from the new origin will add
// (render/bvh/instance_space.h computes it for surface points of instances). The move must
// exceed the extent of that error box along n (pbrt-v4 section 6.8.6, OffsetRayOrigin). Moving
// by that extent rounds each coordinate to the nearest float, which may lose up to half an ulp
// of it, at most the error box again (its bound includes the rounding of p itself): where
// that loss left the move short, the point moves twice as far. The offset thus scales with the
// magnitudes that caused the error: a box 1e5 from the origin moves by one or two of its ulps
// (1/128 each), a box scaled by 1e-4 by a few of its own. Unlike rounding every coordinate
// away from p (pbrt), a normal component of 1e-8 costs no ulp of its axis.
PT_HD Vec3 offsetRayOrigin(Vec3 p, Vec3 pError, Vec3 n, bool towardsNormal) {
    const float distance = dot(vabs(n), pError);
    const Vec3 away = towardsNormal ? n : -n;
    const Vec3 moved = p + away * distance;
    // moved - p is exact (Sterbenz) but where p is tiny; the slack covers the dot product.
    if (dot(away, moved - p) >= distance * (1.0f + gammaBound(4))) return moved;
    return p + away * (distance * (2.0f + gammaBound(4)));
}

}  // namespace pt
