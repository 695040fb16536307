#pragma once
// Split selection for the binned SAH builder (host; internal to binned_sah_builder.cpp):
// centroid binning and the SAH sweep over bin boundaries (Wald, "On fast Construction of
// SAH-based Bounding Volume Hierarchies", IRT 2007), an exact sweep for small nodes, and the
// partitions that apply a chosen split to a primitive range.
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "render/math/vec.h"

namespace pt::sah {

constexpr uint32_t kMaxBins = 64;
constexpr uint32_t kSweepSize = 16;  // nodes this small use the exact sweep, not bins

// A box in four lanes (the fourth is zero), so that growing it is one SSE min and max (the
// scalar fallback keeps other hosts building). The builder's scratch arrays hold these
// uninitialised.
struct alignas(16) Box4 {
    float lo[4], hi[4];

    static Box4 empty() { return {{kInf, kInf, kInf, 0.0f}, {-kInf, -kInf, -kInf, 0.0f}}; }
    // A primitive's box carries the primitive's index in its fourth lanes, 16 bits in each as a
    // whole float (exact, and never a denormal, which would slow the SSE operations on the box),
    // so that sorting and partitioning move one 32-byte record. Boxes grown from these hold junk
    // there, which nothing reads.
    static Box4 ofPrimitive(Vec3 lo, Vec3 hi, uint32_t index) {
        return {{lo.x, lo.y, lo.z, float(index & 0xffffu)}, {hi.x, hi.y, hi.z, float(index >> 16)}};
    }
    uint32_t primitive() const { return uint32_t(lo[3]) | uint32_t(hi[3]) << 16; }
    void grow(const Box4& b) {
#if defined(__SSE2__)
        _mm_store_ps(lo, _mm_min_ps(_mm_load_ps(lo), _mm_load_ps(b.lo)));
        _mm_store_ps(hi, _mm_max_ps(_mm_load_ps(hi), _mm_load_ps(b.hi)));
#else
        for (int k = 0; k < 4; ++k) {
            lo[k] = lo[k] < b.lo[k] ? lo[k] : b.lo[k];
            hi[k] = hi[k] > b.hi[k] ? hi[k] : b.hi[k];
        }
#endif
    }
    // Twice the centroid (lo + hi) as a point box: the factor 2 cancels wherever it is used.
    Box4 centroidPoint() const {
        Box4 c;
#if defined(__SSE2__)
        const __m128 sum = _mm_add_ps(_mm_load_ps(lo), _mm_load_ps(hi));
        _mm_store_ps(c.lo, sum);
        _mm_store_ps(c.hi, sum);
#else
        for (int k = 0; k < 4; ++k) c.lo[k] = c.hi[k] = lo[k] + hi[k];
#endif
        return c;
    }
    // Half the surface area: the SAH only compares ratios of areas. 0 when empty.
    float halfArea() const {
        const float dx = hi[0] - lo[0], dy = hi[1] - lo[1], dz = hi[2] - lo[2];
        if (!(dx >= 0.0f && dy >= 0.0f && dz >= 0.0f)) return 0.0f;
        return dx * dy + dy * dz + dz * dx;
    }
    int largestAxis() const {
        const float dx = hi[0] - lo[0], dy = hi[1] - lo[1], dz = hi[2] - lo[2];
        return dx >= dy ? (dx >= dz ? 0 : 2) : (dy >= dz ? 1 : 2);
    }
};

// A node's primitive range: their boxes, each with its index into the builder's input.
struct PrimRange {
    Box4* boxes;
    uint32_t count;

    PrimRange sub(uint32_t begin, uint32_t n) const { return {boxes + begin, n}; }
};

struct SahSplit {
    int axis = -1;        // -1: no split found (coincident centroids, zero area)
    bool sorted = false;  // exact sweep: the range is already in order, leftCount go left
    uint32_t bin = 0;     // binned: primitives in bins [0, bin) go left
    float cost = kInf;    // sum over the children of halfArea x count (not normalised)
    uint32_t leftCount = 0;
    Box4 leftBounds, rightBounds;  // exact unions of the children's boxes
};

// Maps (doubled) centroids to bins along each axis; flat axes map everything to bin 0.
struct BinMapping {
    alignas(16) float lo[4];
    alignas(16) float scale[4];
    float lastBin;
    uint32_t binCount;

    BinMapping(const Box4& centroids, uint32_t bins);
    // A mapping that separates nothing (for nodes that are not binned).
    static BinMapping none() { return BinMapping(Box4::empty(), 2); }
    bool separable() const { return scale[0] > 0.0f || scale[1] > 0.0f || scale[2] > 0.0f; }
    // The fractional bin coordinates of a box's (doubled) centroid, (lo + hi - this->lo) *
    // scale, in all lanes at once. Binning and partitioning both go through here, so they agree
    // on every primitive's side bit for bit. Bin b holds coordinates in [b, b + 1); the first
    // and last bins also everything below and above, and NaN lands in bin 0.
    void coordinates(const Box4& box, float out[4]) const {
#if defined(__SSE2__)
        const __m128 c = _mm_add_ps(_mm_load_ps(box.lo), _mm_load_ps(box.hi));
        _mm_storeu_ps(out, _mm_mul_ps(_mm_sub_ps(c, _mm_load_ps(lo)), _mm_load_ps(scale)));
#else
        for (int k = 0; k < 4; ++k) out[k] = (box.lo[k] + box.hi[k] - lo[k]) * scale[k];
#endif
    }
    // The bins of a box along each axis: its coordinates clamped to [0, lastBin] (NaN to 0) and
    // truncated, in all lanes at once.
    void bins(const Box4& box, uint32_t out[4]) const {
#if defined(__SSE2__)
        const __m128 c = _mm_add_ps(_mm_load_ps(box.lo), _mm_load_ps(box.hi));
        const __m128 f = _mm_mul_ps(_mm_sub_ps(c, _mm_load_ps(lo)), _mm_load_ps(scale));
        // max(f, 0) with f first gives 0 for NaN (maxps returns its second operand then).
        const __m128 clamped = _mm_min_ps(_mm_max_ps(f, _mm_setzero_ps()), _mm_set1_ps(lastBin));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(out), _mm_cvttps_epi32(clamped));
#else
        float f[4];
        coordinates(box, f);
        for (int k = 0; k < 4; ++k) out[k] = uint32_t(f[k] > 0.0f ? (f[k] < lastBin ? f[k] : lastBin) : 0.0f);
#endif
    }
    bool belowBin(const Box4& box, int axis, uint32_t bin) const {
        float f[4];
        coordinates(box, f);
        return !(f[axis] >= float(bin));
    }
};

// Best binned split of a range (bins in parallel for large ranges).
SahSplit findBinnedSplit(const PrimRange& prims, const BinMapping& mapping);

// Best split among all centroid-sorted positions of a range of at most kSweepSize; leaves the
// range sorted along the chosen axis. Splits by position, so coincident centroids separate.
SahSplit findSweepSplit(const PrimRange& prims);

// In-place partition by bin; returns the left count and the children's centroid bounds.
uint32_t partitionByBin(const PrimRange& prims, const BinMapping& mapping, const SahSplit& split,
                        Box4& leftCentroids, Box4& rightCentroids);

// Object median along the widest centroid axis; returns the left count (count / 2).
uint32_t partitionByMedian(const PrimRange& prims, const Box4& centroids);

// Union of the boxes and of the (doubled) centroids.
void boundsOf(const PrimRange& prims, Box4& bounds, Box4& centroids);

}  // namespace pt::sah
