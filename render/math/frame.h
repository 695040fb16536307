#pragma once
#include "render/math/vec.h"

namespace pt {

// Orthonormal frame around a unit normal; local z is the normal. Built without branches on
// the normal's direction except its sign (Duff et al., "Building an Orthonormal Basis,
// Revisited", JCGT 2017).
struct Frame {
    Vec3 tangent, bitangent, normal;

    PT_HD static Frame fromNormal(Vec3 n) {
        const float sign = copysignf(1.0f, n.z);
        const float a = -1.0f / (sign + n.z);
        const float b = n.x * n.y * a;
        Frame f;
        f.tangent = {1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x};
        f.bitangent = {b, sign + n.y * n.y * a, -n.y};
        f.normal = n;
        return f;
    }
    PT_HD Vec3 toLocal(Vec3 v) const { return {dot(v, tangent), dot(v, bitangent), dot(v, normal)}; }
    PT_HD Vec3 toWorld(Vec3 v) const { return tangent * v.x + bitangent * v.y + normal * v.z; }
};

}  // namespace pt
