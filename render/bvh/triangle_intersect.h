#pragma once
// Watertight ray/triangle intersection: Woop, Benthin and Wald, "Watertight Ray/Triangle
// Intersection", JCGT 2(1), 2013. The triangle is translated to the ray origin and sheared so
// that the ray runs along +z; the 2D edge functions of two triangles sharing an edge are then
// computed from the same operands in the same order, so their signs agree exactly and no ray
// slips between them (see edgeFunction). Two-sided.
#include "render/math/ray.h"

namespace pt {

// Per-ray constants of the test: kz is the dimension where |direction| is largest, kx and ky
// the other two (swapped when direction[kz] < 0 to keep the winding), s the shear.
struct WatertightRay {
    Vec3 origin;
    int kx, ky, kz;
    float sx, sy, sz;
};

// Made once per ray and instance without branches on the direction, whose largest axis is a
// coin toss for diffuse bounces: with makeTraversalRay's slab set-up made the same way, the 1M
// sphere's diffuse rays ran 2.4% faster on one CPU thread (makeTraversalRay had been 7.4% of
// their samples under perf). By reference: passed by value, the vectors were spilled and
// reloaded across two stores, a store-forwarding stall (a third of makeTraversalRay's samples;
// with that and the selects below, a 10k-triangle sphere's diffuse rays ran 5.5% faster).
PT_HD WatertightRay makeWatertightRay(const Vec3& origin, const Vec3& direction) {
    const Vec3 a = vabs(direction);
    const bool xOverY = a.x > a.y, xOverZ = a.x > a.z, yOverZ = a.y > a.z;
    // maxDimension(a), as integer arithmetic on the comparisons.
    const int kz = 2 - 2 * int(xOverY & xOverZ) - int(!xOverY & yOverZ);
    // The next axes after kz in cyclic order, read from two-bit fields (0 -> 1, 2; 1 -> 2, 0;
    // 2 -> 0, 1) and swapped by masks for a negative direction[kz]: written as selects, GCC
    // made both jumps, the second mispredicted for half the diffuse bounces.
    const int next = (0x09 >> (2 * kz)) & 3, afterNext = (0x12 >> (2 * kz)) & 3;
    const float dz = componentAt(direction, kz);
    const int swap = (next ^ afterNext) & -int(dz < 0.0f);
    const int kx = next ^ swap, ky = afterNext ^ swap;
    const float sz = 1.0f / dz;
    return {origin, kx, ky, kz, componentAt(direction, kx) * sz, componentAt(direction, ky) * sz, sz};
}

// The 2D edge function a*b - c*d with each product rounded to float on its own, so that
// edge(a, b, c, d) == -edge(c, d, a, b) bit for bit, which is what makes the test watertight.
// Both backends compute it alike (no FMA: -ffp-contract=off on the host, __fmul_rn on the
// device), so CPU and GPU hits agree to the last bit; exact zeros are redone in double by
// the caller, as the paper does.
PT_HD float edgeFunction(float a, float b, float c, float d) {
#if defined(__CUDA_ARCH__)
    return __fsub_rn(__fmul_rn(a, b), __fmul_rn(c, d));
#else
    const float ab = a * b, cd = c * d;
    return ab - cd;
#endif
}

// Closest-hit test against (0, tMax). On a hit, t is the ray parameter and u, v are the
// barycentric weights of p1 and p2 (p0 weighs 1 - u - v).
PT_HD bool intersectTriangle(const WatertightRay& ray, float tMax, Vec3 p0, Vec3 p1, Vec3 p2, float& t,
                             float& u, float& v) {
    const Vec3 a = p0 - ray.origin, b = p1 - ray.origin, c = p2 - ray.origin;
    const float ax = a[ray.kx] - ray.sx * a[ray.kz], ay = a[ray.ky] - ray.sy * a[ray.kz];
    const float bx = b[ray.kx] - ray.sx * b[ray.kz], by = b[ray.ky] - ray.sy * b[ray.kz];
    const float cx = c[ray.kx] - ray.sx * c[ray.kz], cy = c[ray.ky] - ray.sy * c[ray.kz];
    float e0 = edgeFunction(cx, by, cy, bx);  // weight of p0
    float e1 = edgeFunction(ax, cy, ay, cx);  // weight of p1
    float e2 = edgeFunction(bx, ay, by, ax);  // weight of p2
    if (e0 == 0.0f || e1 == 0.0f || e2 == 0.0f) {
        // Products of floats are exact in double: the sign of each edge is now exact.
        e0 = float(double(cx) * double(by) - double(cy) * double(bx));
        e1 = float(double(ax) * double(cy) - double(ay) * double(cx));
        e2 = float(double(bx) * double(ay) - double(by) * double(ax));
    }
    if ((e0 < 0.0f || e1 < 0.0f || e2 < 0.0f) && (e0 > 0.0f || e1 > 0.0f || e2 > 0.0f)) return false;
    const float det = e0 + e1 + e2;
    if (det == 0.0f) return false;  // the ray lies in the triangle's plane
    const float az = ray.sz * a[ray.kz], bz = ray.sz * b[ray.kz], cz = ray.sz * c[ray.kz];
    const float scaledT = e0 * az + e1 * bz + e2 * cz;
    // Range test on t * |det| first (no division for misses); written so that NaN fails. It is
    // conservative (a relative slack of 2^-20) because tMax * |det| rounds: an exact test here
    // could reject a hit an ulp nearer than tMax, making the closest hit depend on the order
    // primitives are visited in. The exact test on tHit below decides.
    const float signedT = det < 0.0f ? -scaledT : scaledT;
    if (!(signedT > 0.0f && signedT <= tMax * fabsf(det) * (1.0f + 0x1p-20f))) return false;
    const float invDet = 1.0f / det;
    const float tHit = scaledT * invDet;
    if (!(tHit > 0.0f && tHit < tMax)) return false;  // rounding of the division
    t = tHit;
    u = e1 * invDet;
    v = e2 * invDet;
    return true;
}

// Convenience form for a single ray; traversal precomputes the WatertightRay once per ray.
PT_HD bool intersectTriangle(const Ray& ray, Vec3 p0, Vec3 p1, Vec3 p2, float& t, float& u, float& v) {
    return intersectTriangle(makeWatertightRay(ray.origin, ray.direction), ray.tMax, p0, p1, p2, t, u, v);
}

}  // namespace pt
