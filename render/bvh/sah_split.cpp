#include "render/bvh/sah_split.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
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
        for (uint32_t i = 1; i < n; ++i) {  // insertion sort: n is tiny
            const uint64_t k = key[i];
            uint32_t j = i;
            for (; j > 0 && k < key[j - 1]; --j) key[j] = key[j - 1];
            key[j] = k;
        }
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

// Branch-free Lomuto partition: the side of each primitive is unpredictable, and swapping
// unconditionally costs less than the mispredictions a two-pointer partition takes.
uint32_t partitionByBin(const PrimRange& prims, const BinMapping& mapping, const SahSplit& split,
                        Box4& leftCentroids, Box4& rightCentroids) {
    const int a = split.axis;
    Box4 centroids[2] = {Box4::empty(), Box4::empty()};  // right, left
    uint32_t left = 0;
    for (uint32_t i = 0; i < prims.count; ++i) {
        const Box4 box = prims.boxes[i];
        const uint32_t goesLeft = mapping.belowBin(box, a, split.bin) ? 1u : 0u;
        centroids[goesLeft].grow(box.centroidPoint());
        prims.boxes[i] = prims.boxes[left];
        prims.boxes[left] = box;
        left += goesLeft;
    }
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
