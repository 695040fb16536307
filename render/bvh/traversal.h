#pragma once
// Scene-level ray queries, shared by the CPU and CUDA backends: closest hit for path vertices
// and any hit for shadow rays. Two levels (TLAS over instances, BLAS per mesh); with
// RenderScene::bruteForce every primitive of every instance is tested instead.
#include "render/bvh/brute_force.h"
#include "render/bvh/tlas_traversal.h"

namespace pt {

// kF (scene_features.h): code specialised without feature::kBruteForce has no brute-force loop.
template <FeatureSet kF, class Count>
PT_HD bool traverseScene(const RenderScene& scene, const Ray& worldRay, float& tMax, Hit& hit, Count count,
                         bool anyHit) {
    if (hasFeature<kF>(feature::kBruteForce) && scene.bruteForce) {
        return bruteForceIntersect(scene, worldRay, tMax, hit, count, anyHit);
    }
    return traverseTlas<kF>(scene, worldRay, tMax, hit, count, anyHit);
}

// Closest hit with 0 < t < worldRay.tMax, t in the world ray's parametrisation. On a miss,
// returns false and hit.instance == Hit::kNoHit. A non-null `stats` counts the work; it is
// tested here once, and the uncounted walk carries no counters at all.
template <FeatureSet kF = kAllFeatures>
PT_HD bool intersectClosest(const RenderScene& scene, const Ray& worldRay, Hit& hit,
                            TraversalStats* stats = nullptr) {
    hit.t = worldRay.tMax;
    hit.u = hit.v = 0.0f;
    hit.primitive = 0;
    hit.instance = Hit::kNoHit;
    float tMax = worldRay.tMax;
    return stats ? traverseScene<kF>(scene, worldRay, tMax, hit, TraversalCounter{stats}, false)
                 : traverseScene<kF>(scene, worldRay, tMax, hit, NoTraversalCount{}, false);
}

// Whether anything lies at 0 < t < worldRay.tMax (shadow rays); stops at the first hit found.
template <FeatureSet kF = kAllFeatures>
PT_HD bool intersectAny(const RenderScene& scene, const Ray& worldRay, TraversalStats* stats = nullptr) {
    Hit hit;
    float tMax = worldRay.tMax;
    return stats ? traverseScene<kF>(scene, worldRay, tMax, hit, TraversalCounter{stats}, true)
                 : traverseScene<kF>(scene, worldRay, tMax, hit, NoTraversalCount{}, true);
}

// Closest hit, or with `anyHit` whether anything is hit (as intersectAny), through one walk:
// the megakernel traces path segments and shadow rays at one call site, so a warp whose
// threads trace both kinds walks the BVH together, and the kernel holds one copy of the walk.
// As intersectClosest, hit.t starts at worldRay.tMax and hit.instance at Hit::kNoHit. The walk
// knows its call site is shared (SharedSiteCount).
template <FeatureSet kF = kAllFeatures>
PT_HD bool intersectScene(const RenderScene& scene, const Ray& worldRay, bool anyHit, Hit& hit) {
    hit.t = worldRay.tMax;
    hit.u = hit.v = 0.0f;
    hit.primitive = 0;
    hit.instance = Hit::kNoHit;
    float tMax = worldRay.tMax;
    return traverseScene<kF>(scene, worldRay, tMax, hit, SharedSiteCount<NoTraversalCount>{}, anyHit);
}

}  // namespace pt
