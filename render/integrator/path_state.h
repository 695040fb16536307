#pragma once
// PathState: everything a path carries between stages. The megakernel keeps one in
// registers; a wavefront scheduler keeps arrays of them (STYLE.md rule 2).
#include "render/math/ray.h"
#include "render/sampling/sampler.h"

namespace pt {

struct PathState {
    Ray ray;                 // next segment; direction unit length in world space
    Vec3 throughput;         // product of BSDF weights so far
    Vec3 radiance;           // gathered so far
    PathSampler sampler;
    uint32_t depth;          // surface interactions so far
    float etaScale;          // product of eta^2 over refractions: undoes their 1/eta^2 for roulette
    float lastBsdfPdf;       // solid-angle pdf of the sample that made `ray`
    bool lastWasDelta;       // `ray` came from a specular lobe (or the camera)
    bool alive;
};

// A shadow ray for next-event estimation: if nothing blocks it, `contribution` is added.
struct ShadowRay {
    Ray ray;                 // from the shading point to the light point; blocked if any hit has t < tMax
    Vec3 contribution;
    bool valid;
};

// Counters a backend sums over all paths.
struct PathCounters {
    uint64_t rays = 0;           // closest-hit and shadow rays traced
    uint64_t nonfiniteSamples = 0;
};

}  // namespace pt
