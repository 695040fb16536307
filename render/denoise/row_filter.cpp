#include "render/denoise/row_filter.h"

#include "render/denoise/atrous_filter.h"

// GCC builds these three times, for AVX-512 (x86-64-v4: sixteen floats a vector and 32
// vector registers), AVX2 (eight) and any x86-64 (SSE2, four), and the loader picks the one
// the CPU runs (an ifunc), so one binary runs everywhere. 512x512, 4 spp, Xeon with AVX-512,
// one core: 407 ms for the per-pixel steps, 85 ms for these rows with AVX2, 59 with AVX-512.
// (No clone contracts multiply-adds: -ffp-contract=off holds for all.)
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define PT_SIMD_CLONES __attribute__((target_clones("arch=x86-64-v4", "avx2", "default")))
#else
#define PT_SIMD_CLONES
#endif
// The helpers below are inlined into each clone, so that they are built for its instruction set.
#define PT_ALWAYS_INLINE inline __attribute__((always_inline))
// The loops over a row read a dozen planes and write others; the compiler cannot prove they
// do not overlap (they never do), and would otherwise test every pair before vectorising. (Not
// on clang, which builds only the fuzz targets here: under their sanitizers its loops do not
// vectorise, and a loop asked to that does not is a warning.)
#if defined(__GNUC__) && !defined(__clang__)
#define PT_INDEPENDENT_ITERATIONS _Pragma("GCC ivdep")
#else
#define PT_INDEPENDENT_ITERATIONS
#endif

namespace pt::denoise {

namespace {

EdgeStops edgeStopsAt(const SurfaceData& s, size_t i) { return {s.surfaceAt(i), s.stopsAt(i)}; }

// The kTapDistances distances of a-trous taps, in steps. Each pixel's depth scale for each
// (one division each, not one a tap, as atrousAt).
const float kTapDistance[kTapDistances] = {1.0f, 2.0f, sqrtf(2.0f), sqrtf(5.0f), sqrtf(8.0f)};
constexpr int kTapDistanceIndex[3][3] = {{-1, 0, 1}, {0, 2, 3}, {1, 3, 4}};  // by |j|, |i|

// A row's sums through pointers taken once (SampleData says why).
struct RowSumsData {
    float *r, *g, *b, *weight, *variance, *centerLuminance, *inverseLuminance, *outlierLimit;
    float* inverseDepth[kTapDistances];  // the centre's depth scales, by tap distance

    explicit RowSumsData(RowSums& s)
        : r(s.r.data()),
          g(s.g.data()),
          b(s.b.data()),
          weight(s.weight.data()),
          variance(s.variance.data()),
          centerLuminance(s.centerLuminance.data()),
          inverseLuminance(s.inverseLuminance.data()),
          outlierLimit(s.outlierLimit.data()) {
        for (int k = 0; k < kTapDistances; ++k)
            inverseDepth[k] = s.inverseDepth.data() + size_t(k) * s.r.size();
    }

    AtrousSums atrousAt(uint32_t x) const { return {{r[x], g[x], b[x]}, weight[x], variance[x]}; }
    void setAtrous(uint32_t x, const AtrousSums& s) const {
        r[x] = s.radiance.x;
        g[x] = s.radiance.y;
        b[x] = s.radiance.z;
        weight[x] = s.weight;
        variance[x] = s.variance;
    }
    // spatialVarianceRow's sums live in three of the planes.
    SpreadSums spreadAt(uint32_t x) const { return {weight[x], r[x], g[x]}; }
    void setSpread(uint32_t x, const SpreadSums& s) const {
        weight[x] = s.weight;
        r[x] = s.luminance;
        g[x] = s.squares;
    }
};

// Adds the taps (dx, dy), dx = -3 .. 3, of spread row dy to every pixel's sums; the centre's
// own tap (`kCentreRow`, dx = 0) weighs 1.
template <bool kCentreRow>
PT_ALWAYS_INLINE void addSpreadRow(const LuminancePlanes& in, const SurfaceData& surfaces,
                                   const PlaneLayout& layout, uint32_t y, int dy, const RowSumsData& sums) {
    const size_t row = layout.at(0, y);
    const ptrdiff_t tapRow = ptrdiff_t(dy) * layout.stride();
    float distance[kSpreadRadius + 1];  // spatialVarianceAt's, for |dx| = 0 .. 3 on this row
    for (int dx = 0; dx <= kSpreadRadius; ++dx) distance[dx] = sqrtf(float(dx * dx + dy * dy));
    const size_t tapStart = size_t(ptrdiff_t(row) + tapRow - kSpreadRadius);  // tap dx: x + tapStart + dx + 3
    const float *luminance = in.luminance.data(), *included = in.included.data();
    PT_INDEPENDENT_ITERATIONS
    for (uint32_t x = 0; x < layout.width; ++x) {
        const EdgeStops edges = edgeStopsAt(surfaces, row + x);
        SpreadSums s = sums.spreadAt(x);
        PT_UNROLL
        for (int dx = -kSpreadRadius; dx <= kSpreadRadius; ++dx) {
            const size_t q = tapStart + size_t(dx + kSpreadRadius) + x;
            const float w = kCentreRow && dx == 0
                                ? 1.0f
                                : spreadWeight(edges, surfaces.surfaceAt(q), distance[dx < 0 ? -dx : dx]);
            s.add(included[q] > 0.0f ? w : 0.0f, luminance[q]);
        }
        sums.setSpread(x, s);
    }
}

// Adds the taps (i, j), i = -2 .. 2, of a-trous row j to every pixel's sums; the centre's
// own row leaves i = 0 out (`kCentreRow`), as the centre is added first.
template <bool kCentreRow>
PT_ALWAYS_INLINE void addTapRow(const SampleInput& in, const SurfaceData& surfaces, const PlaneLayout& layout,
                                uint32_t y, uint32_t step, int j, const RowSumsData& sums) {
    const size_t row = layout.at(0, y);
    const ptrdiff_t tapRow = ptrdiff_t(j) * ptrdiff_t(step) * layout.stride();
    size_t tapStart[5];  // where tap i's pixels start: x + tapStart[i + 2] (affine in x, so loads vectorise)
    for (int i = -2; i <= 2; ++i)
        tapStart[i + 2] = size_t(ptrdiff_t(row) + tapRow + ptrdiff_t(i) * ptrdiff_t(step));
    const int absJ = j < 0 ? -j : j;
    PT_INDEPENDENT_ITERATIONS
    for (uint32_t x = 0; x < layout.width; ++x) {
        const EdgeStops edges = edgeStopsAt(surfaces, row + x);
        const TapScales scales{sums.centerLuminance[x], sums.inverseLuminance[x], sums.outlierLimit[x]};
        AtrousSums s = sums.atrousAt(x);
        PT_UNROLL
        for (int i = -2; i <= 2; ++i) {
            if (kCentreRow && i == 0) continue;
            const size_t q = tapStart[i + 2] + x;
            const float w = atrousTapWeight(
                edges, surfaces.surfaceAt(q), sums.inverseDepth[kTapDistanceIndex[absJ][i < 0 ? -i : i]][x],
                in.luminance[q], in.deviation[q], scales, splineWeight(i) * splineWeight(j));
            s.add(w, {in.r[q], in.g[q], in.b[q]}, in.deviation[q] * in.deviation[q]);
        }
        sums.setAtrous(x, s);
    }
}

}  // namespace

PT_SIMD_CLONES
void spatialVarianceRow(const LuminancePlanes& in, const SurfacePlanes& surfaces, const PlaneLayout& layout,
                        uint32_t y, RowSums& rowSums, float* variance) {
    const RowSumsData sums(rowSums);
    const SurfaceData surfaceData(surfaces);
    for (uint32_t x = 0; x < layout.width; ++x) sums.setSpread(x, SpreadSums{});
    // Taps in spatialVarianceAt's order; one row of them a sweep over the pixels.
    for (int dy = -kSpreadRadius; dy <= kSpreadRadius; ++dy) {
        if (dy == 0) {
            addSpreadRow<true>(in, surfaceData, layout, y, dy, sums);
        } else {
            addSpreadRow<false>(in, surfaceData, layout, y, dy, sums);
        }
    }
    const float* included = in.included.data() + layout.at(0, y);
    PT_INDEPENDENT_ITERATIONS
    for (uint32_t x = 0; x < layout.width; ++x)
        variance[x] = included[x] > 0.0f ? sums.spreadAt(x).variance() : kInvalid;
}

PT_SIMD_CLONES
void atrousRow(const SamplePlanes& inPlanes, const SurfacePlanes& surfaces, const PlaneLayout& layout,
               uint32_t y, uint32_t step, RowSums& rowSums, SamplePlanes& outPlanes) {
    const SampleInput in(inPlanes);
    const SampleOutput out(outPlanes);
    const RowSumsData sums(rowSums);
    const SurfaceData surfaceData(surfaces);
    const size_t row = layout.at(0, y);
    const float* deviationRows[3] = {in.deviation + row - layout.stride(), in.deviation + row,
                                     in.deviation + row + layout.stride()};  // rows y - 1 .. y + 1
    float distance[kTapDistances];
    for (int k = 0; k < kTapDistances; ++k) distance[k] = float(step) * kTapDistance[k];
    // The centre: its depth scales, luminance stop and outlier limit, and its own sample added first
    // (atrousAt's `if` as a weight of 0: a left-out sample's values are zeros).
    PT_INDEPENDENT_ITERATIONS
    for (uint32_t x = 0; x < layout.width; ++x) {
        const size_t c = row + x;
        const EdgeStops edges = edgeStopsAt(surfaceData, c);
        PT_UNROLL
        for (int k = 0; k < kTapDistances; ++k)
            sums.inverseDepth[k][x] = edges.inverseDepthScale(distance[k]);
        const float deviation = in.deviation[c];
        const bool valid = deviation >= 0.0f;
        const NeighbourhoodVariance around =
            neighbourhoodVarianceAt([&](int dx, int dy) { return deviationRows[dy + 1][ptrdiff_t(x) + dx]; });
        sums.centerLuminance[x] = in.luminance[c];
        sums.inverseLuminance[x] = inverseLuminanceScale(valid, around.blurred);
        sums.outlierLimit[x] = around.outlierLimit;
        const float variance = deviation * deviation;
        AtrousSums s;
        s.add(valid ? centerWeight(variance, around.outlierLimit) : 0.0f, {in.r[c], in.g[c], in.b[c]},
              variance);
        sums.setAtrous(x, s);
    }
    for (int j = -2; j <= 2; ++j) {
        if (j == 0) {
            addTapRow<true>(in, surfaceData, layout, y, step, j, sums);
        } else {
            addTapRow<false>(in, surfaceData, layout, y, step, j, sums);
        }
    }
    PT_INDEPENDENT_ITERATIONS
    for (uint32_t x = 0; x < layout.width; ++x) out.store(row + x, sums.atrousAt(x).result());
}

}  // namespace pt::denoise
