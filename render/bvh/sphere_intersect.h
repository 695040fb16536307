#pragma once
// Analytic ray/sphere intersection with the precision fixes of Haines, Guenther and
// Akenine-Moeller, "Precision Improvements for Ray/Sphere Intersection", Ray Tracing Gems
// ch. 7 (2019):
//  - the discriminant is computed from the distance of the centre to the ray's line,
//    a * (r^2 - |f - (f.d / d.d) d|^2), instead of b^2 - ac, which cancels catastrophically
//    when the sphere is small relative to its distance;
//  - the root nearer to zero is c / q rather than (-b +- sqrt(disc)) / a, which cancels
//    when the two roots differ greatly in magnitude (Numerical Recipes' q trick).
// Coordinates are taken relative to the centre (f = origin - centre), which is exact when the
// ray starts near a sphere far from the world origin.
#include "render/math/ray.h"

namespace pt {

// Nearest t in (0, tMax) where origin + t * direction meets the sphere (xyz centre, w
// radius); from inside the sphere that is the far root. The direction need not be unit.
PT_HD bool intersectSphere(Vec3 origin, Vec3 direction, float tMax, Vec4 sphere, float& t) {
    const Vec3 f = origin - sphere.xyz();
    const float radius2 = sphere.w * sphere.w;
    const float a = dot(direction, direction);
    if (!(a > 0.0f)) return false;
    const float b = -dot(f, direction);      // roots are (b +- sqrt(disc)) / a
    const Vec3 l = f + (b / a) * direction;  // centre-to-line offset, perpendicular to the ray
    const float disc = a * (radius2 - dot(l, l));
    if (!(disc >= 0.0f)) return false;
    const float c = dot(f, f) - radius2;
    const float q = b + copysignf(sqrtf(disc), b);
    if (q == 0.0f) return false;  // grazing at t = 0
    const float r0 = c / q, r1 = q / a;
    const float tNear = r0 < r1 ? r0 : r1;
    const float tFar = r0 < r1 ? r1 : r0;
    if (tNear > 0.0f && tNear < tMax) {
        t = tNear;
        return true;
    }
    if (tFar > 0.0f && tFar < tMax) {
        t = tFar;
        return true;
    }
    return false;
}

PT_HD bool intersectSphere(const Ray& ray, Vec4 sphere, float& t) {
    return intersectSphere(ray.origin, ray.direction, ray.tMax, sphere, t);
}

}  // namespace pt
