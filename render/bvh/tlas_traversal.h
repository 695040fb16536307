#pragma once
// Top level: the BVH over instances in world space. At an instance leaf the world ray is taken
// into the instance's object space (objectSpacePoint: translation first, so instances far from
// the origin keep their precision); the direction is NOT normalised, so a ray parameter t means
// the same point in both spaces and hits compare across instances.
#include "render/bvh/blas_traversal.h"
#include "render/bvh/instance_space.h"
#include "render/math/float_error.h"

namespace pt {

// The world ray as instance `inst` sees it.
PT_HD TraversalRay objectSpaceRay(const RenderInstance& inst, const Ray& worldRay) {
    return makeTraversalRay(objectSpacePoint(inst, worldRay.origin),
                            inst.worldToObject.transformVector(worldRay.direction));
}

// Closest (or any) hit of the world ray in instance `index` alone; on a hit sets hit.instance.
template <FeatureSet kF, class Count>
PT_HD bool traverseInstance(const RenderScene& scene, uint32_t index, const Ray& worldRay, float& tMax,
                            Hit& hit, Count count, bool anyHit) {
    const RenderInstance& inst = scene.instances[index];
    const TraversalRay ray = objectSpaceRay(inst, worldRay);
    if (!traverseBlas<kF>(scene, scene.blases[inst.blas], ray, tMax, hit, count, anyHit)) return false;
    hit.instance = index;
    return true;
}

// Closest (or any) hit in the merged BLAS (merged_geometry.h), whose triangles are world-space
// copies: the world ray walks it as it is, and a hit is reported as the instance triangle it
// copies, so what follows never sees the merge.
template <FeatureSet kF, class Count>
PT_HD bool traverseMerged(const RenderScene& scene, const TraversalRay& worldRay, float& tMax, Hit& hit,
                          Count count, bool anyHit) {
    if (!traverseBlas<kF>(scene, scene.blases[scene.mergedBlas], worldRay, tMax, hit, count, anyHit))
        return false;
    const MergedTriangle copied = scene.mergedTriangles[hit.primitive];
    hit.instance = copied.instance;
    hit.primitive = copied.primitive;
    return true;
}

// Leaf functor of walkBvh (and, on the CPU, walkWideBvh) for the TLAS: each entry of a leaf is
// an instance, or (numbered instances.count) the merged BLAS.
//
// Ties in t between instances go to the lower instance index, as brute force's in-order test
// keeps them (and within a BLAS to the lower primitive, BlasLeaf), so the hit does not depend on
// the order a walk meets the TLAS's leaves in: the CPU's binary and 8-wide TLAS walks, its ray
// packets and the GPU's own TLAS (an LBVH) agree on coincident instances, where a rule of "first
// met" would shade different surfaces on each. An entry that may win such a tie is walked up to
// tMax inclusive (its next float up); the merged BLAS, whose hits may belong to any of its
// instances, gives its hit back where it ties and loses. Within the merged BLAS a tie goes to
// its lower primitive, which is the lower instance because its pieces are laid out in instance
// order (planMergedGeometry).
template <FeatureSet kF, class Count>
struct TlasLeaf {
    const RenderScene& scene;
    const Ray& worldRay;
    const TraversalRay& worldTraversalRay;
    Hit& hit;
    Count counter;
    bool anyHit;

    PT_HD bool operator()(uint32_t first, uint32_t count, float& tMax) {
        bool found = false;
        for (uint32_t i = first; i < first + count; ++i) {
            if (traceEntry(scene.tlasInstanceIndices[i], tMax)) {
                found = true;
                if (anyHit) return true;
            }
        }
        return found;
    }

    // Whether entry `entry` has the closest hit so far (by t, then instance), lowering tMax.
    PT_HD bool traceEntry(uint32_t entry, float& tMax) {
        const bool mayTie = !anyHit && hit.valid();
        if (entry != scene.instances.count) {
            float limit = mayTie && entry < hit.instance ? nextFloatUp(tMax) : tMax;
            if (!traverseInstance<kF>(scene, entry, worldRay, limit, hit, counter, anyHit)) return false;
            tMax = limit;
            return true;
        }
        if (!mayTie) return traverseMerged<kF>(scene, worldTraversalRay, tMax, hit, counter, anyHit);
        const Hit before = hit;
        float limit = nextFloatUp(tMax);
        if (!traverseMerged<kF>(scene, worldTraversalRay, limit, hit, counter, anyHit)) return false;
        if (limit == tMax && hit.instance > before.instance) {
            hit = before;
            return false;
        }
        tMax = limit;
        return true;
    }
};

// Closest (or any) hit over all instances with t < tMax; lowers tMax and fills `hit`. A scene
// of one instance walks its BLAS alone: it has no TLAS to speak of (and kernels specialised
// without feature::kMultipleInstances carry no TLAS code).
template <FeatureSet kF = kAllFeatures, class Count>
PT_HD bool traverseTlas(const RenderScene& scene, const Ray& worldRay, float& tMax, Hit& hit, Count count,
                        bool anyHit) {
    if (scene.instances.empty()) return false;
    if (!hasFeature<kF>(feature::kMultipleInstances) || scene.instances.count == 1) {
        return traverseInstance<kF>(scene, 0, worldRay, tMax, hit, count, anyHit);
    }
    if (scene.tlasNodes.empty()) return false;
    const TraversalRay ray = makeTraversalRay(worldRay.origin, worldRay.direction);
    TlasLeaf<kF, Count> leaf{scene, worldRay, ray, hit, count, anyHit};
#if !defined(__CUDACC__)
    // The CPU's 8-wide TLAS where the compiler made one: 64 instances are two levels of it
    // instead of six binary ones, each node's boxes in one SIMD test. The tie rule (TlasLeaf)
    // keeps its hits the binary walk's.
    if (!scene.tlasWideNodes.empty())
        return walkWideBvh(scene.tlasWideNodes.data, 0, ray, tMax, leaf, count, anyHit);
#endif
    return walkBvh(scene.tlasNodes.data, ray, tMax, leaf, count, anyHit);
}

}  // namespace pt
