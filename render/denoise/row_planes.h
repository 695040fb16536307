#pragma once
// The CPU's form of the denoiser's working planes (atrous_filter.h): a plane a channel, so
// that a row of pixels loads as SIMD vectors, with a margin of left-out pixels around the
// image, so that no tap needs a bounds check. A left-out pixel's weight is 0, as a tap past
// the image's edge has none at all, and its values are finite zeros: summing it changes
// nothing, so the filter's sums are the per-pixel code's to the bit.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "render/denoise/denoise_planes.h"

namespace pt::denoise {

// Two steps of the widest a-trous pass (16 pixels) wide: the reach of its taps.
constexpr uint32_t kPlaneMargin = 32;

struct PlaneLayout {
    uint32_t width, height;
    uint32_t stride() const { return width + 2 * kPlaneMargin; }
    size_t size() const { return size_t(stride()) * (height + 2 * kPlaneMargin); }
    size_t at(uint32_t x, uint32_t y) const { return size_t(y + kPlaneMargin) * stride() + x + kPlaneMargin; }
};

// Samples as the GPU's halves hold them (PackedSample, unpacked to floats once, not a tap),
// and the luminance of each.
struct SamplePlanes {
    std::vector<float> r, g, b, deviation, luminance;

    explicit SamplePlanes(const PlaneLayout& layout)
        : r(layout.size(), 0.0f),
          g(layout.size(), 0.0f),
          b(layout.size(), 0.0f),
          deviation(layout.size(), kInvalid),
          luminance(layout.size(), 0.0f) {}

    PackedSample packed(size_t i) const {
        return {halfFromFloat(r[i]), halfFromFloat(g[i]), halfFromFloat(b[i]), halfFromFloat(deviation[i])};
    }
};

// A SamplePlanes' data through pointers taken once: a loop that read through the vectors
// would reload their data pointers every iteration (a store to another plane might have moved
// them, as far as the compiler knows), and its loads would not vectorise.
template <class Float>
struct SampleData {
    Float *r, *g, *b, *deviation, *luminance;

    template <class Planes>
    explicit SampleData(Planes& p)
        : r(p.r.data()),
          g(p.g.data()),
          b(p.b.data()),
          deviation(p.deviation.data()),
          luminance(p.luminance.data()) {}

    // Rounded to halves, as the GPU packs it.
    void store(size_t i, const DenoiseSample& s) const {
        const PackedSample p = packSample(s);
        r[i] = floatFromHalf(p.r);
        g[i] = floatFromHalf(p.g);
        b[i] = floatFromHalf(p.b);
        deviation[i] = floatFromHalf(p.deviation);
        luminance[i] = pt::luminance(Vec3(r[i], g[i], b[i]));
    }
};
using SampleInput = SampleData<const float>;
using SampleOutput = SampleData<float>;

// What spatialVarianceAt reads of each pixel: the luminance of its full-precision sample, and
// 1 where it takes part (0 where it is left out, and in the margin).
struct LuminancePlanes {
    std::vector<float> luminance, included;

    explicit LuminancePlanes(const PlaneLayout& layout)
        : luminance(layout.size(), 0.0f), included(layout.size(), 0.0f) {}

    void store(size_t i, const DenoiseSample& s) {
        luminance[i] = s.valid() ? pt::luminance(s.radiance) : 0.0f;
        included[i] = s.valid() ? 1.0f : 0.0f;
    }
};

// Each pixel's surface (DenoiseSurface) and its own edge stops (SurfaceStops); the margin
// holds no surface.
struct SurfacePlanes {
    std::vector<float> nx, ny, nz, depth, normalPower, depthSlope;

    explicit SurfacePlanes(const PlaneLayout& layout)
        : nx(layout.size(), 0.0f),
          ny(layout.size(), 0.0f),
          nz(layout.size(), 0.0f),
          depth(layout.size(), 0.0f),
          normalPower(layout.size(), 0.0f),
          depthSlope(layout.size(), 0.0f) {}

    void store(size_t i, const DenoiseSurface& s, const SurfaceStops& stops) {
        nx[i] = s.normal.x;
        ny[i] = s.normal.y;
        nz[i] = s.normal.z;
        depth[i] = s.depth;
        normalPower[i] = stops.normalPower;
        depthSlope[i] = stops.depthSlope;
    }
};

// A SurfacePlanes' data through pointers taken once (SampleData says why).
struct SurfaceData {
    const float *nx, *ny, *nz, *depth, *normalPower, *depthSlope;

    explicit SurfaceData(const SurfacePlanes& s)
        : nx(s.nx.data()),
          ny(s.ny.data()),
          nz(s.nz.data()),
          depth(s.depth.data()),
          normalPower(s.normalPower.data()),
          depthSlope(s.depthSlope.data()) {}

    DenoiseSurface surfaceAt(size_t i) const { return {{nx[i], ny[i], nz[i]}, depth[i]}; }
    SurfaceStops stopsAt(size_t i) const { return {normalPower[i], depthSlope[i]}; }
};

}  // namespace pt::denoise
