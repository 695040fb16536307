// The 8-ray packet walk of an 8-wide triangle BLAS with AVX2 (packet_traversal.h): a node is
// read once for the packet and each of its child boxes tested against all eight rays in one
// 256-bit slab test; lanes left alone in a subtree finish it on the single-ray walk
// (wide_walk_avx2.h). Compiled for AVX2 from avx2_target_begin.h on (wide_walk_avx2.cpp says
// why the shared headers come first).
#include <immintrin.h>

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <limits>

#include "render/bvh/packet_traversal.h"
#include "render/bvh/triangle_block_intersect.h"
#include "render/bvh/wide_walk.h"

// clang-format off
#include "render/bvh/avx2_target_begin.h"
#include "render/bvh/wide_walk_avx2.h"
// clang-format on

namespace pt {
namespace avx2 {
namespace {

// A subtree entered by this many lanes or fewer is walked by each of them alone: testing a box
// against eight lanes costs eight single-ray tests' arithmetic, which pays only while most
// lanes use it (Embree's hybrid walk switches the same way).
constexpr uint32_t kAloneLanes = 2;
constexpr uint32_t kAllSlots = (1u << WideBvhNode::kWidth) - 1u;

// The packet's rays as the box test takes them: per lane, TraversalRay's zero-axis padded
// origins and inverse direction.
struct PacketSlabRays {
    __m256 loX, loY, loZ, hiX, hiY, hiZ, invX, invY, invZ;
};

PacketSlabRays packetSlabRays(const TraversalRay* rays) {
    alignas(32) float v[9][kRayPacketSize];
    for (uint32_t lane = 0; lane < kRayPacketSize; ++lane) {
        const TraversalRay& r = rays[lane];
        for (int a = 0; a < 3; ++a) {
            v[a][lane] = r.slabOriginLo[a];
            v[3 + a][lane] = r.slabOriginHi[a];
            v[6 + a][lane] = r.invDirection[a];
        }
    }
    return {_mm256_load_ps(v[0]), _mm256_load_ps(v[1]), _mm256_load_ps(v[2]),
            _mm256_load_ps(v[3]), _mm256_load_ps(v[4]), _mm256_load_ps(v[5]),
            _mm256_load_ps(v[6]), _mm256_load_ps(v[7]), _mm256_load_ps(v[8])};
}

// The lanes set in `lanes` as a mask vector.
__m256 laneMask(uint32_t lanes) {
    const __m256i bits = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
    return _mm256_castsi256_ps(
        _mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(int(lanes)), bits), bits));
}

// (plane - origin) * inverse in eight lanes: where each lane's ray meets an axis-aligned plane.
inline __m256 planeDistance(float plane, __m256 origin, __m256 inverse) {
    return _mm256_mul_ps(_mm256_sub_ps(_mm256_set1_ps(plane), origin), inverse);
}

// The box [lo, hi] against the eight rays: the lanes whose ray enters it before its limit
// (tMax * kSlabExitScale), as a mask vector, and where each enters. Per lane the operations of
// intersectBox (bvh_walk.h) and pt::intersectWideBoxes in their operand order, so the same
// answer and entry as the single-ray walks' test of that box.
inline __m256 entersBox(const PacketSlabRays& r, const float* lo, const float* hi, __m256 limit,
                        __m256& tNear) {
    const __m256 x0 = planeDistance(lo[0], r.loX, r.invX), x1 = planeDistance(hi[0], r.hiX, r.invX);
    const __m256 y0 = planeDistance(lo[1], r.loY, r.invY), y1 = planeDistance(hi[1], r.hiY, r.invY);
    const __m256 z0 = planeDistance(lo[2], r.loZ, r.invZ), z1 = planeDistance(hi[2], r.hiZ, r.invZ);
    tNear = _mm256_max_ps(_mm256_max_ps(_mm256_min_ps(x0, x1), _mm256_min_ps(y0, y1)),
                          _mm256_max_ps(_mm256_min_ps(z0, z1), _mm256_setzero_ps()));
    const __m256 tFar = _mm256_mul_ps(
        _mm256_min_ps(_mm256_max_ps(x0, x1), _mm256_min_ps(_mm256_max_ps(y0, y1), _mm256_max_ps(z0, z1))),
        _mm256_set1_ps(kSlabExitScale));
    return _mm256_cmp_ps(tNear, _mm256_min_ps(tFar, limit), _CMP_LE_OQ);
}

// Slot `slot` of a wide node as entersBox takes it.
inline __m256 entersSlot(const PacketSlabRays& r, const WideBvhNode& node, uint32_t slot, __m256 limit,
                         __m256& tNear) {
    const float lo[3] = {node.loX[slot], node.loY[slot], node.loZ[slot]};
    const float hi[3] = {node.hiX[slot], node.hiY[slot], node.hiZ[slot]};
    return entersBox(r, lo, hi, limit, tNear);
}

// A binary node's box as entersBox takes it.
inline __m256 entersNode(const PacketSlabRays& r, const BvhNode& node, __m256 limit, __m256& tNear) {
    const float lo[3] = {node.lo.x, node.lo.y, node.lo.z}, hi[3] = {node.hi.x, node.hi.y, node.hi.z};
    return entersBox(r, lo, hi, limit, tNear);
}

float smallestLane(__m256 v) {
    __m128 m = _mm_min_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
    m = _mm_min_ps(m, _mm_movehl_ps(m, m));
    return _mm_cvtss_f32(_mm_min_ss(m, _mm_shuffle_ps(m, m, 1)));
}

float largestLane(__m256 v) {
    __m128 m = _mm_max_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
    m = _mm_max_ps(m, _mm_movehl_ps(m, m));
    return _mm_cvtss_f32(_mm_max_ss(m, _mm_shuffle_ps(m, m, 1)));
}

// A box test for the whole packet at once, where along each axis every ray's direction has the
// same sign (camera rays, say): the eight children of a node in one slab test of interval
// bounds, which no ray of the packet can enter where it says none does, so only the children it
// lets through are tested lane by lane (Reshetov, Soupikov and Hurley 2005, "Multi-Level Ray
// Tracing Algorithm", and Embree's frustum culling of coherent rays, Wald et al. 2014). Along an
// axis where the directions are positive a lane's near distance is (lo - originLo) * inverse
// (bvh_walk.h: padded origins, lo <= hi): at least d * inverse, d = lo - (the largest originLo),
// for the inverse nearest to zero or farthest from it, whichever gives less; its far distance
// (hi - originHi) * inverse at most the larger of e * inverse, e = hi - (the smallest originHi).
// Negative directions swap the planes. Every rounding on the way is monotonic in each operand,
// so the bounds hold for the rounded distances each lane computes.
struct PacketFrustum {
    bool valid = false;                  // false: some axis has directions of both signs
    uint32_t nearPlane[3], farPlane[3];  // byte offsets of the plane arrays in WideBvhNode
    __m256 nearOrigin[3], farOrigin[3], inverseSmall[3], inverseLarge[3];
};

// Over the lanes set in `lanes` (a mask vector) only.
float smallestOf(__m256 v, __m256 lanes) {
    return smallestLane(_mm256_blendv_ps(_mm256_set1_ps(kInf), v, lanes));
}
float largestOf(__m256 v, __m256 lanes) {
    return largestLane(_mm256_blendv_ps(_mm256_set1_ps(-kInf), v, lanes));
}

PacketFrustum packetFrustum(const PacketSlabRays& r, __m256 lanes) {
    constexpr uint32_t kAxisBytes = sizeof(WideBvhNode::loX);
    const __m256 originsLo[3] = {r.loX, r.loY, r.loZ}, originsHi[3] = {r.hiX, r.hiY, r.hiZ};
    const __m256 inverses[3] = {r.invX, r.invY, r.invZ};
    PacketFrustum f{};
    for (int a = 0; a < 3; ++a) {
        const float inverseMin = smallestOf(inverses[a], lanes), inverseMax = largestOf(inverses[a], lanes);
        const bool positive = inverseMin > 0.0f;
        if (!positive && !(inverseMax < 0.0f)) return f;
        const float loMax = largestOf(originsLo[a], lanes), hiMin = smallestOf(originsHi[a], lanes);
        const uint32_t lo = uint32_t(offsetof(WideBvhNode, loX)) + uint32_t(a) * kAxisBytes;
        const uint32_t hi = uint32_t(offsetof(WideBvhNode, hiX)) + uint32_t(a) * kAxisBytes;
        f.nearPlane[a] = positive ? lo : hi;
        f.farPlane[a] = positive ? hi : lo;
        f.nearOrigin[a] = _mm256_set1_ps(positive ? loMax : hiMin);
        f.farOrigin[a] = _mm256_set1_ps(positive ? hiMin : loMax);
        f.inverseSmall[a] = _mm256_set1_ps(inverseMin);
        f.inverseLarge[a] = _mm256_set1_ps(inverseMax);
    }
    f.valid = true;
    return f;
}

// The slots of `node` some ray of the packet may enter before `limit` (the largest lane's).
inline uint32_t frustumSlots(const PacketFrustum& f, const WideBvhNode& node, __m256 limit) {
    const char* bytes = reinterpret_cast<const char*>(&node);
    __m256 nearest[3], farthest[3];
    for (int a = 0; a < 3; ++a) {
        const __m256 d = _mm256_sub_ps(_mm256_load_ps(reinterpret_cast<const float*>(bytes + f.nearPlane[a])),
                                       f.nearOrigin[a]);
        const __m256 e = _mm256_sub_ps(_mm256_load_ps(reinterpret_cast<const float*>(bytes + f.farPlane[a])),
                                       f.farOrigin[a]);
        nearest[a] = _mm256_min_ps(_mm256_mul_ps(d, f.inverseSmall[a]), _mm256_mul_ps(d, f.inverseLarge[a]));
        farthest[a] = _mm256_max_ps(_mm256_mul_ps(e, f.inverseSmall[a]), _mm256_mul_ps(e, f.inverseLarge[a]));
    }
    const __m256 tNear =
        _mm256_max_ps(_mm256_max_ps(nearest[0], nearest[1]), _mm256_max_ps(nearest[2], _mm256_setzero_ps()));
    const __m256 tFar = _mm256_mul_ps(_mm256_min_ps(farthest[0], _mm256_min_ps(farthest[1], farthest[2])),
                                      _mm256_set1_ps(kSlabExitScale));
    const __m256i unused = _mm256_cmpeq_epi32(_mm256_load_si256(reinterpret_cast<const __m256i*>(node.count)),
                                              _mm256_set1_epi32(int(WideBvhNode::kEmpty)));
    return uint32_t(_mm256_movemask_ps(_mm256_andnot_ps(
        _mm256_castsi256_ps(unused), _mm256_cmp_ps(tNear, _mm256_min_ps(tFar, limit), _CMP_LE_OQ))));
}

// An entry of the packet walk: a node (count 0) or a leaf, and per lane where that lane's ray
// enters it, NaN for lanes that do not (a comparison with NaN is false, so they stay out).
struct alignas(32) PacketEntry {
    __m256 entry;
    uint32_t child, count;
};

using Leaf = TriangleBlockLeaf<NoTraversalCount>;

// Asks for an entry's bytes ahead of their use: a node's four cache lines, or a leaf's blocks.
inline void prefetchEntry(const WideBvhNode* nodes, const TriangleBlock* blocks, uint32_t child,
                          uint32_t count) {
    const char* bytes = count == 0 ? reinterpret_cast<const char*>(nodes + child)
                                   : reinterpret_cast<const char*>(blocks + child);
    const uint32_t size = count == 0 ? uint32_t(sizeof(WideBvhNode))
                                     : (count + TriangleBlock::kWidth - 1) / TriangleBlock::kWidth *
                                           uint32_t(sizeof(TriangleBlock));
    for (uint32_t offset = 0; offset < size; offset += 64) _mm_prefetch(bytes + offset, _MM_HINT_T0);
}

// For `anyHit` (the leaves' too) a lane that finds a hit is done: its tMax goes to -infinity, so
// that it reaches nothing more, and the walk ends when every lane is done.
uint32_t walkPacket(const WideBvhNode* nodes, uint32_t root, const TraversalRay* rays, uint32_t lanes,
                    float* tMax, Leaf* leaves, bool anyHit) {
    const PacketSlabRays slab = packetSlabRays(rays);
    const __m256 nan = _mm256_set1_ps(std::numeric_limits<float>::quiet_NaN());
    const __m256 inf = _mm256_set1_ps(kInf), exitScale = _mm256_set1_ps(kSlabExitScale);
    const __m256 rootLanes = laneMask(lanes);
    const PacketFrustum frustum = packetFrustum(slab, rootLanes);
    PacketEntry stack[kWideStackSize];
    uint32_t size = 0;
    PacketEntry current{_mm256_blendv_ps(nan, _mm256_setzero_ps(), rootLanes), root, 0};
    uint32_t found = 0;
    const auto laneFound = [&](uint32_t lane) {
        found |= 1u << lane;
        if (anyHit) tMax[lane] = -kInf;
    };
    for (;;) {
        if (anyHit && found == lanes) return found;
        // The lanes that still reach the entry: as the single-ray walk drops an entry beyond
        // tMax * kSlabExitScale, each lane drops it beyond its own.
        const __m256 limit = _mm256_mul_ps(_mm256_loadu_ps(tMax), exitScale);
        const __m256 reach = _mm256_cmp_ps(current.entry, limit, _CMP_LE_OQ);
        uint32_t active = uint32_t(_mm256_movemask_ps(reach));
        if (active != 0 && current.count > 0) {
            for (; active != 0; active &= active - 1) {
                const uint32_t lane = uint32_t(__builtin_ctz(active));
                if (leaves[lane](current.child, current.count, tMax[lane])) laneFound(lane);
            }
        } else if (active != 0 && uint32_t(__builtin_popcount(active)) <= kAloneLanes) {
            for (; active != 0; active &= active - 1) {
                const uint32_t lane = uint32_t(__builtin_ctz(active));
                if ((walkWideBvh)(nodes, current.child, rays[lane], tMax[lane], leaves[lane],
                                  NoTraversalCount{}, anyHit))
                    laneFound(lane);
            }
        } else if (active != 0) {
            const WideBvhNode& node = nodes[current.child];
            __m256 entries[WideBvhNode::kWidth];
            float nearest[WideBvhNode::kWidth];
            uint32_t order[WideBvhNode::kWidth], n = 0;
            uint32_t slots =
                frustum.valid ? frustumSlots(frustum, node, _mm256_set1_ps(largestLane(limit))) : kAllSlots;
            for (; slots != 0; slots &= slots - 1) {
                const uint32_t slot = uint32_t(__builtin_ctz(slots));
                if (node.count[slot] == WideBvhNode::kEmpty) break;
                __m256 tNear;
                const __m256 enters = _mm256_and_ps(entersSlot(slab, node, slot, limit, tNear), reach);
                if (_mm256_movemask_ps(enters) == 0) continue;
                prefetchEntry(nodes, leaves[0].blocks, node.child[slot], node.count[slot]);
                entries[slot] = _mm256_blendv_ps(nan, tNear, enters);
                nearest[slot] = smallestLane(_mm256_blendv_ps(inf, tNear, enters));
                // Farthest first (insertion sort by the nearest lane's entry), as the single-ray
                // walk orders its children: all but the nearest go on the stack.
                uint32_t at = n++;
                while (at > 0 && nearest[order[at - 1]] < nearest[slot]) {
                    order[at] = order[at - 1];
                    --at;
                }
                order[at] = slot;
            }
            if (n != 0) {
                assert(size + n - 1 <= kWideStackSize && "BVH deeper than the wide traversal stack");
                for (uint32_t i = 0; i + 1 < n; ++i) {
                    const uint32_t slot = order[i];
                    stack[size++] = {entries[slot], node.child[slot], node.count[slot]};
                }
                const uint32_t slot = order[n - 1];
                current = {entries[slot], node.child[slot], node.count[slot]};
                continue;
            }
        }
        if (size == 0) return found;
        current = stack[--size];
    }
}

// The binary TLAS walked by the packet: a node's two boxes against the eight rays, the child
// whose nearest lane enters first taken first; each leaf goes to `visit` with the lanes that
// reach it, and tMax is read again after it.
void walkTlasPacket(const BvhNode* nodes, const TraversalRay* rays, uint32_t lanes, const float* tMax,
                    simd_detail::TlasLeafVisit visit, void* context) {
    struct alignas(32) Entry {
        __m256 entry;  // per lane, NaN where the lane does not enter
        uint32_t node;
    };
    const PacketSlabRays slab = packetSlabRays(rays);
    const __m256 nan = _mm256_set1_ps(std::numeric_limits<float>::quiet_NaN());
    const __m256 inf = _mm256_set1_ps(kInf), exitScale = _mm256_set1_ps(kSlabExitScale);
    Entry stack[kBvhStackSize];
    uint32_t size = 0;
    __m256 tNear;
    const __m256 rootEnters = _mm256_and_ps(
        entersNode(slab, nodes[0], _mm256_mul_ps(_mm256_loadu_ps(tMax), exitScale), tNear), laneMask(lanes));
    Entry current{_mm256_blendv_ps(nan, tNear, rootEnters), 0};
    for (;;) {
        const __m256 limit = _mm256_mul_ps(_mm256_loadu_ps(tMax), exitScale);
        const __m256 reach = _mm256_cmp_ps(current.entry, limit, _CMP_LE_OQ);
        const uint32_t active = uint32_t(_mm256_movemask_ps(reach));
        const BvhNode& node = nodes[current.node];
        if (active != 0 && node.isLeaf()) {
            visit(context, node.leftOrFirst, node.count, active);
        } else if (active != 0) {
            __m256 nearLeft, nearRight;
            const uint32_t left = node.leftOrFirst;
            const __m256 entersLeft = _mm256_and_ps(entersNode(slab, nodes[left], limit, nearLeft), reach);
            const __m256 entersRight =
                _mm256_and_ps(entersNode(slab, nodes[left + 1], limit, nearRight), reach);
            const bool hitLeft = _mm256_movemask_ps(entersLeft) != 0,
                       hitRight = _mm256_movemask_ps(entersRight) != 0;
            const Entry leftEntry{_mm256_blendv_ps(nan, nearLeft, entersLeft), left};
            const Entry rightEntry{_mm256_blendv_ps(nan, nearRight, entersRight), left + 1};
            if (hitLeft && hitRight) {
                assert(size < kBvhStackSize && "TLAS deeper than the traversal stack");
                const bool leftFirst = smallestLane(_mm256_blendv_ps(inf, nearLeft, entersLeft)) <=
                                       smallestLane(_mm256_blendv_ps(inf, nearRight, entersRight));
                stack[size++] = leftFirst ? rightEntry : leftEntry;
                current = leftFirst ? leftEntry : rightEntry;
                continue;
            }
            if (hitLeft || hitRight) {
                current = hitLeft ? leftEntry : rightEntry;
                continue;
            }
        }
        if (size == 0) return;
        current = stack[--size];
    }
}

}  // namespace
}  // namespace avx2

void simd_detail::walkTlasPacketAvx2(const BvhNode* nodes, const TraversalRay* rays, uint32_t lanes,
                                     const float* tMax, TlasLeafVisit visit, void* context) {
    avx2::walkTlasPacket(nodes, rays, lanes, tMax, visit, context);
}

uint32_t simd_detail::walkTriangleWidePacketAvx2(const WideBvhNode* nodes, uint32_t root,
                                                 const TriangleBlock* blocks, const TraversalRay* rays,
                                                 uint32_t lanes, float* tMax, Hit* hits, bool anyHit) {
    static_assert(kRayPacketSize == 8, "one leaf functor a lane, listed below");
    avx2::Leaf leaves[kRayPacketSize] = {
        {blocks, rays[0], hits[0], {}, anyHit}, {blocks, rays[1], hits[1], {}, anyHit},
        {blocks, rays[2], hits[2], {}, anyHit}, {blocks, rays[3], hits[3], {}, anyHit},
        {blocks, rays[4], hits[4], {}, anyHit}, {blocks, rays[5], hits[5], {}, anyHit},
        {blocks, rays[6], hits[6], {}, anyHit}, {blocks, rays[7], hits[7], {}, anyHit}};
    return avx2::walkPacket(nodes, root, rays, lanes, tMax, leaves, anyHit);
}

}  // namespace pt

#include "render/bvh/avx2_target_end.h"
