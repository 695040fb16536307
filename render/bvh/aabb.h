#pragma once
#include "render/math/vec.h"

namespace pt {

// Axis-aligned box; the default is empty (min > max) so that grow() starts it.
struct Aabb {
    Vec3 lo{kInf, kInf, kInf};
    Vec3 hi{-kInf, -kInf, -kInf};

    PT_HD void grow(Vec3 p) {
        lo = vmin(lo, p);
        hi = vmax(hi, p);
    }
    PT_HD void grow(const Aabb& b) {
        lo = vmin(lo, b.lo);
        hi = vmax(hi, b.hi);
    }
    PT_HD bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    PT_HD Vec3 center() const { return (lo + hi) * 0.5f; }
    PT_HD Vec3 extent() const { return hi - lo; }
    PT_HD float surfaceArea() const {
        if (empty()) return 0.0f;
        const Vec3 e = extent();
        return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
    }
};

}  // namespace pt
