#pragma once
// Alpha-transparent surfaces (glTF alphaMode MASK and BLEND; coverage in
// render/materials/alpha.h) and culled back faces (glTF doubleSided = false) for closest-hit
// and shadow rays.
//
// The simplest correct approach: a surface that is transparent at the point a ray meets it
// is not there for that ray. MASK surfaces are transparent where alpha < alphaCutoff; BLEND
// surfaces stop a ray with probability alpha (stochastic transparency: the expected image is
// the alpha blend, with no sorting). A camera or bounce ray continues through such a
// surface from its far side, in the same direction, without counting a bounce (the path
// state's transparentHits counts instead); a shadow ray does the same until it reaches the
// light or an opaque surface. At most SampleDims::kAlphaLayers surfaces are passed per
// segment and the next is treated as opaque, so every path terminates. Lights sampled by
// NEE are weighted by their own coverage (light_sample.h), so both strategies agree.
#include "render/bvh/traversal.h"
#include "render/integrator/path_state.h"
#include "render/integrator/spawn_ray.h"
#include "render/integrator/surface_hit.h"
#include "render/materials/alpha.h"
#include "render/sampling/sampler.h"

namespace pt {

// The ray that continues past `surface` (met by `ray` at `hitT`) in the same direction.
// Finite rays keep their end point: the parameter range left is what lay beyond the hit.
PT_HD Ray continuePast(const Ray& ray, const SurfaceHit& surface, float hitT) {
    Ray next = ray;
    const Vec3 n = surface.geometricNormal;
    next.origin = spawnOrigin(surface, n, dot(ray.direction, n) > 0.0f);
    if (isFinite(ray.tMax)) next.tMax = ray.tMax - hitT;
    return next;
}

// After an any-hit query found something on the shadow ray `ray`: whether every surface on it
// lets it through (alpha, culled back faces), walking them in order from the nearest.
template <FeatureSet kF>
PT_HD bool shadowRayPassesBlockers(const RenderScene& scene, Ray ray, const PathSampler& sampler,
                                   uint32_t depth, PathCounters& counters) {
    if constexpr (!hasFeature<kF>(feature::kTransparency)) {
        return false;  // no surface lets rays through: the first hit blocks
    } else {
        if (!scene.transparentMaterials) return false;
        for (uint32_t layer = 0; layer < SampleDims::kAlphaLayers; ++layer) {
            Hit hit;
            ++counters.rays;
            if (!intersectClosest<kF>(scene, ray, hit)) return true;
            const SurfaceHit surface = surfaceAt<kF>(scene, ray, hit);
            const Material& m = scene.materials[surface.material];
            const float u = sampler.get(SampleDims::shadowAlpha(depth, layer));
            if (!passesThrough<kF>(scene, m, surface.uv, surface.frontFace, u)) return false;
            ray = continuePast(ray, surface, hit.t);
            if (!(ray.tMax > 0.0f)) return true;
        }
        return false;
    }
}

// Whether nothing opaque lies on `ray` (0 < t < tMax). `depth` names the bounce the ray
// leaves from, for the stochastic-transparency numbers.
template <FeatureSet kF = kAllFeatures>
PT_HD bool shadowRayUnoccluded(const RenderScene& scene, Ray ray, const PathSampler& sampler, uint32_t depth,
                               PathCounters& counters) {
    ++counters.rays;
    if (!intersectAny<kF>(scene, ray)) return true;
    return shadowRayPassesBlockers<kF>(scene, ray, sampler, depth, counters);
}

// If the surface `state.ray` hit is transparent there, moves the ray past it and returns true.
template <FeatureSet kF = kAllFeatures>
PT_HD bool passTransparentSurface(const RenderScene& scene, PathState& state, const SurfaceHit& surface,
                                  const Hit& hit) {
    if (!hasFeature<kF>(feature::kTransparency) || !scene.transparentMaterials ||
        state.transparentHits >= SampleDims::kAlphaLayers) {
        return false;
    }
    const Material& m = scene.materials[surface.material];
    const float u = state.sampler.get(SampleDims::alpha(state.depth, state.transparentHits));
    if (!passesThrough<kF>(scene, m, surface.uv, surface.frontFace, u)) return false;
    ++state.transparentHits;
    state.ray = continuePast(state.ray, surface, hit.t);
    return true;
}

}  // namespace pt
