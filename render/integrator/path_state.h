#pragma once
// PathState: everything a path carries between stages. The megakernel keeps one in
// registers; a wavefront scheduler keeps arrays of them (STYLE.md rule 2).
#include "render/math/ray.h"
#include "render/sampling/sampler.h"

namespace pt {

// The volumes (KHR_materials_volume) a path is inside, innermost last: a small stack of
// material indices, pushed when the path refracts into a volumetric material's front face
// and popped when it refracts out through a back face, so glass inside water attenuates by
// each in turn. Deeper nesting than kMaxNestedMedia keeps counting but stores no more; the
// innermost stored medium then stands in for the deeper ones.
constexpr uint32_t kMaxNestedMedia = 4;
constexpr uint32_t kNoMedium = ~0u;  // a medium index meaning: none (vacuum)
struct MediumStack {
    uint32_t materials[kMaxNestedMedia];
    uint32_t depth;  // volumes entered and not left

    PT_HD bool empty() const { return depth == 0; }
    PT_HD uint32_t innermost() const {
        return materials[(depth < kMaxNestedMedia ? depth : kMaxNestedMedia) - 1];
    }
    PT_HD void enter(uint32_t material) {
        if (depth < kMaxNestedMedia) materials[depth] = material;
        ++depth;
    }
    PT_HD void leave() {
        if (depth > 0) --depth;
    }
};

struct PathState {
    Ray ray;          // next segment; direction unit length in world space
    Vec3 throughput;  // product of BSDF weights (and volume transmittances) so far
    Vec3 radiance;    // gathered so far
    Vec3 lastVertex;  // where `ray` was scattered (MIS densities of lights it hits)
    PathSampler sampler;
    uint32_t depth;            // surface interactions so far
    uint16_t transparentHits;  // surfaces this segment has passed through (alpha, index-matched)
    uint16_t mediumBounces;    // scattering events inside media so far (medium_scattering.h)
    MediumStack media;
    float etaScale;     // product of eta^2 over refractions: undoes their 1/eta^2 for roulette
    float lastBsdfPdf;  // solid-angle pdf of the sample that made `ray`
    bool lastWasDelta;  // `ray` came from a specular lobe (or the camera)
    bool alive;
    // The wavelength the first dispersive surface gave the path (dispersion.h's packing; 0: none
    // yet): in the two bytes the bools leave, so the state keeps its size.
    uint16_t wavelength;
};
// What the wavefront keeps per path between stages (with Hit and ShadowRay; pt-render bench
// reports the total).
static_assert(sizeof(PathState) == 116, "PathState: 116 bytes");

// A shadow ray for next-event estimation: if nothing blocks it, `contribution` is added, times
// the transmittance of the media it crosses (transparency.h).
struct ShadowRay {
    Ray ray;  // from the shading point to the light point; blocked if any hit has t < tMax
    Vec3 contribution;
    uint32_t medium;  // the volume it starts in (material index), kNoMedium outside all
    bool valid;
};
static_assert(sizeof(ShadowRay) == 48, "ShadowRay: 48 bytes");

// Counters a backend sums over all paths.
struct PathCounters {
    uint64_t rays = 0;  // closest-hit and shadow rays traced
    uint64_t nonfiniteSamples = 0;
};

}  // namespace pt
