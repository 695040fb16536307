#pragma once
// Top level: the BVH over instances in world space. At an instance leaf the world ray is taken
// into the instance's object space (objectSpacePoint: translation first, so instances far from
// the origin keep their precision); the direction is NOT normalised, so a ray parameter t means
// the same point in both spaces and hits compare across instances.
#include "render/bvh/blas_traversal.h"
#include "render/bvh/instance_space.h"

namespace pt {

// The world ray as instance `inst` sees it.
PT_HD TraversalRay objectSpaceRay(const RenderInstance& inst, const Ray& worldRay) {
    return makeTraversalRay(objectSpacePoint(inst, worldRay.origin),
                            inst.worldToObject.transformVector(worldRay.direction));
}

// Leaf functor of walkBvh for the TLAS: each entry of a leaf is an instance.
template <class Count>
struct TlasLeaf {
    const RenderScene& scene;
    const Ray& worldRay;
    Hit& hit;
    Count counter;
    bool anyHit;

    PT_HD bool operator()(uint32_t first, uint32_t count, float& tMax) {
        bool found = false;
        for (uint32_t i = first; i < first + count; ++i) {
            const uint32_t index = scene.tlasInstanceIndices[i];
            const RenderInstance& inst = scene.instances[index];
            const TraversalRay ray = objectSpaceRay(inst, worldRay);
            const BlasRef& blas = scene.blases[inst.blas];
            const bool hitHere = anyHit ? traverseBlas<true>(scene, blas, ray, tMax, hit, counter)
                                        : traverseBlas<false>(scene, blas, ray, tMax, hit, counter);
            if (hitHere) {
                hit.instance = index;
                found = true;
                if (anyHit) return true;
            }
        }
        return found;
    }
};

// Closest (or any) hit over all instances with t < tMax; lowers tMax and fills `hit`.
template <bool kAnyHit, class Count>
PT_HD bool traverseTlas(const RenderScene& scene, const Ray& worldRay, float& tMax, Hit& hit, Count count) {
    if (scene.tlasNodes.empty() || scene.instances.empty()) return false;
    const TraversalRay ray = makeTraversalRay(worldRay.origin, worldRay.direction);
    TlasLeaf<Count> leaf{scene, worldRay, hit, count, kAnyHit};
    return walkBvh<kAnyHit>(scene.tlasNodes.data, ray, tMax, leaf, count);
}

}  // namespace pt
