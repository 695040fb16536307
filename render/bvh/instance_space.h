#pragma once
// Points across an instance transform, and the rounding error that a ray leaving a surface
// must beat.
//
// World to object: the linear part of worldToObject applied to (p - translation), where the
// translation is objectToWorld's. Subtracting first keeps the precision of an instance placed far
// from the world origin: at 1e5 floats are 1/128 apart, and worldToObject * p + (-R^-1 t) rounds
// both terms there before they cancel (an error of ~1/128 in object space, more than the 0.005
// between the Cornell box's light and its ceiling), whereas p - t is exact while p and t are
// within a factor of two of each other (Sterbenz) and otherwise off by half an ulp of the
// (object-sized) difference.
//
// Object to world: objectToWorld.transformPoint, whose only large error is the final rounding
// to the world coordinate's ulp.
#include "render/kernel/render_scene.h"
#include "render/math/affine.h"
#include "render/math/float_error.h"

namespace pt {

// World point `p` in the object space of `inst`.
PT_HD Vec3 objectSpacePoint(const RenderInstance& inst, Vec3 p) {
    return inst.worldToObject.transformVector(p - inst.objectToWorld.translation());
}

// Roundings between the exact surface point and what a ray spawned from its float value sees
// in object space, each bounded by gamma(n) of the same magnitudes (Higham's worst cases). Per
// axis: interpolating the point from the vertices (4), objectToWorld's linear part (4), bringing
// the origin back (p - t, then worldToObject: 4), worldToObject being a rounded inverse
// (cofactors times 1 / det: 8). Then the intersection test's own error in t, which mixes the
// axes (the watertight test shears them into one another; a sphere's dot products sum them): a
// ray from a point exactly on the plane y = 0 of an axis-aligned floor, where the per-axis
// bound along y is zero, still met the floor again at t ~ 1e-8 in 4% of grazing directions.
// That term is relative to the largest coordinate (12; cf. pbrt-v4 section 6.8.4). Typical
// errors are far smaller (spawn_ray_test finds no self-intersection with both set to 1): slack for
// the worst case, not a fudge factor.
constexpr int kSpawnRoundings = 20;
constexpr int kIntersectionRoundings = 12;

// A bound, per axis, on the error of any point of a primitive of `inst` whose object-space
// vertices (or centre and radius) are at most `objectMagnitude` in size, as computed from
// object space with objectToWorld.transformPoint, including the error of taking a ray origin
// there back into object space and intersecting it there. offsetRayOrigin() moves a spawned
// origin past it.
PT_HD Vec3 surfacePointError(const RenderInstance& inst, Vec3 objectMagnitude) {
    const Vec3 local = inst.objectToWorld.transformMagnitude(objectMagnitude);  // bounds |p - t|
    const Vec3 size = objectMagnitude + inst.worldToObject.transformMagnitude(local);
    const Vec3 objectError =
        size * gammaBound(kSpawnRoundings) + Vec3(maxComponent(size)) * gammaBound(kIntersectionRoundings);
    // The world coordinate itself (at most |t| + local) is rounded once, by transformPoint.
    const Vec3 world = vabs(inst.objectToWorld.translation()) + local;
    const Vec3 error = inst.objectToWorld.transformMagnitude(objectError) + world * gammaBound(1);
    if (!inst.tracedInWorldSpace) return error;
    // Traced as world-space copies (merged_geometry.h): the copies' vertices are rounded world
    // coordinates, and the intersection test's error is relative to the world magnitude.
    return error + world * gammaBound(kSpawnRoundings) +
           Vec3(maxComponent(world)) * gammaBound(kIntersectionRoundings);
}

// The same for a sphere (xyz centre, w radius, in object space).
PT_HD Vec3 spherePointError(const RenderInstance& inst, Vec4 sphere) {
    return surfacePointError(inst, vabs(sphere.xyz()) + Vec3(sphere.w));
}

// Barycentrics `b` (of p0, p1, p2) moved, where needed, to lie at least `margin` (a world
// distance) inside the triangle whose world edges from p0 are e1 (to p1) and e2 (to p2); a
// triangle too small for that gives its centroid. A point within a rounding error of an edge
// would otherwise round onto the plane of a surface that meets the triangle there (a wall under
// the edge of a ceiling), and rays leaving it would slip out through that surface: at 1e5,
// where positions are 1/128 apart, one in 256 of the hits near such an edge did.
PT_HD Vec3 insetBarycentrics(Vec3 b, Vec3 e1, Vec3 e2, float margin) {
    // The point's distance from the edge opposite vertex i is b_i times the height of vertex i
    // over it, 2 area / |edge|.
    const Vec3 lo = Vec3(length(e2 - e1), length(e2), length(e1)) * (margin / length(cross(e1, e2)));
    const float loSum = lo.x + lo.y + lo.z;
    if (!(loSum < 1.0f)) return Vec3(1.0f / 3.0f);  // NaN or inf too: a degenerate triangle
    if (b.x >= lo.x && b.y >= lo.y && b.z >= lo.z) return b;
    const Vec3 spare = vmax(b - lo, Vec3(0.0f));  // sums to more than 1 - loSum > 0
    return lo + spare * ((1.0f - loSum) / (spare.x + spare.y + spare.z));
}

// A world point of a surface and the bound on its error that offsetRayOrigin() needs.
struct SurfacePoint {
    Vec3 position;
    Vec3 error;  // per axis
};

// The point at barycentrics `b` of `inst`'s object-space triangle (p0, p1, p2), in world space,
// kept inside the triangle by its error bound.
PT_HD SurfacePoint triangleSurfacePoint(const RenderInstance& inst, Vec3 p0, Vec3 p1, Vec3 p2, Vec3 b) {
    SurfacePoint s;
    s.error = surfacePointError(inst, vmax(vabs(p0), vmax(vabs(p1), vabs(p2))));
    const Affine3& m = inst.objectToWorld;
    const Vec3 inside =
        insetBarycentrics(b, m.transformVector(p1 - p0), m.transformVector(p2 - p0), length(s.error));
    s.position = m.transformPoint(p0 * inside.x + p1 * inside.y + p2 * inside.z);
    return s;
}

}  // namespace pt
