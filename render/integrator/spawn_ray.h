#pragma once
// Rays that leave a surface: from just off it (offsetRayOrigin with the hit's error bound, so
// the offset scales with the coordinates: render/bvh/instance_space.h), and shadow rays that
// stop just short of the light point they aim at.
#include "render/integrator/surface_hit.h"
#include "render/lights/light_sample.h"

namespace pt {

// Origin of a ray leaving `surface` on the side of `normal` (its geometric normal, either way
// round) or, with towardsNormal false, on the other side.
PT_HD Vec3 spawnOrigin(const SurfaceHit& surface, Vec3 normal, bool towardsNormal) {
    return offsetRayOrigin(surface.position, surface.positionError, normal, towardsNormal);
}

// Where a shadow ray to an area light stops, as a fraction of the way from its origin to its
// offset target. Each instance sees the segment through its own transform, which rounds its end
// by a fraction of the segment's length (the direction's error, not the target's): this much.
constexpr float kShadowRayEnd = 1.0f - gammaBound(kSpawnRoundings + kIntersectionRoundings);

// The shadow ray from `origin` (a point in a medium, or just off a surface) to `light`'s sample
// point: blocked if anything lies between. The target is offset off an area light towards the
// shading point, like an origin, so that neither the light itself nor a surface right behind it
// (a lamp a ulp under a ceiling) is hit.
PT_HD Ray shadowRayFrom(Vec3 origin, const LightSample& light) {
    if (isInfinite(light.distance)) return {origin, light.wi, kInf};
    if (light.delta) return {origin, light.point - origin, 1.0f};  // punctual: no surface there
    const Vec3 target = offsetRayOrigin(light.point, light.pointError, light.normal, true);
    return {origin, target - origin, kShadowRayEnd};
}

// The shadow ray from `surface`, leaving it on the light's side.
PT_HD Ray shadowRayTo(const SurfaceHit& surface, const LightSample& light) {
    const Vec3 n = surface.geometricNormal;
    return shadowRayFrom(spawnOrigin(surface, n, dot(light.wi, n) > 0.0f), light);
}

}  // namespace pt
