#pragma once
// Arbitrary output variables (AOVs): per-pixel images of what the camera sees first, beside the
// beauty, for the editor's views, EXR layers and denoisers. The integrator fills an AovSample at
// the camera ray's first visible surface without drawing a random number, so the beauty is
// bit-identical with AOVs on or off; backends add samples into per-pixel double sums
// (AovBuffers) that exist only for the AOVs asked for.
//
// What each AOV holds, per sample, averaged over the samples it took (the beauty's, less any
// before changeAovs added it or after a sample cap stopped it: Backend::setAovSampleCap; the
// averages are not renormalised or re-quantised):
//   albedo            base color with its texture, for every material (metal and glass too)
//   shading_normal    unit world-space normal after vertex normals and normal maps (xyz)
//   geometric_normal  unit world-space normal of the primitive (xyz); both normals on the
//                     surface's front (outer) side, as SurfaceHit has them, not turned to the camera
//   depth             distance from the camera ray's origin (on the lens) to the hit, not z
//   position          world-space hit point;  uv: texture coordinates (xy)
//   roughness, metallic  the BSDF's inputs after textures and clamping
//   emission          emitted radiance seen from the camera: lights' front faces (as the beauty),
//                     and the environment where the camera ray leaves the scene
//   instance_id, material_id  of the FIRST sample only, never averaged: the RenderScene
//                     instance index (as Hit::instance of Backend::traceRays) and material index
//   bvh_cost          nodes visited (x) and primitives tested (y) by the camera segment's
//                     closest-hit queries (several where it passes alpha-transparent surfaces)
//   sample_count      samples of the pixel (the accumulation's spp; nothing stored per pixel)
//   variance          variance of the pixel's mean beauty luminance (Welford's running sums)
//   alpha             the fraction of the pixel's camera rays that found a surface (coverage,
//                     as compositors use it; alpha-transparent surfaces passed do not count)
// A camera ray that leaves the scene gives 0 everywhere (depth 0: infinity would poison the
// average) but its emission (the environment it sees), ids -1, and the traversal work it
// still cost.
#include <cstddef>
#include <cstdint>

#include "render/bvh/bvh_walk.h"
#include "render/integrator/surface_hit.h"
#include "render/lights/emitter_sample.h"    // emittedRadiance
#include "render/materials/material_eval.h"  // bsdfParamsAt

namespace pt {

enum class Aov : uint32_t {
    Albedo = 0,
    ShadingNormal,
    GeometricNormal,
    Depth,
    Position,
    Uv,
    Roughness,
    Metallic,
    Emission,
    InstanceId,
    MaterialId,
    BvhCost,
    SampleCount,
    Variance,
    Alpha,
    Count
};
using AovMask = uint32_t;
constexpr uint32_t kAovCount = uint32_t(Aov::Count);
constexpr AovMask aovBit(Aov a) { return 1u << uint32_t(a); }
constexpr AovMask kAllAovs = (1u << kAovCount) - 1u;
// AOVs the path itself must record; sample_count and variance come from the accumulation.
constexpr AovMask kPathAovs = kAllAovs & ~(aovBit(Aov::SampleCount) | aovBit(Aov::Variance));

// Doubles stored per pixel for an AOV. Variance keeps Welford's mean and sum of squared
// deviations; sample_count is the same for every pixel and needs none.
constexpr uint32_t aovChannels(Aov a) {
    switch (a) {
        case Aov::Albedo:
        case Aov::ShadingNormal:
        case Aov::GeometricNormal:
        case Aov::Position:
        case Aov::Emission: return 3;
        case Aov::Uv:
        case Aov::BvhCost:
        case Aov::Variance: return 2;
        case Aov::SampleCount:
        case Aov::Count: return 0;
        default: return 1;
    }
}

// One sample's view of the first visible surface. Lives in registers; 96 bytes.
struct AovSample {
    Vec3 albedo, shadingNormal, geometricNormal, position, emission;
    Vec2 uv;
    float depth = 0.0f, roughness = 0.0f, metallic = 0.0f;
    int32_t instance = -1, material = -1;  // -1: the camera ray left the scene
    TraversalStats cost;
};
static_assert(sizeof(AovSample) == 96, "AovSample: 96 bytes");

// Where a backend accumulates AOVs: per enabled AOV, aovChannels() doubles per pixel, holding
// the samples from firstSample on (an AOV added while the beauty accumulates starts there:
// Backend::changeAovs) that recorded it: `mask` holds the AOVs this pass records (a capped
// AOV that is full keeps its sums but is left out of it).
struct AovBuffers {
    double* sums[kAovCount];  // nullptr where the AOV is off or stores nothing
    AovMask mask;
    uint32_t firstSample[kAovCount];

    PT_HD bool has(Aov a) const { return (mask & aovBit(a)) != 0; }
    PT_HD double* at(Aov a, uint32_t pixel) const {
        return sums[uint32_t(a)] + size_t(pixel) * aovChannels(a);
    }
};
static_assert(sizeof(AovBuffers) == 184, "AovBuffers: 184 bytes of every AOV kernel's parameters");

// Fills `out` (but its cost) from the surface the camera segment stopped at; `cameraOrigin` is
// where the camera ray started. Reads textures but draws no random number.
PT_HD void recordAovSurface(const RenderScene& scene, const SurfaceHit& surface, Vec3 cameraOrigin,
                            AovSample& out) {
    const Material& m = scene.materials[surface.material];
    const BsdfParams bsdf = bsdfParamsAt(scene, m, surface.uv);
    out.albedo = bsdf.baseColor;
    out.shadingNormal = surface.shadingNormal;
    out.geometricNormal = surface.geometricNormal;
    out.position = surface.position;
    out.emission = m.isEmissive() && surface.frontFace ? emittedRadiance(scene, m, surface.uv) : Vec3(0.0f);
    out.uv = surface.uv;
    out.depth = length(surface.position - cameraOrigin);
    out.roughness = bsdf.roughness;
    out.metallic = bsdf.metallic;
    out.instance = int32_t(surface.instance);
    out.material = int32_t(surface.material);
}

PT_HD void addToAovSum(double* sum, double value) {
#if defined(__CUDA_ARCH__)
    atomicAdd(sum, value);  // the samples of a pixel run in several threads of a wave
#else
    *sum += value;  // the CPU backend gives each pixel to one thread
#endif
}

PT_HD void addAovChannels(const AovBuffers& b, Aov a, uint32_t pixel, Vec3 value) {
    if (!b.has(a)) return;
    double* sum = b.at(a, pixel);
    for (uint32_t c = 0; c < aovChannels(a); ++c) addToAovSum(sum + c, double(value[int(c)]));
}

// Adds a sample's surface values (not its cost: addAovCost) to pixel `pixel`. The ids are
// written by their AOV's first sample only (sample `sampleIndex` of the accumulation).
PT_HD void addAovSample(const AovBuffers& b, uint32_t pixel, uint32_t sampleIndex, const AovSample& s) {
    addAovChannels(b, Aov::Albedo, pixel, s.albedo);
    addAovChannels(b, Aov::ShadingNormal, pixel, s.shadingNormal);
    addAovChannels(b, Aov::GeometricNormal, pixel, s.geometricNormal);
    addAovChannels(b, Aov::Depth, pixel, Vec3(s.depth));
    addAovChannels(b, Aov::Position, pixel, s.position);
    addAovChannels(b, Aov::Uv, pixel, Vec3(s.uv.x, s.uv.y, 0.0f));
    addAovChannels(b, Aov::Roughness, pixel, Vec3(s.roughness));
    addAovChannels(b, Aov::Metallic, pixel, Vec3(s.metallic));
    addAovChannels(b, Aov::Emission, pixel, s.emission);
    addAovChannels(b, Aov::Alpha, pixel, Vec3(s.instance >= 0 ? 1.0f : 0.0f));
    if (b.has(Aov::InstanceId) && sampleIndex == b.firstSample[uint32_t(Aov::InstanceId)])
        *b.at(Aov::InstanceId, pixel) = double(s.instance);
    if (b.has(Aov::MaterialId) && sampleIndex == b.firstSample[uint32_t(Aov::MaterialId)])
        *b.at(Aov::MaterialId, pixel) = double(s.material);
}

// Adds traversal work of the camera segment (possibly in parts) to pixel `pixel`.
PT_HD void addAovCost(const AovBuffers& b, uint32_t pixel, TraversalStats cost) {
    if (!b.has(Aov::BvhCost)) return;
    double* sum = b.at(Aov::BvhCost, pixel);
    addToAovSum(sum + 0, double(cost.nodesVisited));
    addToAovSum(sum + 1, double(cost.primitivesTested));
}

// Welford's update (Knuth, TAOCP vol. 2, 4.2.2) of the running mean and sum of squared
// deviations of a pixel's beauty luminance: a constant gives exactly 0, and no sum of squares
// grows to swallow the deviations. Not atomic: one writer per pixel, in sample order (this is
// sample `sampleIndex` of the accumulation; the AOV's own count starts at its first sample and
// has no gaps: a sample cap never holds the variance, checkAovSampleCap refuses it).
PT_HD void addVarianceSample(const AovBuffers& b, uint32_t pixel, uint32_t sampleIndex, Vec3 radiance) {
    double* w = b.at(Aov::Variance, pixel);
    const double y = double(luminance(radiance));
    const double delta = y - w[0];
    w[0] += delta / double(sampleIndex - b.firstSample[uint32_t(Aov::Variance)] + 1u);
    w[1] += delta * (y - w[0]);
}

}  // namespace pt
