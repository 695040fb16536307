#include "render/bvh/packet_traversal.h"

#include <algorithm>
#include <cassert>

#include "render/bvh/traversal.h"
#include "render/bvh/wide_walk_simd.h"
#include "render/math/float_error.h"

// Sections: which scenes the packets take / one BLAS / through the TLAS / one packet / entry points.

namespace pt {

namespace {

// ---- which scenes the packets take -----------------------------------------------------------

// How a packet reaches the scene's triangles, as traverseTlas does: the only instance's BLAS in
// its object space, the merged BLAS alone in world space (the TLAS holds nothing else), or the
// TLAS. A BLAS's wide form is walked even where the scene also has compressed BLASes (the CPU
// backend never builds those; tests do), whose walk traverseBlas would take: the hits are the
// same, as every walk's are.
enum class PacketRoute { None, OneInstance, MergedOnly, Tlas };

PacketRoute packetRoute(const RenderScene& scene) {
    if (scene.bruteForce || scene.blasWideRoots.empty() || scene.instances.empty() ||
        wideWalkSimdLevel() != SimdLevel::Avx2)
        return PacketRoute::None;
    if (scene.instances.count == 1) {
        return scene.blases[scene.instances[0].blas].kind == GeometryKind::Triangles
                   ? PacketRoute::OneInstance
                   : PacketRoute::None;
    }
    if (scene.tlasNodes.empty()) return PacketRoute::None;
    if (scene.mergedBlas != kNoMergedBlas && scene.tlasInstanceIndices.count == 1 &&
        scene.tlasInstanceIndices[0] == scene.instances.count)
        return PacketRoute::MergedOnly;
    return PacketRoute::Tlas;
}

// intersectClosest's start: no hit, at the ray's tMax.
Hit noHit(const Ray& ray) { return {ray.tMax, 0.0f, 0.0f, 0u, Hit::kNoHit}; }

// ---- one BLAS --------------------------------------------------------------------------------

// A hit of `blas` as traverseInstance or traverseMerged reports it: the instance, and for the
// merged BLAS the instance triangle it copies.
void reportHit(const RenderScene& scene, uint32_t entry, Hit& hit) {
    if (entry == scene.instances.count) {
        const MergedTriangle copied = scene.mergedTriangles[hit.primitive];
        hit.instance = copied.instance;
        hit.primitive = copied.primitive;
    } else {
        hit.instance = entry;
    }
}

// The closest hits of the lanes in `lanes` in TLAS entry `entry` (an instance, or
// instances.count for the merged BLAS) below tMax[lane], each as a fresh traverseBlas gives it
// (ties in t to the lower primitive): rays[lane] are world rays, world[lane] their traversal
// form. Returns the lanes that hit, their hits (not yet reported) in found[lane]. With
// `anyHit`, the lanes that hit anything (found[lane] then holds no closest hit).
uint32_t traceEntry(const RenderScene& scene, uint32_t entry, const Ray* rays, const TraversalRay* world,
                    uint32_t lanes, float* tMax, Hit* found, bool anyHit) {
    const bool merged = entry == scene.instances.count;
    const uint32_t index = merged ? scene.mergedBlas : scene.instances[entry].blas;
    const BlasRef& blas = scene.blases[index];
    if (blas.primitiveCount == 0 || blas.nodeCount == 0) return 0;  // traverseBlas: no hit
    TraversalRay local[kRayPacketSize];
    const uint32_t some = uint32_t(__builtin_ctz(lanes));
    for (uint32_t lane = 0; lane < kRayPacketSize; ++lane) {
        found[lane] = {tMax[lane], 0.0f, 0.0f, 0u, Hit::kNoHit};
        if (lanes & (1u << lane))
            local[lane] = merged ? world[lane] : objectSpaceRay(scene.instances[entry], rays[lane]);
    }
    for (uint32_t lane = 0; lane < kRayPacketSize; ++lane) {
        if (!(lanes & (1u << lane))) local[lane] = local[some];  // lanes left out copy one taken
    }
    if (blas.kind == GeometryKind::Triangles) {
        return simd_detail::walkTriangleWidePacketAvx2(scene.blasWideNodes.data, scene.blasWideRoots[index],
                                                       scene.blasTriangleBlocks.data, local, lanes, tMax,
                                                       found, anyHit);
    }
    uint32_t hit = 0;
    for (uint32_t bits = lanes; bits != 0; bits &= bits - 1) {
        const uint32_t lane = uint32_t(__builtin_ctz(bits));
        if (traverseBlas(scene, blas, local[lane], tMax[lane], found[lane], NoTraversalCount{}, anyHit))
            hit |= 1u << lane;
    }
    return hit;
}

// ---- through the TLAS ------------------------------------------------------------------------

// The packet's state through the TLAS: per lane the hit so far (intersectClosest's) and its
// tMax; for any hits, the lanes that found one (their tMax -infinity: they reach no more).
struct TlasPacket {
    const RenderScene& scene;
    const Ray* rays;
    const TraversalRay* world;
    float tMax[kRayPacketSize];
    Hit* hits;
    bool anyHit = false;
    uint32_t occluded = 0;
};

// A TLAS leaf's entries in order, as TlasLeaf takes them. A lane with a hit asks each entry for
// hits up to its t inclusive (the next float up): a nearer one replaces it, one at the same t
// where its instance is the lower (TlasLeaf's tie rule). So each lane ends with its single-ray
// hit whatever order the packet meets the entries in. For any hits, each lane not yet occluded
// asks each entry for anything up to its tMax; one that finds it is done.
void visitTlasLeaf(void* context, uint32_t first, uint32_t count, uint32_t lanes) {
    TlasPacket& p = *static_cast<TlasPacket*>(context);
    if (p.anyHit) {
        // A lane's tMax stays its ray's until it is occluded (then -infinity), so each entry is
        // walked up to it in place.
        for (uint32_t i = first; i < first + count && (lanes &= ~p.occluded) != 0; ++i) {
            Hit found[kRayPacketSize];
            const uint32_t hit = traceEntry(p.scene, p.scene.tlasInstanceIndices[i], p.rays, p.world, lanes,
                                            p.tMax, found, true);
            p.occluded |= hit;
            for (uint32_t bits = hit; bits != 0; bits &= bits - 1) p.tMax[__builtin_ctz(bits)] = -kInf;
        }
        return;
    }
    for (uint32_t i = first; i < first + count; ++i) {
        const uint32_t entry = p.scene.tlasInstanceIndices[i];
        float limit[kRayPacketSize];
        for (uint32_t lane = 0; lane < kRayPacketSize; ++lane) {
            limit[lane] = p.hits[lane].valid() ? nextFloatUp(p.tMax[lane]) : p.tMax[lane];
        }
        Hit found[kRayPacketSize];
        const uint32_t hit = traceEntry(p.scene, entry, p.rays, p.world, lanes, limit, found, false);
        for (uint32_t bits = hit; bits != 0; bits &= bits - 1) {
            const uint32_t lane = uint32_t(__builtin_ctz(bits));
            reportHit(p.scene, entry, found[lane]);
            // A lane without a hit was walked up to its tMax exclusive: its hit is nearer.
            if (found[lane].t == p.tMax[lane] && found[lane].instance > p.hits[lane].instance) continue;
            p.hits[lane] = found[lane];
            p.tMax[lane] = found[lane].t;
        }
    }
}

// ---- one packet ------------------------------------------------------------------------------

// One packet through the scene by `route` (not None): closest hits into hits[lane] (from
// noHit), or with `anyHit` the lanes that hit anything. Lanes past `count` repeat the last ray
// and are left out of the walks.
uint32_t tracePacket(const RenderScene& scene, PacketRoute route, const Ray* rays, uint32_t count, Hit* hits,
                     bool anyHit) {
    Ray laneRays[kRayPacketSize];
    TraversalRay world[kRayPacketSize] = {};
    Hit laneHits[kRayPacketSize];
    for (uint32_t lane = 0; lane < kRayPacketSize; ++lane) {
        laneRays[lane] = rays[std::min(lane, count - 1)];
        // One instance's rays are taken into its object space alone (traceEntry).
        if (route != PacketRoute::OneInstance) {
            world[lane] = makeTraversalRay(laneRays[lane].origin, laneRays[lane].direction);
        }
        laneHits[lane] = noHit(laneRays[lane]);
    }
    const uint32_t lanes = (1u << count) - 1u;
    uint32_t hit = 0;
    if (route == PacketRoute::Tlas) {
        TlasPacket packet{scene, laneRays, world, {}, laneHits, anyHit};
        for (uint32_t lane = 0; lane < kRayPacketSize; ++lane) packet.tMax[lane] = laneRays[lane].tMax;
        simd_detail::walkTlasPacketAvx2(scene.tlasNodes.data, world, lanes, packet.tMax, visitTlasLeaf,
                                        &packet);
        hit = packet.occluded;
    } else {
        const uint32_t entry = route == PacketRoute::MergedOnly ? scene.instances.count : 0u;
        float tMax[kRayPacketSize];
        Hit found[kRayPacketSize];
        for (uint32_t lane = 0; lane < kRayPacketSize; ++lane) tMax[lane] = laneRays[lane].tMax;
        hit = traceEntry(scene, entry, laneRays, world, lanes, tMax, found, anyHit);
        for (uint32_t bits = anyHit ? 0u : hit; bits != 0; bits &= bits - 1) {
            const uint32_t lane = uint32_t(__builtin_ctz(bits));
            reportHit(scene, entry, found[lane]);
            laneHits[lane] = found[lane];
        }
    }
    if (hits) std::copy(laneHits, laneHits + count, hits);
    return hit;
}

}  // namespace

// ---- entry points ----------------------------------------------------------------------------

bool packetWalkApplies(const RenderScene& scene) { return packetRoute(scene) != PacketRoute::None; }

bool raysCoherent(const Ray* rays, uint32_t count) {
    constexpr float kCosSquared = 0.81f;  // cos(25.8 degrees)^2
    const Vec3 first = rays[0].direction;
    const float firstLengthSquared = dot(first, first);
    for (uint32_t i = 1; i < count; ++i) {
        const Vec3 d = rays[i].direction;
        const float c = dot(first, d);
        if (!(c > 0.0f && c * c >= kCosSquared * firstLengthSquared * dot(d, d))) return false;
    }
    return true;
}

void intersectClosestPacket(const RenderScene& scene, const Ray* rays, uint32_t count, Hit* hits) {
    assert(count >= 1 && count <= kRayPacketSize && "a packet holds 1 to 8 rays");
    const PacketRoute route = packetRoute(scene);
    if (route == PacketRoute::None) {
        for (uint32_t i = 0; i < count; ++i) intersectClosest(scene, rays[i], hits[i]);
        return;
    }
    tracePacket(scene, route, rays, count, hits, false);
}

void intersectClosestGrouped(const RenderScene& scene, const Ray* rays, uint32_t count, Hit* hits) {
    if (raysCoherent(rays, count)) {
        intersectClosestPacket(scene, rays, count, hits);
        return;
    }
    for (uint32_t i = 0; i < count; ++i) intersectClosest(scene, rays[i], hits[i]);
}

uint32_t intersectAnyPacket(const RenderScene& scene, const Ray* rays, uint32_t count) {
    assert(count >= 1 && count <= kRayPacketSize && "a packet holds 1 to 8 rays");
    const PacketRoute route = packetRoute(scene);
    if (route != PacketRoute::None) return tracePacket(scene, route, rays, count, nullptr, true);
    uint32_t occluded = 0;
    for (uint32_t i = 0; i < count; ++i) occluded |= intersectAny(scene, rays[i]) ? 1u << i : 0u;
    return occluded;
}

}  // namespace pt
