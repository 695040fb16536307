// PlocBuilder::build (gpu_bvh.h): Meister and Bittner 2018. Passes, queued on the caller's
// stream:
//   1. keys sorted by the Morton code of the box centres (MortonSort)
//   2. one cluster a primitive, in that order: the leaf it will become
//   3. rounds while more clusters are left than one block holds, each one kernel (as PLOC++,
//      Benthin et al. 2022, fuses them): every cluster's nearest neighbour among kPlocRadius on
//      either side (the least surface area of the union), then every mutual pair merged into a
//      new cluster at the lower index; then the clusters merged away compacted out
//      (cub::DeviceSelect). The count stays on the device: the rounds are launched over the
//      last count read back, which is read again every kRoundsPerReadBack rounds
//   4. the last rounds in one block, in shared memory (a round of a few hundred clusters would
//      cost more in launches than in work)
// A merge writes its two clusters as nodes into a pair of fresh slots and becomes an interior
// cluster pointing at them, so siblings are adjacent without a renumbering pass; the last
// cluster is the root, node 0.
#include <algorithm>
#include <cub/block/block_scan.cuh>
#include <cub/device/device_select.cuh>

#include "render/backend/cuda/bvh_bottom_up.cuh"
#include "render/backend/cuda/gpu_bvh.h"
#include "render/backend/cuda/ploc_clusters.cuh"

namespace pt::cuda {

namespace {

// The clusters the last rounds take in one block.
constexpr int kFinishClusters = 1024;
// Rounds between read-backs of the cluster count. Each read-back waits for the stream (about
// 15 us); the rounds between launch over the count last read, which shrinks about 11% a round
// on a million triangles, and blocks past the current count exit at once.
constexpr int kRoundsPerReadBack = 3;

// The index of cluster i's nearest neighbour among the `count` of the round (count >= 2),
// `clusterAt(k)` giving cluster k.
template <class ClusterAt>
__device__ __forceinline__ int nearestNeighbour(int i, int count, const ClusterAt& clusterAt) {
    const ClusterWords mine = clusterAt(i);
    const int first = max(i - kPlocRadius, 0), last = min(i + kPlocRadius, count - 1);
    int best = -1;
    float bestCost = INFINITY;
    for (int j = first; j <= last; ++j) {
        if (j == i) continue;
        const float cost = unionCost(mine, clusterAt(j));
        if (betterNeighbour(i, j, cost, best, bestCost)) {
            bestCost = cost;
            best = j;
        }
    }
    return best;
}

// Cluster i's part in its round's merges, given its neighbour j: a mutual pair is merged by
// its lower end (its two clusters written as nodes into fresh slots of `out`, the slot from
// `nextSlot`), and dropped by its higher end; any other cluster goes on as it is. Returns
// whether cluster i goes on, as `next`.
__device__ __forceinline__ bool mergeStep(int i, int j, bool mutual, const ClusterWords& mine,
                                          const ClusterWords& neighbour, const MergeOutput& out,
                                          uint32_t* nextSlot, ClusterWords& next) {
    if (!mutual) {
        next = mine;
        return true;
    }
    if (i > j) return false;
    next = mergeClusters(mine, neighbour, out, atomicAdd(nextSlot, 2u));
    return true;
}

// Pass 2: the leaf cluster of the primitive at sorted position q, and its primIndices entry.
__global__ void leafClustersKernel(const Aabb* boxes, const uint64_t* sortedKeys, uint32_t count,
                                   BvhNode* clusters, uint32_t* primIndices, uint32_t* counters) {
    const uint32_t q = blockIdx.x * blockDim.x + threadIdx.x;
    if (q == 0) {
        counters[kNextSlot] = 1;  // slot 0 is the root's
        counters[kClustersLeft] = count;
    }
    if (q >= count) return;
    storeCluster(clusters + q, leafCluster(boxes, sortedKeys[q], q, primIndices));
}

// Pass 3: one round over the clusters counters[kClustersLeft] holds (at most `bound`): the
// merged clusters into `merged` (at each cluster's index), and whether each goes on into `keep`
// (0 past the count, where the compaction still looks). A block finds the nearest neighbours of
// its clusters and of kPlocRadius on either side, whose choices its own mutual tests need,
// from its clusters and 2 kPlocRadius on either side, read into shared memory once.
constexpr int kRoundNeighbours = kBvhBlockSize + 2 * kPlocRadius;
constexpr int kRoundTile = kBvhBlockSize + 4 * kPlocRadius;
__global__ void __launch_bounds__(kBvhBlockSize)
    roundKernel(const BvhNode* clusters, uint32_t bound, uint32_t* counters, BvhNode* merged, uint8_t* keep,
                MergeOutput out) {
    __shared__ float4 low[kRoundTile], high[kRoundTile];
    __shared__ int32_t neighbour[kRoundNeighbours];
    const int count = int(counters[kClustersLeft]);
    const int blockStart = int(blockIdx.x * blockDim.x), i = blockStart + int(threadIdx.x);
    // The whole block has nothing to merge. (count < 2 does not happen while the host reads the
    // count back before it could: a round at most halves it, and the rounds run from over
    // kFinishClusters.)
    if (blockStart >= count || count < 2) {
        if (i < int(bound)) keep[i] = i < count ? 1 : 0;
        if (i < count) merged[i] = clusters[i];
        return;
    }
    const int tileStart = blockStart - 2 * kPlocRadius, neighboursStart = blockStart - kPlocRadius;
    for (int t = int(threadIdx.x); t < kRoundTile; t += kBvhBlockSize) {
        const int k = tileStart + t;
        if (k >= 0 && k < count) {
            const ClusterWords c = loadCluster(clusters, k);
            low[t] = c.low;
            high[t] = c.high;
        }
    }
    __syncthreads();
    const auto clusterAt = [&](int k) { return ClusterWords{low[k - tileStart], high[k - tileStart]}; };
    for (int t = int(threadIdx.x); t < kRoundNeighbours; t += kBvhBlockSize) {
        const int k = neighboursStart + t;
        if (k >= 0 && k < count) neighbour[t] = nearestNeighbour(k, count, clusterAt);
    }
    __syncthreads();
    if (i >= int(bound)) return;
    if (i >= count) {
        keep[i] = 0;
        return;
    }
    const int j = neighbour[i - neighboursStart];  // within kPlocRadius of i: in the block's range
    ClusterWords next;
    const bool goesOn = mergeStep(i, j, neighbour[j - neighboursStart] == i, clusterAt(i), clusterAt(j), out,
                                  counters + kNextSlot, next);
    if (goesOn) storeCluster(merged + i, next);
    keep[i] = goesOn ? 1 : 0;
}

// Pass 4: the rounds of the last counters[kClustersLeft] <= kFinishClusters clusters, in one
// block of kFinishClusters threads; the root to node 0 and its height to counters[kRootHeight].
__global__ void __launch_bounds__(kFinishClusters)
    finishKernel(const BvhNode* clusters, MergeOutput out, uint32_t* counters) {
    using Scan = cub::BlockScan<int, kFinishClusters>;
    __shared__ typename Scan::TempStorage scanStorage;
    __shared__ float4 low[kFinishClusters], high[kFinishClusters];
    __shared__ int32_t neighbour[kFinishClusters];
    const int t = int(threadIdx.x);
    int left = int(counters[kClustersLeft]);
    if (t < left) {
        const ClusterWords c = loadCluster(clusters, t);
        low[t] = c.low;
        high[t] = c.high;
    }
    __syncthreads();
    const auto clusterAt = [&](int k) { return ClusterWords{low[k], high[k]}; };
    while (left > 1) {
        if (t < left) neighbour[t] = nearestNeighbour(t, left, clusterAt);
        __syncthreads();
        ClusterWords next{};
        int goesOn = 0;
        if (t < left) {
            const int j = neighbour[t];
            goesOn = mergeStep(t, j, neighbour[j] == t, clusterAt(t), clusterAt(j), out, counters + kNextSlot,
                               next);
        }
        int position = 0, total = 0;
        Scan(scanStorage).ExclusiveSum(goesOn, position, total);
        __syncthreads();  // every thread has read the round's clusters and neighbours
        if (goesOn) {
            low[position] = next.low;
            high[position] = next.high;
        }
        left = total;
        __syncthreads();
    }
    if (t == 0) {
        const ClusterWords root = clusterAt(0);
        storeAsNode(out, 0, root);
        counters[kRootHeight] = root.height();
    }
}

}  // namespace

void PlocBuilder::reserve(uint32_t count) {
    if (count <= capacity_) return;
    const uint32_t capacity = grownCapacity(count, capacity_);
    clusters_.resize(capacity);
    merged_.resize(capacity);
    keep_.resize(capacity);
    counters_.resize(kPlocCounters);
    choices_.resize(lbvhNodeCount(capacity));
    pairCosts_.resize(capacity);
    size_t selectBytes = 0;
    PT_CUDA_CHECK(cub::DeviceSelect::Flagged(nullptr, selectBytes, merged_.data(), keep_.data(),
                                             clusters_.data(), counters_.data() + kClustersLeft, capacity));
    selectScratch_.resize(std::max<size_t>(selectBytes, 1));
    capacity_ = capacity;
}

void PlocBuilder::release() {
    morton_.release();
    clusters_ = {};
    merged_ = {};
    keep_ = {};
    selectScratch_ = {};
    counters_ = {};
    choices_ = {};
    pairCosts_ = {};
    fallback_.release();
    choicesValid_ = false;
    capacity_ = 0;
}

void PlocBuilder::build(const Aabb* boxes, uint32_t count, BvhNode* nodes, uint32_t* primIndices,
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
    const MergeOutput out{nodes, {choices_.data(), pairCosts_.data()}};
    leafClustersKernel<<<bvhBlocks(count), kBvhBlockSize, 0, stream>>>(boxes, sorted, count, clusters_.data(),
                                                                       primIndices, counters_.data());
    PT_CUDA_CHECK_LAUNCH("leafClustersKernel");
    uint32_t bound = count;  // the count last read back: no less than the count on the device
    while (bound > uint32_t(kFinishClusters)) {
        for (int round = 0; round < kRoundsPerReadBack; ++round) {
            roundKernel<<<bvhBlocks(bound), kBvhBlockSize, 0, stream>>>(
                clusters_.data(), bound, counters_.data(), merged_.data(), keep_.data(), out);
            PT_CUDA_CHECK_LAUNCH("roundKernel");
            size_t selectBytes = selectScratch_.bytes();
            PT_CUDA_CHECK(cub::DeviceSelect::Flagged(selectScratch_.data(), selectBytes, merged_.data(),
                                                     keep_.data(), clusters_.data(),
                                                     counters_.data() + kClustersLeft, bound, stream));
        }
        PT_CUDA_CHECK(cudaMemcpyAsync(&bound, counters_.data() + kClustersLeft, sizeof(bound),
                                      cudaMemcpyDeviceToHost, stream));
        PT_CUDA_CHECK(cudaStreamSynchronize(stream));
    }
    finishKernel<<<1, kFinishClusters, 0, stream>>>(clusters_.data(), out, counters_.data());
    PT_CUDA_CHECK_LAUNCH("finishKernel");
    PT_CUDA_CHECK(cudaMemcpyAsync(&depth_, counters_.data() + kRootHeight, sizeof(depth_),
                                  cudaMemcpyDeviceToHost, stream));
    PT_CUDA_CHECK(cudaStreamSynchronize(stream));
    if (depth_ > kGpuBvhMaxDepth) {
        fallback_.buildFromSortedKeys(boxes, sorted, count, nodes, primIndices, stream);
        fellBack_ = true;
        return;
    }
    choicesValid_ = true;
}

}  // namespace pt::cuda
