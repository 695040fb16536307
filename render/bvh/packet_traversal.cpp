#include "render/bvh/packet_traversal.h"

#include <algorithm>
#include <cassert>

#include "render/bvh/traversal.h"
#include "render/bvh/wide_walk_simd.h"

namespace pt {

namespace {

// The one triangle BLAS every ray of the scene meets, as traverseTlas reaches it: the only
// instance's, in its object space, or the merged BLAS where the TLAS holds nothing else, in
// world space. Null where there is none, or where the packet walk does not apply.
struct PacketTarget {
    const BlasRef* blas = nullptr;
    bool merged = false;  // the merged BLAS: world-space rays, hits mapped to their instances
};

PacketTarget packetTarget(const RenderScene& scene) {
    if (scene.bruteForce || scene.blasWideRoots.empty() || scene.instances.empty() ||
        wideWalkSimdLevel() != SimdLevel::Avx2)
        return {};
    PacketTarget target;
    if (scene.instances.count == 1) {
        target.blas = &scene.blases[scene.instances[0].blas];
    } else if (scene.mergedBlas != kNoMergedBlas && scene.tlasInstanceIndices.count == 1 &&
               scene.tlasInstanceIndices[0] == scene.instances.count) {
        target.blas = &scene.blases[scene.mergedBlas];
        target.merged = true;
    }
    if (!target.blas || target.blas->kind != GeometryKind::Triangles) return {};
    return target;
}

}  // namespace

bool packetWalkApplies(const RenderScene& scene) { return packetTarget(scene).blas != nullptr; }

void intersectClosestPacket(const RenderScene& scene, const Ray* rays, uint32_t count, Hit* hits) {
    assert(count >= 1 && count <= kRayPacketSize && "a packet holds 1 to 8 rays");
    const PacketTarget target = packetTarget(scene);
    if (!target.blas) {
        for (uint32_t i = 0; i < count; ++i) intersectClosest(scene, rays[i], hits[i]);
        return;
    }
    // intersectClosest's start: no hit, at the ray's tMax. Lanes past `count` repeat the last
    // ray and are left out of the walk.
    TraversalRay traversal[kRayPacketSize];
    float tMax[kRayPacketSize];
    Hit laneHits[kRayPacketSize];
    for (uint32_t lane = 0; lane < kRayPacketSize; ++lane) {
        const Ray& ray = rays[std::min(lane, count - 1)];
        traversal[lane] = target.merged ? makeTraversalRay(ray.origin, ray.direction)
                                        : objectSpaceRay(scene.instances[0], ray);
        tMax[lane] = ray.tMax;
        laneHits[lane] = {ray.tMax, 0.0f, 0.0f, 0u, Hit::kNoHit};
    }
    const BlasRef& blas = *target.blas;
    uint32_t found = 0;
    if (blas.primitiveCount != 0 && blas.nodeCount != 0) {  // traverseBlas: an empty BLAS hits nothing
        const uint32_t index = uint32_t(&blas - scene.blases.data);
        found = simd_detail::walkTriangleWidePacketAvx2(scene.blasWideNodes.data, scene.blasWideRoots[index],
                                                        scene.blasTriangleBlocks.data, traversal,
                                                        (1u << count) - 1u, tMax, laneHits);
    }
    for (uint32_t lane = 0; lane < count; ++lane) {
        Hit& hit = laneHits[lane];
        if (found & (1u << lane)) {
            if (target.merged) {  // as traverseMerged reports it
                const MergedTriangle copied = scene.mergedTriangles[hit.primitive];
                hit.instance = copied.instance;
                hit.primitive = copied.primitive;
            } else {
                hit.instance = 0;
            }
        }
        hits[lane] = hit;
    }
}

}  // namespace pt
