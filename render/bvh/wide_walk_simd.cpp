#include "render/bvh/wide_walk_simd.h"

#include <atomic>
#include <stdexcept>
#include <string>

#include "render/bvh/wide_walk.h"

namespace pt {

namespace {

// The level alone is stored (the walk follows from it at each call), so a change is one store.
std::atomic<SimdLevel>& chosenLevel() {
    static std::atomic<SimdLevel> level{supportedSimdLevel()};
    return level;
}

}  // namespace

const char* simdLevelName(SimdLevel level) { return level == SimdLevel::Avx2 ? "AVX2" : "SSE2"; }

SimdLevel supportedSimdLevel() {
    // libgcc's cpuid check also asks the OS (XGETBV) whether it saves the 256-bit registers.
    __builtin_cpu_init();
    // The AVX2 node test takes its plane distances as fused multiply-adds (wide_walk_avx2.h):
    // every AVX2 processor made has FMA3, but a virtual machine may show one without the other.
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") ? SimdLevel::Avx2
                                                                           : SimdLevel::Sse2;
}

SimdLevel wideWalkSimdLevel() { return chosenLevel().load(std::memory_order_relaxed); }

void setWideWalkSimdLevel(SimdLevel level) {
    if (level == SimdLevel::Avx2 && supportedSimdLevel() != SimdLevel::Avx2) {
        throw std::invalid_argument(std::string("this processor does not run ") + simdLevelName(level));
    }
    chosenLevel().store(level);
}

bool walkTriangleWideBvh(const WideBvhNode* nodes, uint32_t root, const TriangleBlock* blocks,
                         const TraversalRay& ray, float& tMax, Hit& hit, TraversalStats* stats, bool anyHit) {
    return wideWalkSimdLevel() == SimdLevel::Avx2
               ? simd_detail::walkTriangleWideBvhAvx2(nodes, root, blocks, ray, tMax, hit, stats, anyHit)
               : simd_detail::walkTriangleWideBvhSse2(nodes, root, blocks, ray, tMax, hit, stats, anyHit);
}

namespace simd_detail {

bool walkTriangleWideBvhSse2(const WideBvhNode* nodes, uint32_t root, const TriangleBlock* blocks,
                             const TraversalRay& ray, float& tMax, Hit& hit, TraversalStats* stats,
                             bool anyHit) {
    return walkTriangleBlocks(nodes, root, blocks, ray, tMax, hit, stats, anyHit);
}

int intersectWideNodeSse2(const WideBvhNode& node, const TraversalRay& ray, float tMax, float* entry) {
    alignas(16) float entries[WideBvhNode::kWidth];
    const int hits = intersectWideNode(wideSlabRay(ray), node, tMax, entries);
    for (uint32_t s = 0; s < WideBvhNode::kWidth; ++s) entry[s] = entries[s];
    return hits;
}

}  // namespace simd_detail

}  // namespace pt
