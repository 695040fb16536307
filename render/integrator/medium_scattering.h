#pragma once
// Scattering inside homogeneous media (issue 15: fog, smoke, and random-walk subsurface
// scattering in skin, wax, jade, marble). A segment of the path inside a scattering medium
// samples a free flight (free_flight.h): either the path reaches the surface ahead, weighted by
// the transmittance, or it scatters on the way. There it samples a light (next_event.h) with the
// Henyey-Greenstein phase function as the scattering function, and a new direction from the
// phase function (henyey_greenstein.h, whose sample weight is 1), MIS-weighted against each
// other as at a surface. A random walk through a dense medium is the same loop, step by step
// (Chiang et al. 2016; pbrt-v4's VolPathIntegrator); it ends after
// SampleDims::kMaxMediumBounces events, by Russian roulette, or where the path leaves the
// volume through its boundary.
//
// Shadow rays leave from the scattering point: inside a volume with a refracting boundary only
// lights inside it are reached; through index-matched boundaries, lights anywhere
// (transparency.h attenuates them by every medium they cross).
#include "render/integrator/free_flight.h"
#include "render/integrator/medium.h"
#include "render/integrator/next_event.h"
#include "render/integrator/spawn_ray.h"
#include "render/materials/henyey_greenstein.h"

namespace pt {

// One light sample from `point` inside a medium with phase anisotropy g.
template <FeatureSet kF>
PT_HD ShadowRay sampleDirectLightInMedium(const RenderScene& scene, const PathState& state, Vec3 point,
                                          float g, uint32_t dims) {
    LightSample light;
    if (!sampleLight<kF>(scene, point, state.sampler.get(dims + SampleDims::kMediumLightPick),
                         state.sampler.get2(dims + SampleDims::kMediumLightPoint), light)) {
        return ShadowRay{};
    }
    // Light travels along -wi, then on along -direction: the cosine between the two.
    const float phase = henyeyGreenstein(dot(light.wi, state.ray.direction), g);
    return lightShadowRay<kF>(scene, state, light, Vec3(phase), phase, shadowRayFrom(point, light),
                              state.media.innermost());
}

// The segment of `state.ray` up to the surface at `hitT`, inside the path's innermost volume.
// Returns true if the path scattered before the surface: it then goes on from the scattering
// point (or has ended), with the shadow ray of its light sample in `shadow`. Otherwise the
// throughput has taken the segment's transmittance (or the free flight's weight) and the
// surface is next.
template <FeatureSet kF>
PT_HD bool scatterInMedium(const RenderScene& scene, PathState& state, float hitT, ShadowRay& shadow) {
    const HomogeneousMedium medium = mediumOf<kF>(scene.materials[state.media.innermost()]);
    if (!hasFeature<kF>(feature::kScatteringMedia) || !medium.scatters()) {
        state.throughput *= transmittance(medium.sigmaT, hitT);  // the ray is unit length
        return false;
    }
    const uint32_t dims = SampleDims::medium(state.depth, state.mediumBounces, state.transparentHits);
    const FreeFlight flight = sampleFreeFlight(medium.sigmaT, medium.sigmaS, state.throughput, hitT,
                                               state.sampler.get(dims + SampleDims::kMediumChannel),
                                               state.sampler.get(dims + SampleDims::kMediumDistance));
    state.throughput *= flight.weight;
    if (!flight.scattered) return false;
    if (isBlack(state.throughput) || state.mediumBounces >= SampleDims::kMaxMediumBounces) {
        state.alive = false;
        return true;
    }
    const Vec3 point = state.ray.origin + state.ray.direction * flight.distance;
    if (neeEnabled(scene)) shadow = sampleDirectLightInMedium<kF>(scene, state, point, medium.g, dims);
    const PhaseSample s = sampleHenyeyGreenstein(state.ray.direction, medium.g,
                                                 state.sampler.get2(dims + SampleDims::kMediumPhaseDir));
    state.ray = {point, s.direction, kInf};
    state.lastVertex = point;
    state.lastBsdfPdf = s.pdf;
    state.lastWasDelta = false;
    state.transparentHits = 0;
    state.mediumBounces += 1;
    state.alive = surviveRoulette<kF>(scene, state, state.sampler.get(dims + SampleDims::kMediumRoulette));
    return true;
}

}  // namespace pt
