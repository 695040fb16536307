#pragma once
// Bottom level: one mesh's BVH in object space. The primitive test is shared with brute force
// so that both paths compute bit-identical hits for the same prepared ray.
#include "render/bvh/bvh_walk.h"
#include "render/bvh/compressed_wide_walk.h"
#include "render/bvh/hit.h"
#include "render/bvh/sphere_intersect.h"
#include "render/bvh/triangle_intersect.h"
#include "render/kernel/render_scene.h"
#if !defined(__CUDACC__)
#include "render/bvh/wide_walk.h"
#include "render/bvh/wide_walk_simd.h"
#endif

namespace pt {

// Tests mesh-local primitive `local` of `blas` against (0, tMax); on a hit fills t, u, v and
// primitive of `hit` (spheres set u = v = 0). Without feature::kSpheres in kF every BLAS holds
// triangles.
template <FeatureSet kF = kAllFeatures>
PT_HD bool intersectBlasPrimitive(const RenderScene& scene, const BlasRef& blas, uint32_t local,
                                  const TraversalRay& ray, float tMax, Hit& hit) {
    const uint32_t global = blas.primitiveOffset + local;
    float t, u = 0.0f, v = 0.0f;
    if (hasFeature<kF>(feature::kSpheres) && blas.kind == GeometryKind::Spheres) {
        if (!intersectSphere(ray.watertight.origin, ray.direction, tMax, scene.spheres[global], t)) {
            return false;
        }
    } else {
        const TriangleIndices tri = scene.triangles[global];
        if (!intersectTriangle(ray.watertight, tMax, scene.positions[tri.v0], scene.positions[tri.v1],
                               scene.positions[tri.v2], t, u, v)) {
            return false;
        }
    }
    hit.t = t;
    hit.u = u;
    hit.v = v;
    hit.primitive = local;
    return true;
}

// Leaf functor of walkBvh for one BLAS. With kLeafTriangles (a triangle BLAS's compressed
// form), entry i is leafTriangles[i], whose corners sit beside its primitive index; otherwise
// primIndices[i], tested through the scene's triangles and positions.
template <FeatureSet kF, class Count, bool kLeafTriangles = false>
struct BlasLeaf {
    const RenderScene& scene;
    const BlasRef& blas;
    const uint32_t* primIndices;  // this BLAS's slice of RenderScene::blasPrimIndices
    const TraversalRay& ray;
    Hit& hit;
    Count counter;
    bool anyHit;
    // With kLeafTriangles (primIndices null): RenderScene::blasCompressedTriangles, parallel to
    // blasCompressedPrims.
    const LeafTriangle* leafTriangles = nullptr;

    bool hitHere = false;  // this walk has found a hit: tMax is that hit's t

    // Entry i against (0, limit): its primitive, and on a hit t, u and v of `candidate`.
    PT_HD bool testEntry(uint32_t i, float limit, Hit& candidate, uint32_t& primitive) const {
        if constexpr (kLeafTriangles) {
            const LeafTriangle t = loadLeafTriangle(leafTriangles, i);
            primitive = t.primitive;
            return intersectTriangle(ray.watertight, limit, t.p0, t.p1, t.p2, candidate.t, candidate.u,
                                     candidate.v);
        } else {
            primitive = primIndices[i];
            return intersectBlasPrimitive<kF>(scene, blas, primitive, ray, limit, candidate);
        }
    }

    // Ties in t go to the lower primitive index within a BLAS, as brute force's in-order test
    // keeps it, so that the hit does not depend on the order a walk meets its leaves in: the
    // binary, 8-wide and compressed 8-wide walks then agree on coincident faces (a box standing
    // on a floor), where they would otherwise shade different surfaces.
    PT_HD bool operator()(uint32_t first, uint32_t count, float& tMax) {
        bool found = false;
        for (uint32_t i = first; i < first + count; ++i) {
            counter.primitive();
            const float limit = hitHere ? intAsFloat(floatAsInt(tMax) + 1) : tMax;  // t == tMax too
            Hit candidate;
            uint32_t primitive;
            if (testEntry(i, limit, candidate, primitive) &&
                (candidate.t < tMax || primitive < hit.primitive)) {
                hit.t = candidate.t, hit.u = candidate.u, hit.v = candidate.v, hit.primitive = primitive;
                tMax = candidate.t;
                found = hitHere = true;
                if (anyHit) return true;
            }
        }
        return found;
    }
};

// Closest (or, with anyHit, any) hit of `ray` (already in the BLAS's object space) with
// t < tMax. On a hit, lowers tMax to it and fills hit.t/u/v/primitive; hit.instance is the
// caller's business.
template <FeatureSet kF = kAllFeatures, class Count>
PT_HD bool traverseBlas(const RenderScene& scene, const BlasRef& blas, const TraversalRay& ray, float& tMax,
                        Hit& hit, Count count, bool anyHit) {
    if (blas.primitiveCount == 0 || blas.nodeCount == 0) return false;
    const uint32_t index = uint32_t(&blas - scene.blases.data);
    // The compressed 8-wide form where the BLAS has one (IntegratorToggles::gpuWideBvh; the CPU's
    // tests walk it too) and the ray's direction allows it (compressedWalkTakes). Its leaf
    // entries are mesh-local primitives, as the binary list's are, and a triangle BLAS's come
    // with their corners (leaf_triangle.h).
    if (!scene.blasCompressedRoots.empty() && scene.blasCompressedRoots[index] != kNoCompressedRoot &&
        compressedWalkTakes(ray)) {
        const CompressedWideNode* nodes = scene.blasCompressedNodes.data;
        const uint32_t root = scene.blasCompressedRoots[index];
        if (!hasFeature<kF>(feature::kSpheres) || blas.kind == GeometryKind::Triangles) {
            BlasLeaf<kF, Count, true> leaf{scene, blas,  nullptr, ray,
                                           hit,   count, anyHit,  scene.blasCompressedTriangles.data};
            return walkCompressedWideBvh(nodes, root, ray, tMax, leaf, count, anyHit);
        }
        BlasLeaf<kF, Count> leaf{scene, blas, scene.blasCompressedPrims.data, ray, hit, count, anyHit};
        return walkCompressedWideBvh(nodes, root, ray, tMax, leaf, count, anyHit);
    }
    BlasLeaf<kF, Count> leaf{scene, blas,  scene.blasPrimIndices.data + blas.primIndexOffset, ray, hit,
                             count, anyHit};
#if !defined(__CUDACC__)
    // The CPU walks the 8-wide form where the scene has one (IntegratorToggles::wideBvh), whose
    // leaves are blocks of four triangles (triangle_block.h) or, for spheres, primitive ranges.
    if (!scene.blasWideRoots.empty()) {
        if (!hasFeature<kF>(feature::kSpheres) || blas.kind == GeometryKind::Triangles) {
            // At the widest SIMD level the processor runs (wide_walk_simd.h).
            return walkTriangleWideBvh(scene.blasWideNodes.data, scene.blasWideRoots[index],
                                       scene.blasTriangleBlocks.data, ray, tMax, hit, count.stats(), anyHit);
        }
        return walkWideBvh(scene.blasWideNodes.data, scene.blasWideRoots[index], ray, tMax, leaf, count,
                           anyHit);
    }
#endif
    return walkBvh(scene.blasNodes.data + blas.nodeOffset, ray, tMax, leaf, count, anyHit);
}

}  // namespace pt
