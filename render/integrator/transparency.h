#pragma once
// Surfaces rays pass: alpha-transparent ones (glTF alphaMode MASK and BLEND; coverage in
// render/materials/alpha.h), culled back faces (glTF doubleSided = false) and index-matched
// volume boundaries (medium.h), for closest-hit and shadow rays.
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
#include "render/integrator/medium.h"
#include "render/integrator/path_state.h"
#include "render/integrator/spawn_ray.h"
#include "render/integrator/surface_hit.h"
#include "render/materials/alpha.h"
#include "render/sampling/sampler.h"

namespace pt {

// The ray that continues past `surface` (met by `ray`) in the same direction. A finite ray
// keeps its end point: it is aimed at it from the new origin, for that origin is offset off the
// surface (sideways, too) by more than the margin a shadow ray keeps short of its light
// (spawn_ray.h), and a parallel ray would end inside a sphere light it meets at a slant (a sphere
// light behind an index-matched boundary was missed by one shadow ray in ten).
PT_HD Ray continuePast(const Ray& ray, const SurfaceHit& surface) {
    Ray next = ray;
    const Vec3 n = surface.geometricNormal;
    next.origin = spawnOrigin(surface, n, dot(ray.direction, n) > 0.0f);
    if (isFinite(ray.tMax)) {
        next.direction = ray.origin + ray.direction * ray.tMax - next.origin;
        next.tMax =
            dot(next.direction, ray.direction) > 0.0f ? 1.0f : 0.0f;  // 0: the end lay before the surface
    }
    return next;
}

// The shadow ray met nothing: it carries its light through the medium it started in.
template <FeatureSet kF>
PT_HD void attenuateUnblockedShadowRay(const RenderScene& scene, ShadowRay& shadow) {
    if (!hasFeature<kF>(feature::kVolume) || shadow.medium == kNoMedium) return;
    const float distance = shadow.ray.tMax * length(shadow.ray.direction);  // may be infinite
    shadow.contribution *= mediumTransmittance<kF>(scene, shadow.medium, distance);
}

// After an any-hit query found something on `shadow`'s ray: whether every surface on it lets it
// through (alpha, culled back faces, index-matched volume boundaries), walking them in order
// from the nearest. Its contribution takes the transmittance of the media between them: the
// one it starts in, and those it enters through index-matched boundaries. (Leaving the one it
// started in, it is in vacuum: the path's outer volumes are not carried.)
template <FeatureSet kF>
PT_HD bool shadowRayPassesBlockers(const RenderScene& scene, ShadowRay& shadow, const PathSampler& sampler,
                                   uint32_t depth, PathCounters& counters) {
    constexpr bool kAlpha = hasFeature<kF>(feature::kTransparency);
    constexpr bool kMatched = hasFeature<kF>(feature::kIndexMatchedBoundaries);
    if constexpr (!kAlpha && !kMatched) {
        return false;  // no surface lets rays through: the first hit blocks
    } else {
        const bool alpha = kAlpha && scene.transparentMaterials;
        if (!alpha && !kMatched) return false;
        MediumStack media{};
        if (shadow.medium != kNoMedium) media.enter(shadow.medium);
        Ray ray = shadow.ray;
        for (uint32_t layer = 0; layer < SampleDims::kAlphaLayers; ++layer) {
            Hit hit;
            ++counters.rays;
            const bool found = intersectClosest<kF>(scene, ray, hit);
            const float t = found ? hit.t : ray.tMax;
            shadow.contribution *= mediumTransmittance<kF>(scene, media, t * length(ray.direction));
            if (!found) return true;
            const SurfaceHit surface = surfaceAt<kF>(scene, ray, hit);
            const Material& m = scene.materials[surface.material];
            if (kMatched && isIndexMatchedBoundary(m)) {
                shadow.contribution *= m.baseColor;
                crossVolumeBoundary<kF>(scene, media, surface.material, surface.frontFace);
            } else {
                const float u = sampler.get(SampleDims::shadowAlpha(depth, layer));
                if (!alpha || !passesThrough<kF>(scene, m, surface.uv, surface.frontFace, u)) return false;
            }
            ray = continuePast(ray, surface);
            if (!(ray.tMax > 0.0f)) return true;
        }
        return false;
    }
}

// After the any-hit query on `shadow`'s ray (`found`: it met something): whether its light gets
// through, its contribution attenuated by the media on the way. `depth` names the bounce the
// ray leaves from, for the stochastic-transparency numbers.
template <FeatureSet kF>
PT_HD bool shadowRayGetsThrough(const RenderScene& scene, ShadowRay& shadow, bool found,
                                const PathSampler& sampler, uint32_t depth, PathCounters& counters) {
    if (!found) {
        attenuateUnblockedShadowRay<kF>(scene, shadow);
        return true;
    }
    return shadowRayPassesBlockers<kF>(scene, shadow, sampler, depth, counters);
}

// Whether nothing opaque lies on `shadow`'s ray (0 < t < tMax): the any-hit query, then the above.
template <FeatureSet kF = kAllFeatures>
PT_HD bool shadowRayUnoccluded(const RenderScene& scene, ShadowRay& shadow, const PathSampler& sampler,
                               uint32_t depth, PathCounters& counters) {
    ++counters.rays;
    const bool found = intersectAny<kF>(scene, shadow.ray);
    return shadowRayGetsThrough<kF>(scene, shadow, found, sampler, depth, counters);
}

// If the surface `state.ray` hit is transparent there, moves the ray past it and returns true.
template <FeatureSet kF = kAllFeatures>
PT_HD bool passTransparentSurface(const RenderScene& scene, PathState& state, const SurfaceHit& surface) {
    if (!hasFeature<kF>(feature::kTransparency) || !scene.transparentMaterials ||
        state.transparentHits >= SampleDims::kAlphaLayers) {
        return false;
    }
    const Material& m = scene.materials[surface.material];
    const float u = state.sampler.get(SampleDims::alpha(state.depth, state.transparentHits));
    if (!passesThrough<kF>(scene, m, surface.uv, surface.frontFace, u)) return false;
    ++state.transparentHits;
    state.ray = continuePast(state.ray, surface);
    return true;
}

// If the surface `state.ray` hit is an index-matched volume boundary (medium.h), moves the ray
// past it into or out of the volume and returns true. The path's last vertex and its density
// stay those of the scattering before, so light found beyond is weighted as if no surface
// were there (next-event estimation reaches it through the boundary too).
template <FeatureSet kF = kAllFeatures>
PT_HD bool passIndexMatchedBoundary(const RenderScene& scene, PathState& state, const SurfaceHit& surface) {
    if (!hasFeature<kF>(feature::kIndexMatchedBoundaries) ||
        state.transparentHits >= SampleDims::kAlphaLayers)
        return false;
    const Material& m = scene.materials[surface.material];
    if (!isIndexMatchedBoundary(m)) return false;
    ++state.transparentHits;
    state.throughput *= m.baseColor;
    crossVolumeBoundary<kF>(scene, state.media, surface.material, surface.frontFace);
    state.ray = continuePast(state.ray, surface);
    return true;
}

}  // namespace pt
