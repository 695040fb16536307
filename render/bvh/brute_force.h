#pragma once
// Brute force: every primitive of every instance, no BVH. The validation path
// (RenderScene::bruteForce) and the reference the BVH tests compare against. It uses the same
// object-space ray preparation and primitive test as the BVH path, and its in-order test keeps
// the lowest instance and primitive of equal t, as every walk does (tlas_traversal.h), so hits
// agree bit for bit.
#include "render/bvh/tlas_traversal.h"

namespace pt {

template <class Count>
PT_HD bool bruteForceIntersect(const RenderScene& scene, const Ray& worldRay, float& tMax, Hit& hit,
                               Count count, bool anyHit) {
    bool found = false;
    for (uint32_t index = 0; index < scene.instances.size(); ++index) {
        const RenderInstance& inst = scene.instances[index];
        const BlasRef& blas = scene.blases[inst.blas];
        const TraversalRay ray = objectSpaceRay(inst, worldRay);
        for (uint32_t local = 0; local < blas.primitiveCount; ++local) {
            count.primitive();
            if (intersectBlasPrimitive(scene, blas, local, ray, tMax, hit)) {
                tMax = hit.t;
                hit.instance = index;
                found = true;
                if (anyHit) return true;
            }
        }
    }
    return found;
}

}  // namespace pt
