// HplocBuilder::build (gpu_bvh.h): Benthin et al., HPG 2024. Passes, queued on the caller's
// stream:
//   1. keys sorted by the Morton code of the box centres (MortonSort)
//   2. one kernel, a thread a primitive: the primitive's leaf cluster, then up the LBVH of the
//      keys, as Apetrei builds it bottom-up: at each node the thread of the child that arrives
//      second goes on with the node's range, the first stops. Where a node spans more than
//      kHplocThreshold positions, its warp loads the clusters its two children kept (a lane
//      each: at most kHplocThreshold a child), merges them by PLOC, each with its least-cost
//      neighbour among kHplocRadius lanes on either side wherever the choice is mutual, until
//      kHplocThreshold are left (one at the root), and writes them over its range's first
//      positions.
// Merges write their two clusters as nodes into fresh slot pairs, as PLOC's rounds do
// (ploc_clusters.cuh), so siblings are adjacent and the root is node 0.
#include <stdexcept>
#include <string>

#include "render/backend/cuda/bvh_bottom_up.cuh"
#include "render/backend/cuda/gpu_bvh.h"
#include "render/backend/cuda/ploc_clusters.cuh"

namespace pt::cuda {

namespace {

constexpr int kWarpSize = 32;
constexpr uint32_t kFullWarp = 0xffffffffu;
constexpr uint32_t kNoSibling = ~0u;
static_assert(2 * kHplocThreshold <= kWarpSize, "a node's clusters must fit its warp, one a lane");
static_assert(kHplocRadius < kWarpSize, "neighbours are other lanes");
static_assert(kBvhBlockSize % kWarpSize == 0, "whole warps: the votes and shuffles name every lane");

// Apetrei's distance at split i, between sorted keys i and i + 1: their XOR, whose highest bit
// is the level of the radix tree node that splits there. Keys are unique, so it is never 0.
__device__ __forceinline__ uint64_t splitDistance(const uint64_t* keys, uint32_t i) {
    return keys[i] ^ keys[i + 1];
}

__device__ __forceinline__ uint32_t lanesBelow(int lane) { return (1u << lane) - 1u; }

// A warp's shared memory for moving clusters between lanes.
struct WarpClusters {
    float4 low[kWarpSize], high[kWarpSize];
};

// The clusters of the lanes in `kept`, moved in order to lanes 0, 1, ...; returns how many. They
// stay in `scratch` too, at the same lanes, for the neighbour search to read, until the next
// compact.
__device__ __forceinline__ int compact(ClusterWords& c, uint32_t kept, int lane, WarpClusters& scratch) {
    __syncwarp();  // every lane has read the scratch (here or in the search) before it is rewritten
    if (kept >> lane & 1u) {
        const int to = __popc(kept & lanesBelow(lane));
        scratch.low[to] = c.low;
        scratch.high[to] = c.high;
    }
    __syncwarp();
    const int n = __popc(kept);
    if (lane < n) c = {scratch.low[lane], scratch.high[lane]};
    return n;
}

// The lane whose cluster is the least-cost neighbour of this lane's among the `n` clusters in
// lanes 0..n-1, within kHplocRadius; -1 for lanes from n on. `scratch` holds the same n
// clusters, as compact left them: a neighbour's box is two shared-memory loads where shuffling
// it took six shuffles (1M boxes on an H200: 0.83 -> 0.80 ms a build). Each pair's cost is
// computed once, by its lower lane, and handed to the upper, so both ends compare the same value.
__device__ __forceinline__ int nearestInWarp(const ClusterWords& c, const WarpClusters& scratch, int lane,
                                             int n) {
    int best = -1;
    float bestCost = INFINITY;
    for (int d = 1; d <= kHplocRadius; ++d) {
        const bool hasAbove = lane + d < n;
        const float above =
            hasAbove ? unionCost(c.low, c.high, scratch.low[lane + d], scratch.high[lane + d]) : INFINITY;
        const float below = __shfl_up_sync(kFullWarp, above, d);  // the pair (lane - d, lane)
        if (lane < n && lane >= d && betterNeighbour(lane, lane - d, below, best, bestCost)) {
            best = lane - d;
            bestCost = below;
        }
        if (hasAbove && betterNeighbour(lane, lane + d, above, best, bestCost)) {
            best = lane + d;
            bestCost = above;
        }
    }
    return best;
}

// The warp merges the clusters of the LBVH node over sorted positions [first, last], split
// after `split` (the same on every lane), until at most kHplocThreshold are left, and writes
// them over the range's first kHplocThreshold positions, empty ones after them; the root merges
// to one and writes it as node 0, its height to counters[kRootHeight].
__device__ void mergeNode(uint32_t first, uint32_t split, uint32_t last, uint32_t count, BvhNode* clusters,
                          const MergeOutput& out, uint32_t* counters, int lane, WarpClusters& scratch) {
    // A child over more than kHplocThreshold positions kept at most that many clusters, first in
    // its range; a smaller child is still its leaves. The left child's go to lanes from 0, the
    // right child's to lanes from kHplocThreshold.
    const uint32_t leftLoad = min(split + 1 - first, uint32_t(kHplocThreshold));
    const uint32_t rightLoad = min(last - split, uint32_t(kHplocThreshold));
    const uint32_t slotInChild = uint32_t(lane % kHplocThreshold);
    const bool leftLane = lane < kHplocThreshold;
    const bool loads = slotInChild < (leftLane ? leftLoad : rightLoad);
    ClusterWords c{};
    if (loads) c = loadClusterCoherent(clusters, int((leftLane ? first : split + 1) + slotInChild));
    int n = compact(c, __ballot_sync(kFullWarp, loads && c.count() != 0), lane, scratch);

    const bool root = first == 0 && last == count - 1;
    const int target = root ? 1 : kHplocThreshold;
    while (n > target) {
        const int best = nearestInWarp(c, scratch, lane, n);
        const int from = best < 0 ? lane : best;
        // Every lane takes part: a full-mask shuffle that some lanes skip (as the short-circuit
        // `best >= 0 && __shfl_sync(...)` did, for the lanes past the clusters) is undefined
        // behaviour; the first run on a GPU hung in it.
        const int fromBest = __shfl_sync(kFullWarp, best, from);
        const bool mutual = best >= 0 && fromBest == lane;
        // The least-cost pair is mutual (tieOrder makes the order on pairs total), so every
        // pass merges at least once and `merging` is never empty.
        const uint32_t merging = __ballot_sync(kFullWarp, mutual && lane < best);
        if (merging == 0) {  // cannot happen (above); counted, so build throws rather than hangs
            if (lane == 0) atomicAdd(counters + kStalls, 1u);
            break;
        }
        const int leader = __ffs(merging) - 1;
        uint32_t base = 0;
        if (lane == leader) base = 1u + atomicAdd(counters + kNextSlot, 2u * uint32_t(__popc(merging)));
        base = __shfl_sync(kFullWarp, base, leader);
        if (mutual && lane < best)
            c = mergeClusters(c, {scratch.low[best], scratch.high[best]}, out,  // the partner, as compacted
                              base + 2u * __popc(merging & lanesBelow(lane)));
        n = compact(c, __ballot_sync(kFullWarp, lane < n && !(mutual && lane > best)), lane, scratch);
    }
    if (root) {
        if (lane == 0) {
            storeAsNode(out, 0, c);
            counters[kRootHeight] = c.height();
        }
        return;
    }
    if (lane < kHplocThreshold) storeCluster(clusters + first + lane, lane < n ? c : ClusterWords{});
}

__global__ void __launch_bounds__(kBvhBlockSize)
    hplocKernel(const Aabb* boxes, const uint64_t* keys, uint32_t count, BvhNode* clusters,
                uint32_t* primIndices, uint32_t* siblingBounds, MergeOutput out, uint32_t* counters) {
    __shared__ WarpClusters scratch[kBvhBlockSize / kWarpSize];
    const int lane = int(threadIdx.x) % kWarpSize;
    WarpClusters& warpScratch = scratch[threadIdx.x / kWarpSize];
    const uint32_t q = blockIdx.x * blockDim.x + threadIdx.x;
    uint32_t first = q, last = q, split = 0;
    bool climbing = q < count;
    if (climbing) storeCluster(clusters + q, leafCluster(boxes, keys[q], q, primIndices));
    bool wrote = true;  // this warp wrote clusters not yet fenced
    while (__any_sync(kFullWarp, climbing)) {
        // Release: every lane's clusters are visible before any lane's arrival below is, so the
        // thread that arrives second at a node, in whatever block, reads its sibling's clusters.
        // Other lanes of the warp stored a merged node's clusters (mergeNode); the warp barrier
        // orders their stores before this lane's fence and exchange (the votes and shuffles
        // order no memory). `wrote` is the same in every lane.
        if (wrote) {
            __syncwarp();
            __threadfence();
        }
        bool merge = false;
        if (climbing) {
            // The parent splits at the end of the range whose neighbouring keys differ in a lower
            // bit (Apetrei 2014); at the first or last key, at the other end.
            const bool goRight = first == 0 || (last + 1 < count &&
                                                splitDistance(keys, last) < splitDistance(keys, first - 1));
            split = goRight ? last : first - 1;
            const uint32_t sibling = atomicExch(siblingBounds + split, goRight ? first : last);
            if (sibling == kNoSibling) {
                climbing = false;  // the sibling's thread will go on
            } else {
                if (goRight)
                    last = sibling;
                else
                    first = sibling;
                __threadfence();  // acquire: the sibling's clusters, written before its arrival
                merge = last - first + 1 > uint32_t(kHplocThreshold) || (first == 0 && last == count - 1);
            }
        }
        const uint32_t merges = __ballot_sync(kFullWarp, merge);
        // Acquire for the warp: each owner's fence above comes before every lane's loads of the
        // sibling's clusters in mergeNode.
        if (merges != 0) __syncwarp();
        for (uint32_t pending = merges; pending != 0; pending &= pending - 1) {
            const int owner = __ffs(pending) - 1;
            mergeNode(__shfl_sync(kFullWarp, first, owner), __shfl_sync(kFullWarp, split, owner),
                      __shfl_sync(kFullWarp, last, owner), count, clusters, out, counters, lane, warpScratch);
        }
        wrote = merges != 0;
        if (first == 0 && last == count - 1) climbing = false;  // the root is done
    }
}

}  // namespace

void HplocBuilder::reserve(uint32_t count) {
    if (count <= capacity_) return;
    const uint32_t capacity = grownCapacity(count, capacity_);
    clusters_.resize(capacity);
    siblingBounds_.resize(capacity);
    counters_.resize(kPlocCounters);
    choices_.resize(lbvhNodeCount(capacity));
    pairCosts_.resize(capacity);
    capacity_ = capacity;
}

void HplocBuilder::release() {
    morton_.release();
    clusters_ = {};
    siblingBounds_ = {};
    counters_ = {};
    choices_ = {};
    pairCosts_ = {};
    fallback_.release();
    choicesValid_ = false;
    capacity_ = 0;
}

void HplocBuilder::build(const Aabb* boxes, uint32_t count, BvhNode* nodes, uint32_t* primIndices,
                         cudaStream_t stream) {
    fellBack_ = false;
    choicesValid_ = false;
    depth_ = 0;
    if (count <= 1) {  // the empty root or a single leaf, as the LBVH makes them
        fallback_.build(boxes, count, nodes, primIndices, stream);
        return;
    }
    reserve(count);
    const uint64_t* sorted = morton_.sort(boxes, count, stream);
    PT_CUDA_CHECK(cudaMemsetAsync(siblingBounds_.data(), 0xFF, (count - 1) * sizeof(uint32_t), stream));
    PT_CUDA_CHECK(cudaMemsetAsync(counters_.data(), 0, kPlocCounters * sizeof(uint32_t), stream));
    const MergeOutput out{nodes, {choices_.data(), pairCosts_.data()}};
    hplocKernel<<<bvhBlocks(count), kBvhBlockSize, 0, stream>>>(
        boxes, sorted, count, clusters_.data(), primIndices, siblingBounds_.data(), out, counters_.data());
    PT_CUDA_CHECK_LAUNCH("hplocKernel");
    uint32_t counters[kPlocCounters];
    PT_CUDA_CHECK(
        cudaMemcpyAsync(counters, counters_.data(), sizeof(counters), cudaMemcpyDeviceToHost, stream));
    PT_CUDA_CHECK(cudaStreamSynchronize(stream));
    depth_ = counters[kRootHeight];
    // n - 1 merges, two slots each, after the root's slot 0: any other count is a broken tree
    // (and writes past `nodes`), which must not pass silently.
    if (counters[kNextSlot] != 2 * (count - 1) || counters[kStalls] != 0) {
        throw std::logic_error("H-PLOC handed out " + std::to_string(counters[kNextSlot]) +
                               " node slots for " + std::to_string(count) + " primitives (" +
                               std::to_string(2 * (count - 1)) + " expected); " +
                               std::to_string(counters[kStalls]) + " merge passes found no pair");
    }
    if (depth_ > kGpuBvhMaxDepth) {
        fallback_.buildFromSortedKeys(boxes, sorted, count, nodes, primIndices, stream);
        fellBack_ = true;
        return;
    }
    choicesValid_ = true;
}

}  // namespace pt::cuda
