#pragma once
// Closest hits (and any hits) of eight rays at once on the CPU (issue 21): camera rays of neighbouring
// pixels, which enter the same nodes, walk a triangle BLAS's 8-wide tree together, as Embree's 8-ray packets
// do (Wald, Slusallek, Benthin and Wagner 2001, "Interactive Rendering with Coherent Ray Tracing"; Embree's
// hybrid walk: Wald et al. 2014, "Embree: A Kernel Framework for Efficient CPU Ray Tracing", section 5): a
// node is loaded once for the packet, each child box is tested against the eight rays in one 256-bit slab
// test, and lanes left alone in a subtree finish it on the single-ray walk; over several instances the packet
// walks the TLAS first. Each ray gets exactly the hit intersectClosest gives it: every (ray, box) test
// computes what the single-ray test computes for that ray and box, every leaf a ray enters is tested for that
// ray by the single-ray leaf test, with its state, the closest hit with ties to the lower
// primitive does not depend on the order of a BLAS's leaves, nor with ties to the lower
// instance on the order of the TLAS's (tlas_traversal.h).
#if defined(__CUDACC__)
#error "packet_traversal.h is CPU code"
#endif
#include <cstdint>

#include "render/bvh/bvh_walk.h"
#include "render/bvh/hit.h"
#include "render/kernel/bvh_node.h"
#include "render/kernel/render_scene.h"
#include "render/kernel/triangle_block.h"
#include "render/kernel/wide_bvh_node.h"
#include "render/math/ray.h"

namespace pt {

constexpr uint32_t kRayPacketSize = 8;

// Whether intersectClosestPacket walks `scene`'s rays together: the CPU runs AVX2 (the walk's
// level, wide_walk_simd.h), the scene has the 8-wide BLASes and instances, brute force is off,
// and its one instance (where it has one) is of triangles; with several, a TLAS. Otherwise it
// traces the rays one by one.
bool packetWalkApplies(const RenderScene& scene);

// Whether `count` rays point about one way (each within about 25 degrees of the first), so that
// they enter mostly the same nodes and walking them together pays: camera rays of neighbouring
// pixels, shadow rays toward one light. Diffuse bounces point every way: in packets their
// closest hits ran 0.88-0.96x as fast as one at a time (bench's 1M sphere at 640x480, one
// thread pinned), since the packet's interval test needs one sign per axis and each lane then
// tests every box it is offered.
bool raysCoherent(const Ray* rays, uint32_t count);

// hits[i] = what intersectClosest(scene, rays[i], hits[i]) gives, bit for bit, for i < count
// (1 <= count <= kRayPacketSize).
void intersectClosestPacket(const RenderScene& scene, const Ray* rays, uint32_t count, Hit* hits);
// The same hits, walked as a packet where raysCoherent, else one ray at a time.
void intersectClosestGrouped(const RenderScene& scene, const Ray* rays, uint32_t count, Hit* hits);

// Shadow rays: bit i set where intersectAny(scene, rays[i]) is true, for i < count (1 <= count
// <= kRayPacketSize). The walk is intersectClosestPacket's with any-hit leaves; a lane that finds
// a hit drops out of it, and it ends when every lane has one. The answer is the single ray's:
// a lane enters the leaves its own ray enters, up to its own tMax, and any hit there is one.
uint32_t intersectAnyPacket(const RenderScene& scene, const Ray* rays, uint32_t count);

namespace simd_detail {
// The packet walk at AVX2 (packet_walk_avx2.cpp) of the 8-wide tree `nodes` from `root`, whose
// leaves index `blocks`, by rays[lane] for the lanes set in `lanes` (all kRayPacketSize rays
// must be readable): lowers tMax[lane] and fills hits[lane].t/u/v/primitive where a lane finds
// a hit (as walkTriangleWideBvh does); returns the lanes that found one. With `anyHit`, a lane
// stops at its first hit, and its tMax becomes -infinity.
uint32_t walkTriangleWidePacketAvx2(const WideBvhNode* nodes, uint32_t root, const TriangleBlock* blocks,
                                    const TraversalRay* rays, uint32_t lanes, float* tMax, Hit* hits,
                                    bool anyHit);
// What a TLAS leaf does with the packet: visit(context, first, count, lanes) for its entries
// [first, first + count) of RenderScene::tlasInstanceIndices and the lanes that reach it.
using TlasLeafVisit = void (*)(void* context, uint32_t first, uint32_t count, uint32_t lanes);
// The packet walk at AVX2 of the binary TLAS `nodes` by the world rays rays[lane], lanes in
// `lanes` (all kRayPacketSize readable); tMax (per lane) is read again after every leaf.
void walkTlasPacketAvx2(const BvhNode* nodes, const TraversalRay* rays, uint32_t lanes, const float* tMax,
                        TlasLeafVisit visit, void* context);
}  // namespace simd_detail

}  // namespace pt
