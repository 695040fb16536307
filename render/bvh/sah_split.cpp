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

// Binning is exact (min/max and integer counts), so the parallel reduction's result does not
// depend on how TBB splits the range.
void binPrimitives(const PrimRange& prims, const BinMapping& m, BinGrid& grid) {
    grid.reset(m.binCount);
    if (prims.count < kParallelBinSize) {
        for (uint32_t i = 0; i < prims.count; ++i) grid.add(prims.boxes[i], m);
        return;
    }
    using Range = tbb::blocked_range<uint32_t>;
    grid = tbb::parallel_reduce(
        Range(0, prims.count, kBinGrain), grid,
        [&](const Range& r, BinGrid partial) {
            for (uint32_t i = r.begin(); i != r.end(); ++i) partial.add(prims.boxes[i], m);
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

// Sorting a handful of 8-byte keys per axis is cheaper than the fixed 3 x binCount bins of
// binning, which would dominate the many small nodes near the leaves, and the sweep is exact.
SahSplit findSweepSplit(const PrimRange& prims) {
    struct Key {
        float centroid;
        uint32_t slot;
    };
    const uint32_t n = prims.count;
    Key keys[3][kSweepSize];
    float rightArea[kSweepSize];
    SahSplit best;
    for (int a = 0; a < 3; ++a) {
        for (uint32_t i = 0; i < n; ++i) keys[a][i] = {prims.boxes[i].lo[a] + prims.boxes[i].hi[a], i};
        for (uint32_t i = 1; i < n; ++i) {  // insertion sort: n is tiny
            const Key key = keys[a][i];
            uint32_t j = i;
            for (; j > 0 && key.centroid < keys[a][j - 1].centroid; --j) keys[a][j] = keys[a][j - 1];
            keys[a][j] = key;
        }
        Box4 acc = Box4::empty();
        for (uint32_t i = n - 1; i > 0; --i) {
            acc.grow(prims.boxes[keys[a][i].slot]);
            rightArea[i] = acc.halfArea();
        }
        acc = Box4::empty();
        for (uint32_t i = 1; i < n; ++i) {
            acc.grow(prims.boxes[keys[a][i - 1].slot]);
            const float cost = acc.halfArea() * float(i) + rightArea[i] * float(n - i);
            if (cost < best.cost) {
                best.axis = a;
                best.cost = cost;
                best.leftCount = i;
            }
        }
    }
    if (best.axis < 0) return best;
    Box4 boxes[kSweepSize];
    uint32_t indices[kSweepSize];
    for (uint32_t i = 0; i < n; ++i) {
        boxes[i] = prims.boxes[keys[best.axis][i].slot];
        indices[i] = prims.indices[keys[best.axis][i].slot];
    }
    std::copy(boxes, boxes + n, prims.boxes);
    std::copy(indices, indices + n, prims.indices);
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
        const uint32_t index = prims.indices[i];
        const uint32_t goesLeft = mapping.belowBin(box, a, split.bin) ? 1u : 0u;
        centroids[goesLeft].grow(box.centroidPoint());
        prims.boxes[i] = prims.boxes[left];
        prims.indices[i] = prims.indices[left];
        prims.boxes[left] = box;
        prims.indices[left] = index;
        left += goesLeft;
    }
    leftCentroids = centroids[1];
    rightCentroids = centroids[0];
    return left;
}

// nth_element over a permutation, then one gather: moving 4-byte slots is cheaper than moving
// 32-byte boxes and their indices in step.
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
    std::vector<uint32_t> indices(n);
    for (uint32_t i = 0; i < n; ++i) {
        boxes[i] = prims.boxes[order[i]];
        indices[i] = prims.indices[order[i]];
    }
    std::copy(boxes.begin(), boxes.end(), prims.boxes);
    std::copy(indices.begin(), indices.end(), prims.indices);
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
