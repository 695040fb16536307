#include "render/bvh/sah_split.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cassert>
#include <utility>
#include <vector>

namespace pt::sah {

namespace {

constexpr uint32_t kParallelBinSize = 1u << 16;  // ranges this large bin in parallel
constexpr uint32_t kBinGrain = 1u << 14;

struct BinGrid {
    Box4 boxes[3][kMaxBins];  // only [axis][0, binCount) is initialised and used
    uint32_t counts[3][kMaxBins];

    void reset(uint32_t binCount) {
        for (int a = 0; a < 3; ++a) {
            for (uint32_t b = 0; b < binCount; ++b) {
                boxes[a][b] = Box4::empty();
                counts[a][b] = 0;
            }
        }
    }
    void add(const Box4& box, const BinMapping& m) {
        uint32_t bin[4];
        m.bins(box, bin);
        for (int a = 0; a < 3; ++a) {
            boxes[a][bin[a]].grow(box);
            ++counts[a][bin[a]];
        }
    }
    void merge(const BinGrid& other, uint32_t binCount) {
        for (int a = 0; a < 3; ++a) {
            for (uint32_t b = 0; b < binCount; ++b) {
                boxes[a][b].grow(other.boxes[a][b]);
                counts[a][b] += other.counts[a][b];
            }
        }
    }
};

// Adds prims.boxes[begin, end) to `grid`. Neighbours in a mesh mostly fall into the same bins,
// and each add then waits for the store of the add before it to the same bin box: from
// kTwoGridsSize primitives on, every other one goes to a second grid, merged at the end, so that
// two such chains run side by side (1M-triangle sphere, one thread: 5% off the build; below
// that size the merge costs more than it saves).
constexpr uint32_t kTwoGridsSize = 128;
void binRange(const PrimRange& prims, uint32_t begin, uint32_t end, const BinMapping& m, BinGrid& grid) {
    if (end - begin < kTwoGridsSize) {
        for (uint32_t i = begin; i < end; ++i) grid.add(prims.boxes[i], m);
        return;
    }
    BinGrid odd;
    odd.reset(m.binCount);
    uint32_t i = begin;
    for (; i + 1 < end; i += 2) {
        grid.add(prims.boxes[i], m);
        odd.add(prims.boxes[i + 1], m);
    }
    if (i < end) grid.add(prims.boxes[i], m);
    grid.merge(odd, m.binCount);
}

// Binning is exact (min/max and integer counts), so the parallel reduction's result does not
// depend on how TBB splits the range.
void binPrimitives(const PrimRange& prims, const BinMapping& m, BinGrid& grid) {
    grid.reset(m.binCount);
    if (prims.count < kParallelBinSize) {
        binRange(prims, 0, prims.count, m, grid);
        return;
    }
    using Range = tbb::blocked_range<uint32_t>;
    grid = tbb::parallel_reduce(
        Range(0, prims.count, kBinGrain), grid,
        [&](const Range& r, BinGrid partial) {
            binRange(prims, r.begin(), r.end(), m, partial);
            return partial;
        },
        [&](BinGrid a, const BinGrid& b) {
            a.merge(b, m.binCount);
            return a;
        });
}

// Sweeps the bin boundaries of one axis: suffix areas right to left, then prefixes.
void sweepBins(const BinGrid& grid, uint32_t binCount, int axis, SahSplit& best) {
    float rightArea[kMaxBins];
    uint32_t rightCount[kMaxBins];
    Box4 acc = Box4::empty();
    uint32_t count = 0;
    for (uint32_t b = binCount - 1; b > 0; --b) {
        acc.grow(grid.boxes[axis][b]);
        count += grid.counts[axis][b];
        rightArea[b] = acc.halfArea();
        rightCount[b] = count;
    }
    acc = Box4::empty();
    count = 0;
    for (uint32_t b = 1; b < binCount; ++b) {
        acc.grow(grid.boxes[axis][b - 1]);
        count += grid.counts[axis][b - 1];
        if (count == 0 || rightCount[b] == 0) continue;
        const float cost = acc.halfArea() * float(count) + rightArea[b] * float(rightCount[b]);
        if (cost < best.cost) {
            best.axis = axis;
            best.bin = b;
            best.cost = cost;
            best.leftCount = count;
        }
    }
}

}  // namespace

BinMapping::BinMapping(const Box4& centroids, uint32_t bins) : lastBin(float(bins - 1)), binCount(bins) {
    for (int k = 0; k < 4; ++k) {
        const float extent = centroids.hi[k] - centroids.lo[k];
        lo[k] = k < 3 ? centroids.lo[k] : 0.0f;
        scale[k] = k < 3 && extent > 0.0f ? float(bins) / extent : 0.0f;
    }
}

SahSplit findBinnedSplit(const PrimRange& prims, const BinMapping& mapping) {
    BinGrid grid;
    binPrimitives(prims, mapping, grid);
    SahSplit best;
    for (int a = 0; a < 3; ++a) {
        if (mapping.scale[a] > 0.0f) sweepBins(grid, mapping.binCount, a, best);
    }
    if (best.axis < 0) return best;
    best.leftBounds = best.rightBounds = Box4::empty();
    for (uint32_t b = 0; b < mapping.binCount; ++b) {
        (b < best.bin ? best.leftBounds : best.rightBounds).grow(grid.boxes[best.axis][b]);
    }
    return best;
}

namespace {

// findSweepSplit of two primitives, most of its calls (half of a 1M-triangle build's nodes):
// every axis splits a pair the same way at the same cost (a sum of the same two areas), and
// the sweep takes the first axis of equal costs, so the pair is ordered along x as the sweep
// would order it, without its sorts.
SahSplit splitPair(const PrimRange& prims) {
    SahSplit split;
    const auto centroidX = [&](uint32_t i) { return prims.boxes[i].lo[0] + prims.boxes[i].hi[0]; };
    const uint32_t first = centroidX(1) < centroidX(0) ? 1 : 0;
    const float cost = prims.boxes[first].halfArea() * 1.0f + prims.boxes[1 - first].halfArea() * 1.0f;
    if (!(cost < kInf)) return split;
    if (first == 1) std::swap(prims.boxes[0], prims.boxes[1]);
    split.leftBounds = prims.boxes[0];
    split.rightBounds = prims.boxes[1];
    split.axis = 0;
    split.cost = cost;
    split.leftCount = 1;
    split.sorted = true;
    return split;
}

// A sweep's sort key: the centroid's bits made to order as unsigned integers (negative floats
// reversed, positive ones above them; -0 is made +0 first, as float comparison has them
// equal), and the slot below them, so that equal centroids keep their slots' order.
uint64_t sweepKey(float centroid, uint32_t slot) {
    const uint32_t bits = uint32_t(floatAsInt(centroid + 0.0f));
    const uint32_t ordered = bits & 0x80000000u ? ~bits : bits | 0x80000000u;
    return uint64_t(ordered) << 32 | slot;
}

}  // namespace

// Sorting a handful of keys per axis is cheaper than the fixed 3 x binCount bins of binning,
// which would dominate the many small nodes near the leaves, and the sweep is exact.
SahSplit findSweepSplit(const PrimRange& prims) {
    const uint32_t n = prims.count;
    if (n == 2) return splitPair(prims);
    Box4 boxes[kSweepSize];
    std::copy(prims.boxes, prims.boxes + n, boxes);
    uint64_t keys[3][kSweepSize];
    for (uint32_t i = 0; i < n; ++i) {
        const Box4 c = boxes[i].centroidPoint();
        for (int a = 0; a < 3; ++a) keys[a][i] = sweepKey(c.lo[a], i);
    }
    Box4 rightBounds[kSweepSize];
    SahSplit best;
    for (int a = 0; a < 3; ++a) {
        uint64_t* key = keys[a];
        // Sorted by rank: the keys are distinct (the slot is in their low bits), so each goes to
        // the number of keys below it, with no branch on a comparison. The insertion sort before
        // missed a branch on most of its steps; it was a third of this function's samples, and
        // one thread's build of a 1M-triangle soup went from 352-367 to 330-337 ms with this.
        uint64_t sorted[kSweepSize];
        for (uint32_t i = 0; i < n; ++i) {
            uint32_t rank = 0;
            for (uint32_t j = 0; j < n; ++j) rank += key[j] < key[i] ? 1u : 0u;
            sorted[rank] = key[i];
        }
        std::copy(sorted, sorted + n, key);
        Box4 acc = Box4::empty();
        float rightArea[kSweepSize];
        for (uint32_t i = n - 1; i > 0; --i) {
            acc.grow(boxes[uint32_t(key[i])]);
            rightBounds[i] = acc;
            rightArea[i] = acc.halfArea();
        }
        acc = Box4::empty();
        for (uint32_t i = 1; i < n; ++i) {
            acc.grow(boxes[uint32_t(key[i - 1])]);
            const float cost = acc.halfArea() * float(i) + rightArea[i] * float(n - i);
            if (cost < best.cost) {
                best.axis = a;
                best.cost = cost;
                best.leftCount = i;
                best.leftBounds = acc;
                best.rightBounds = rightBounds[i];
            }
        }
    }
    if (best.axis < 0) return best;
    for (uint32_t i = 0; i < n; ++i) prims.boxes[i] = boxes[uint32_t(keys[best.axis][i])];
    best.sorted = true;
    return best;
}

namespace {

// Branch-free Lomuto partition of prims.boxes[begin, end): the side of each primitive is
// unpredictable, and swapping unconditionally costs less than the mispredictions a two-pointer
// partition takes. Returns the left count; grows centroids[1] by the left ones' centroids and
// centroids[0] by the right ones'.
uint32_t partitionRange(const PrimRange& prims, uint32_t begin, uint32_t end, const BinMapping& mapping,
                        const SahSplit& split, Box4 centroids[2]) {
    const int a = split.axis;
    uint32_t left = begin;
    for (uint32_t i = begin; i < end; ++i) {
        const Box4 box = prims.boxes[i];
        const uint32_t goesLeft = mapping.belowBin(box, a, split.bin) ? 1u : 0u;
        centroids[goesLeft].grow(box.centroidPoint());
        prims.boxes[i] = prims.boxes[left];
        prims.boxes[left] = box;
        left += goesLeft;
    }
    return left - begin;
}

// Partitions of this many primitives or more run in parallel: alone, the root's took one thread
// while the others waited, and the levels below it had fewer tasks than threads. On the GPU
// machine's 16-core Xeon (pt-render bench --backend cpu, build medians, two alternated rounds)
// the 1M-triangle sphere's build took 53.3-56.6 ms on 16 threads with it and the sweep's rank
// sort, 59.5-64.4 with the sort alone and 63.4-70.4 with neither; the 10M sphere's 623-656 ms
// against 694-750 with neither.
constexpr uint32_t kParallelPartitionSize = 1u << 17;
constexpr uint32_t kPartitionChunk = 1u << 14;

// Where the misplaced primitives of one side lie after the chunks' own partitions: chunk c's
// run of them starts at first[c], and the runs before it hold before[c] of them.
struct MisplacedRuns {
    std::vector<uint32_t> first, before;

    // The position of the rank-th misplaced primitive, in position order.
    uint32_t position(uint32_t rank) const {
        const size_t c = size_t(std::upper_bound(before.begin(), before.end(), rank) - before.begin()) - 1;
        return first[c] + (rank - before[c]);
    }
};

// The partition in two parallel passes over fixed chunks: each chunk is partitioned on its own,
// then the left primitives lying past the final split are swapped, in position order, with the
// right ones lying before it. The chunks do not depend on the thread count, so neither does the
// result (nor the tree built on it).
uint32_t partitionInParallel(const PrimRange& prims, const BinMapping& mapping, const SahSplit& split,
                             Box4 centroids[2]) {
    const uint32_t n = prims.count, chunks = (n + kPartitionChunk - 1) / kPartitionChunk;
    const auto chunkEnd = [&](uint32_t begin) { return std::min(n, begin + kPartitionChunk); };
    struct ChunkPartition {
        uint32_t lefts = 0;
        Box4 centroids[2] = {Box4::empty(), Box4::empty()};  // right, left
    };
    std::vector<ChunkPartition> parts(chunks);
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, chunks, 1), [&](const tbb::blocked_range<uint32_t>& r) {
        for (uint32_t c = r.begin(); c != r.end(); ++c) {
            const uint32_t begin = c * kPartitionChunk;
            parts[c].lefts =
                partitionRange(prims, begin, chunkEnd(begin), mapping, split, parts[c].centroids);
        }
    });
    uint32_t left = 0;
    for (const ChunkPartition& part : parts) {
        left += part.lefts;
        centroids[0].grow(part.centroids[0]);
        centroids[1].grow(part.centroids[1]);
    }
    // Chunk c holds its left primitives in [begin, begin + parts[c].lefts), its right ones after:
    // the left ones at or past `left` are misplaced, and the right ones before it.
    MisplacedRuns lost, strays;  // left primitives on the right side; right ones on the left side
    uint32_t misplaced = 0, straying = 0;
    for (uint32_t c = 0; c < chunks; ++c) {
        const uint32_t begin = c * kPartitionChunk, end = chunkEnd(begin);
        const uint32_t rightBegin = begin + parts[c].lefts;
        const uint32_t lostFirst = std::max(begin, left);
        lost.first.push_back(lostFirst);
        lost.before.push_back(misplaced);
        misplaced += rightBegin > lostFirst ? rightBegin - lostFirst : 0u;
        strays.first.push_back(rightBegin);
        strays.before.push_back(straying);
        straying += std::min(end, left) > rightBegin ? std::min(end, left) - rightBegin : 0u;
    }
    assert(misplaced == straying &&
           "as many left primitives lie right of the split as right ones left of it");
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, misplaced, kPartitionChunk / 4),
                      [&](const tbb::blocked_range<uint32_t>& r) {
                          for (uint32_t k = r.begin(); k != r.end(); ++k) {
                              std::swap(prims.boxes[lost.position(k)], prims.boxes[strays.position(k)]);
                          }
                      });
    return left;
}

}  // namespace

uint32_t partitionByBin(const PrimRange& prims, const BinMapping& mapping, const SahSplit& split,
                        Box4& leftCentroids, Box4& rightCentroids) {
    Box4 centroids[2] = {Box4::empty(), Box4::empty()};  // right, left
    const uint32_t left = prims.count >= kParallelPartitionSize
                              ? partitionInParallel(prims, mapping, split, centroids)
                              : partitionRange(prims, 0, prims.count, mapping, split, centroids);
    leftCentroids = centroids[1];
    rightCentroids = centroids[0];
    return left;
}

// nth_element over a permutation, then one gather: moving 4-byte slots is cheaper than moving
// 32-byte boxes.
uint32_t partitionByMedian(const PrimRange& prims, const Box4& centroids) {
    const int axis = centroids.largestAxis();
    const uint32_t n = prims.count, mid = n / 2;
    std::vector<uint32_t> order(n);
    for (uint32_t i = 0; i < n; ++i) order[i] = i;
    std::nth_element(order.begin(), order.begin() + mid, order.end(), [&](uint32_t x, uint32_t y) {
        return prims.boxes[x].lo[axis] + prims.boxes[x].hi[axis] <
               prims.boxes[y].lo[axis] + prims.boxes[y].hi[axis];
    });
    std::vector<Box4> boxes(n);
    for (uint32_t i = 0; i < n; ++i) boxes[i] = prims.boxes[order[i]];
    std::copy(boxes.begin(), boxes.end(), prims.boxes);
    return mid;
}

void boundsOf(const PrimRange& prims, Box4& bounds, Box4& centroids) {
    bounds = centroids = Box4::empty();
    for (uint32_t i = 0; i < prims.count; ++i) {
        bounds.grow(prims.boxes[i]);
        centroids.grow(prims.boxes[i].centroidPoint());
    }
}

}  // namespace pt::sah
