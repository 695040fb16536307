#pragma once
// Scene-level ray queries, shared by the CPU and CUDA backends: closest hit for path vertices
// and any hit for shadow rays. Two levels (TLAS over instances, BLAS per mesh); with
// RenderScene::bruteForce every primitive of every instance is tested instead.
#include "render/bvh/brute_force.h"
#include "render/bvh/tlas_traversal.h"

namespace pt {

template <bool kAnyHit, class Count>
PT_HD bool traverseScene(const RenderScene& scene, const Ray& worldRay, float& tMax, Hit& hit, Count count) {
    return scene.bruteForce ? bruteForceIntersect<kAnyHit>(scene, worldRay, tMax, hit, count)
                            : traverseTlas<kAnyHit>(scene, worldRay, tMax, hit, count);
}

// Closest hit with 0 < t < worldRay.tMax, t in the world ray's parametrisation. On a miss,
// returns false and hit.instance == Hit::kNoHit. A non-null `stats` counts the work; it is
// tested here once, and the uncounted walk carries no counters at all.
PT_HD bool intersectClosest(const RenderScene& scene, const Ray& worldRay, Hit& hit,
                            TraversalStats* stats = nullptr) {
    hit.t = worldRay.tMax;
    hit.u = hit.v = 0.0f;
    hit.primitive = 0;
    hit.instance = Hit::kNoHit;
    float tMax = worldRay.tMax;
    return stats ? traverseScene<false>(scene, worldRay, tMax, hit, TraversalCounter{stats})
                 : traverseScene<false>(scene, worldRay, tMax, hit, NoTraversalCount{});
}

// Whether anything lies at 0 < t < worldRay.tMax (shadow rays); stops at the first hit found.
PT_HD bool intersectAny(const RenderScene& scene, const Ray& worldRay, TraversalStats* stats = nullptr) {
    Hit hit;
    float tMax = worldRay.tMax;
    return stats ? traverseScene<true>(scene, worldRay, tMax, hit, TraversalCounter{stats})
                 : traverseScene<true>(scene, worldRay, tMax, hit, NoTraversalCount{});
}

}  // namespace pt
