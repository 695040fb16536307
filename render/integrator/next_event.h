#pragma once
// Next-event estimation's common part, for surface vertices (path_tracer.h) and scattering
// events inside media (medium_scattering.h): one light sample, weighted against the strategy
// that samples the scattering function (BSDF or phase function) by the power heuristic (Veach
// 1997) for area lights and the environment, at full weight for delta (punctual) lights, and
// the firefly clamp on what reaches the first vertex through others.
#include "render/integrator/path_state.h"
#include "render/kernel/render_scene.h"
#include "render/lights/light_sample.h"
#include "render/sampling/warp.h"

namespace pt {

PT_HD bool neeEnabled(const RenderScene& scene) {
    return scene.settings.nextEventEstimation && scene.emitterAlias.count > 0;
}

// The scattering vertices a path has left behind: surfaces, and with kScatteringMedia the
// scattering events inside media.
template <FeatureSet kF = kAllFeatures>
PT_HD uint32_t pathVertices(const PathState& state) {
    return state.depth + (hasFeature<kF>(feature::kScatteringMedia) ? state.mediumBounces : 0u);
}

// The firefly clamp: an indirect contribution (light that reached the first hit through
// another surface) keeps at most clampRadiance of luminance; direct light is never clamped.
PT_HD Vec3 clampIndirect(const RenderScene& scene, Vec3 contribution, bool indirect) {
    const float limit = scene.settings.clampRadiance;
    if (!indirect || !(limit > 0.0f)) return contribution;
    const float y = luminance(contribution);
    return y > limit ? contribution * (limit / y) : contribution;
}

// The shadow ray `ray` that carries `light` to the path's current vertex, where the scattering
// function is `f` (times the cosine at a surface) and the density of sampling it `scatterPdf`.
// `medium` is the volume the ray starts in (transparency.h attenuates it through the media it
// crosses).
template <FeatureSet kF = kAllFeatures>
PT_HD ShadowRay lightShadowRay(const RenderScene& scene, const PathState& state, const LightSample& light,
                               Vec3 f, float scatterPdf, const Ray& ray, uint32_t medium) {
    ShadowRay shadow{};
    if (isBlack(f) || isBlack(light.radiance)) return shadow;
    const float weight =
        !light.delta && scene.settings.multipleImportance ? powerHeuristic(light.pdf, scatterPdf) : 1.0f;
    shadow.ray = ray;
    shadow.medium = medium;
    const Vec3 contribution = state.throughput * f * light.radiance * (weight / light.pdf);
    shadow.contribution = clampIndirect(scene, contribution, pathVertices<kF>(state) >= 1);
    shadow.valid = !isBlack(shadow.contribution);
    return shadow;
}

// Russian roulette, from the vertex rouletteDepth on, with `u` in [0, 1).
template <FeatureSet kF = kAllFeatures>
PT_HD bool surviveRoulette(const RenderScene& scene, PathState& state, float u) {
    if (!scene.settings.russianRoulette || pathVertices<kF>(state) < scene.settings.russianRouletteDepth)
        return true;
    const float q = fminf(maxComponent(state.throughput) * state.etaScale, 1.0f);
    if (q >= 1.0f) return true;
    if (u >= q) return false;
    state.throughput *= 1.0f / q;
    return true;
}

}  // namespace pt
