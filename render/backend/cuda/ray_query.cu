// Traversal alone over a batch of rays: what benchmarks time as Mrays/s and picking asks.
#include "render/backend/cuda/cuda_check.h"
#include "render/backend/cuda/persistent_grid.cuh"
#include "render/backend/cuda/register_cap.cuh"
#include "render/backend/cuda/wavefront_kernels.h"
#include "render/bvh/traversal.h"

namespace pt::cuda {

namespace {

constexpr uint32_t kBlock = 128;

// The traversal code a scene needs (feature_set.h), as the path kernels' variants choose theirs
// (kernel_variants.h): a scene of one instance walks its BLAS without a TLAS. A kernel's
// registers are those of its heaviest path, and the TLAS walk keeps its own state live under
// every BLAS walk: the generic kernel took 108 registers (ptxas, sm_90) where the one-instance
// kernel took 72 (closest hit; 70 for any hit), so timing a one-instance scene with it measured
// the TLAS, not the walk (H200, 1080p, 1M-triangle sphere, Mrays/s primary / diffuse / shadow:
// 2231 / 1197 / 167 with the generic kernel, 2895 / 1527 / 1036 with this one). Instanced
// scenes keep the generic kernel: one for them without the brute-force loop took as many
// registers but traced Balloon's shadow rays slower (206 against 243 Mrays/s; camera and
// diffuse rays alike).
constexpr FeatureSet kSingleInstanceTraversal =
    kAllFeatures & ~(feature::kMultipleInstances | feature::kBruteForce);

// Registers a thread (register_cap.cuh), and a persistent grid (persistent_grid.cuh).
// Uncapped, the one-instance kernel took 79 registers (closest hit; 6 blocks of 128 an SM) and
// the generic one 114. H200, bench's rays, medians of 7 launches, Mrays/s, camera / diffuse /
// shadow rays, one ray a thread uncapped, then persistent and capped (64 and 72):
//   1M-triangle sphere, 1080p, compressed walk: 2869-2883 / 1717-1727 / 1309-1311 to 3176-3177 /
//   1825-1827 / 1444-1453 (capped alone: 2971-2986 / 1784-1785 / 1396-1397; persistent alone:
//   3157 / 1793-1795 / 1443-1456); its binary walk: 2564-2572 / 1467-1479 / 997-1003 to
//   2956-2963 / 1646-1658 / 1061-1074;
//   64 instances of a 200k-triangle sphere, 720p, compressed walk: 3292-3299 / 144 / 303-305
//   to 3465-3700 / 221-231 / 271-274; binary walk: 2558-2573 / 119 / 174-178 to 2832-2900 /
//   163-165 / 172-178 (its diffuse and shadow sets are small, 53,028 and 40,177 rays).
// The generic kernel spilled at 64 registers: one ray a thread, 3290-3448 camera rays a second
// against 3563-3581 at 72 on the field.
//
// Tried and dropped: dynamic fetch (Aila and Laine 2009, section 4), where a thread whose ray is
// done takes another while its warp walks on: the warp stepped its threads' walks one node at
// a time and claimed rays for the idle ones once fewer than N of them held a ray. On the 1M
// sphere (H200, 1080p, compressed walk, two rounds, Mrays/s camera / diffuse / shadow) it was
// slower at every N: 2480-2520 / 1498-1548 / 1195-1221 at N = 20 and 24, 2061-2082 /
// 1244-1247 / 1081-1097 at 32, against 2991-2998 / 1710-1716 / 1372-1377 for this kernel on
// the same stepped walk (3182 / 1818 / 1424 on the walk as it is, which stepping slowed). ncu:
// active threads a warp 18.7 against 19.1 on camera rays (so the idle threads were not ones
// whose rays had ended) and 15.5 against 13.7 on diffuse rays, but the walk's
// state, carried from step to step, went through local memory (19M spill requests a launch at
// 64 registers; at 72 it was no faster).
//
// Tried and dropped: the compressed walk's stack in shared memory, as Ylitie et al. keep theirs:
// its bottom K entries in a row a thread of a 128-thread block (K * 1 KB a block), the rest
// in local memory as before. On the 1M sphere (H200, 1080p, two rounds, Mrays/s camera /
// diffuse / shadow) it was no faster at any K: 3125-3163 / 1785-1792 / 1418-1432 at K = 8,
// 3130-3139 / 1775-1788 / 1422-1448 at 4, 3119-3129 / 1765-1787 / 1424-1439 at 12, against
// 3188-3197 / 1801-1817 / 1425-1439 with the stack in local memory, which L1 holds; on the
// 64-instance field (720p) 3497 / 219 / 258 at K = 8 against 3624 / 229 / 275.
template <FeatureSet kF>
constexpr uint32_t kRayRegisters = (kF & feature::kMultipleInstances) ? 72u : 64u;

template <FeatureSet kF, bool kAnyHit>
__global__ void __launch_bounds__(kBlock, blocksPerSmFor(kBlock, kRayRegisters<kF>))
    traceRaysKernel(RenderScene scene, const Ray* rays, uint32_t count, Hit* hits, WorkClaims* claims) {
    forClaimedItems(claims, count, [&](uint32_t i) {
        const Ray ray = rays[i];
        Hit hit;
        if (kAnyHit) {
            hit = Hit{};
            hit.instance = intersectAny<kF>(scene, ray) ? 0u : Hit::kNoHit;
        } else {
            intersectClosest<kF>(scene, ray, hit);
        }
        hits[i] = hit;
    });
}

template <FeatureSet kF, bool kAnyHit>
void launchFor(const RenderScene& scene, const Ray* rays, uint32_t count, Hit* hits, WorkClaims* claims,
               cudaStream_t stream) {
    launchPersistent<traceRaysKernel<kF, kAnyHit>, kBlock>(count, stream, scene, rays, count, hits, claims);
}

template <FeatureSet kF>
void launchWith(const RenderScene& scene, const Ray* rays, uint32_t count, bool anyHit, Hit* hits,
                WorkClaims* claims, cudaStream_t stream) {
    if (anyHit) {
        launchFor<kF, true>(scene, rays, count, hits, claims, stream);
    } else {
        launchFor<kF, false>(scene, rays, count, hits, claims, stream);
    }
    PT_CUDA_CHECK_LAUNCH("traceRaysKernel");
}

}  // namespace

void launchTraceRays(const RenderScene& scene, const Ray* rays, uint32_t count, bool anyHit, Hit* hits,
                     WorkClaims* claims, cudaStream_t stream) {
    if (count == 0) return;
    if (scene.bruteForce || scene.instances.count > 1) {
        launchWith<kAllFeatures>(scene, rays, count, anyHit, hits, claims, stream);
    } else {
        launchWith<kSingleInstanceTraversal>(scene, rays, count, anyHit, hits, claims, stream);
    }
}

}  // namespace pt::cuda
