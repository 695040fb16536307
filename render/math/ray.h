#pragma once
#include "render/math/vec.h"

namespace pt {

struct Ray {
    Vec3 origin;
    Vec3 direction;  // not necessarily unit length in object space
    float tMax = kInf;
};

// Moves a hit point off its surface along the geometric normal, far enough that float
// rounding cannot put the new origin back behind the surface, and no farther. The offset
// grows with the magnitude of the coordinates, so a scene 1e5 units from the origin is as
// safe as one at the origin (Waechter and Binder, "A Fast and Robust Method for Avoiding
// Self-Intersection", Ray Tracing Gems ch. 6).
PT_HD Vec3 offsetRayOrigin(Vec3 p, Vec3 geometricNormal, bool towardsNormal) {
    constexpr float kOrigin = 1.0f / 32.0f;
    constexpr float kFloatScale = 1.0f / 65536.0f;
    constexpr float kIntScale = 256.0f;
    const Vec3 n = towardsNormal ? geometricNormal : -geometricNormal;
    const int ofi[3] = {int(kIntScale * n.x), int(kIntScale * n.y), int(kIntScale * n.z)};
    Vec3 pi;
    for (int i = 0; i < 3; ++i) {
        const float v = p[i];
        const float moved = intAsFloat(floatAsInt(v) + ((v < 0) ? -ofi[i] : ofi[i]));
        pi[i] = fabsf(v) < kOrigin ? v + kFloatScale * n[i] : moved;
    }
    return pi;
}

}  // namespace pt
