#pragma once
// What the denoiser's passes read and write per pixel (atrous_filter.h). Each of the 125 taps
// a pixel makes reads a neighbour's sample and surface; on the H100 at 1080p the passes were
// bound by the bytes of those loads (an a-trous pass 0.38 ms with 16 + 32 bytes a tap, 94% of
// the memory system's throughput), so a tap reads a sample of halves (8 bytes) and a surface
// of 16, and what only the centre needs lives apart. Both backends pack with the same code,
// so they filter the same numbers.
#include <cstddef>
#include <cstdint>

#include "render/math/half_float.h"
#include "render/math/hd.h"
#include "render/math/vec.h"

namespace pt {

// One pixel of the filter's working planes: demodulated radiance and the variance of its
// mean luminance. A pixel whose input was not finite has a negative variance: it takes no part
// in the filter, and its neighbours fill it in.
struct DenoiseSample {
    Vec3 radiance;
    float variance;

    PT_HD bool valid() const { return variance >= 0.0f; }
};

namespace denoise {

constexpr float kInvalid = -1.0f;  // DenoiseSample::variance of a pixel left out

// A pixel's surface as its neighbours' edge stops compare it (surfaceOf): 16 bytes, one load
// (aligned so that the GPU makes it one).
struct alignas(16) DenoiseSurface {
    Vec3 normal;  // unit; 0 where the pixel holds no usable normal
    float depth;  // of the part of the pixel on a surface; 0 where none is
};

// Pixel q's surface: on the GPU one 16-byte load (nvcc copies the struct member by member).
// Signed: a tap's offset from its row's pointer may be negative.
PT_HD DenoiseSurface loadSurface(const DenoiseSurface* surfaces, ptrdiff_t q) {
#if defined(__CUDA_ARCH__)
    const float4 v = __ldg(reinterpret_cast<const float4*>(surfaces) + q);
    return {{v.x, v.y, v.z}, v.w};
#else
    return surfaces[q];
#endif
}

// What only a pixel's own edge stops read (surfaceOf, depthSlopeAt), a plane of its own so
// that the taps do not load it.
struct SurfaceStops {
    float normalPower;  // the normal edge stop's power, lowered by the pixel's spread of normals
    float depthSlope;   // the larger of its depth slopes along x and y, a pixel
};

// A sample as halves: radiance, and the standard deviation of the mean luminance (not the
// variance: at thousands of samples a variance falls below half's normal range, 6e-5, and its
// subnormals keep only a few bits). Negative: left out. Demodulated radiance past 65504
// saturates there; filteredRadiance gives such a pixel back its own excess.
struct alignas(8) PackedSample {
    uint16_t r, g, b, deviation;
};

// Sample q: on the GPU one 8-byte load (a copy of the struct became four 2-byte loads).
PT_HD PackedSample loadPacked(const PackedSample* samples, ptrdiff_t q) {
#if defined(__CUDA_ARCH__)
    const uint2 v = __ldg(reinterpret_cast<const uint2*>(samples) + q);
    return {uint16_t(v.x), uint16_t(v.x >> 16), uint16_t(v.y), uint16_t(v.y >> 16)};
#else
    return samples[q];
#endif
}

PT_HD PackedSample packSample(const DenoiseSample& s) {
    const float deviation = s.valid() ? sqrtf(s.variance) : kInvalid;
    return {halfFromFloat(s.radiance.x), halfFromFloat(s.radiance.y), halfFromFloat(s.radiance.z),
            halfFromFloat(deviation)};
}

PT_HD DenoiseSample unpackSample(PackedSample p) {
    const float deviation = floatFromHalf(p.deviation);
    return {{floatFromHalf(p.r), floatFromHalf(p.g), floatFromHalf(p.b)},
            deviation >= 0.0f ? deviation * deviation : kInvalid};
}

// The filter's result for a pixel whose own (full-precision) sample is `input`: what the
// passes made of the packed input, plus what packing took off the input (so a flat image
// passes unchanged, and a pixel past half's range keeps its excess).
PT_HD Vec3 filteredRadiance(const DenoiseSample& input, PackedSample filtered) {
    const Vec3 result = unpackSample(filtered).radiance;
    return input.valid() ? result + (input.radiance - unpackSample(packSample(input)).radiance) : result;
}

}  // namespace denoise
}  // namespace pt
