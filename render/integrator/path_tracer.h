#pragma once
// The integrator as stage functions over a PathState (generate, shade surface, shade miss,
// accumulate), and tracePath(), the megakernel loop that schedules them for one sample.
// Unidirectional path tracing with next-event estimation on every light (emissive triangles
// and spheres, punctual lights, the environment), combined with BSDF sampling by multiple
// importance sampling (power heuristic; Veach 1997) wherever both strategies reach a light,
// and Russian roulette. NEE, MIS, roulette and the firefly clamp are IntegratorSettings.
// Alpha-transparent surfaces and index-matched volume boundaries are passed through
// (transparency.h); paths inside volumetric materials are attenuated by Beer-Lambert (medium.h)
// and, where the volume scatters, scatter inside it (medium_scattering.h). AOVs (aov.h) are recorded at the
// camera ray's first visible surface where the caller passes an AovSample.
//
// Every stage takes the feature set kF it is compiled for (render/compile/scene_features.h):
// the CUDA backend instantiates them per kernel variant, so a scene without textures, volumes,
// clearcoat, ... runs code without them; the default, kAllFeatures, is the generic code.
#include "render/bvh/traversal.h"
#include "render/integrator/anisotropy_frame.h"
#include "render/integrator/aov.h"
#include "render/integrator/camera.h"
#include "render/integrator/medium.h"
#include "render/integrator/medium_scattering.h"
#include "render/integrator/next_event.h"
#include "render/integrator/path_state.h"
#include "render/integrator/spawn_ray.h"
#include "render/integrator/surface_hit.h"
#include "render/integrator/transparency.h"
#include "render/lights/environment.h"
#include "render/lights/light_sample.h"
#include "render/materials/bsdf.h"
#include "render/materials/dispersion.h"
#include "render/materials/material_eval.h"  // bsdfParamsAt
#include "render/materials/texture_sample.h"

namespace pt {

template <FeatureSet kF = kAllFeatures>
PT_HD PathState generatePath(const RenderScene& scene, uint32_t x, uint32_t y, uint32_t sampleIndex) {
    const IntegratorSettings& s = scene.settings;
    PathState state{};
    state.sampler = {y * s.width + x, sampleIndex, s.seed};
    RenderCamera camera = scene.camera;
    if (!hasFeature<kF>(feature::kThinLens)) camera.lensRadius = 0.0f;  // a pinhole: no lens code
    state.ray = generateCameraRay(camera, s.width, s.height, x, y,
                                  s.pixelJitter ? state.sampler.get2(SampleDims::kPixel) : Vec2(0.5f, 0.5f),
                                  state.sampler.get2(SampleDims::kLens));
    state.throughput = Vec3(1.0f);
    state.lastVertex = state.ray.origin;
    state.etaScale = 1.0f;
    state.lastWasDelta = true;
    state.alive = true;
    return state;
}

// MIS weight of light that the path's last BSDF sample found, against NEE's density
// `lightPdf` for the same direction (0 where NEE cannot pick it). 0 when NEE alone counts it.
PT_HD float bsdfSampledLightWeight(const RenderScene& scene, const PathState& state, float lightPdf) {
    if (state.lastWasDelta || !neeEnabled(scene) || !(lightPdf > 0.0f)) return 1.0f;
    if (!scene.settings.multipleImportance) return 0.0f;
    return powerHeuristic(state.lastBsdfPdf, lightPdf);
}

// A ray that left the scene: the environment, weighted against NEE's environment sampling.
// On the camera segment, a non-null `aov` receives the environment seen as its emission: the
// sky is an emitter, and the denoiser takes what the camera sees of it out before filtering, so
// a pixel half on an object and half on the sky is not noisy in how much of each its samples
// found.
template <FeatureSet kF = kAllFeatures>
PT_HD void shadeMiss(const RenderScene& scene, PathState& state, AovSample* aov = nullptr) {
    state.alive = false;
    state.throughput *= mediumTransmittance<kF>(scene, state.media, kInf);  // an unclosed volume
    if (!hasFeature<kF>(feature::kConstantEnvironment | feature::kImageEnvironment)) return;  // black
    if (isBlack(state.throughput)) return;
    const Vec3 direction = state.ray.direction;
    const float lightPdf = state.lastWasDelta ? 0.0f : environmentLightPdf<kF>(scene, direction);
    const float weight = bsdfSampledLightWeight(scene, state, lightPdf);
    if (weight > 0.0f) {
        const Vec3 light = state.throughput * environmentRadiance<kF>(scene, direction) * weight;
        state.radiance += clampIndirect(scene, light, pathVertices<kF>(state) >= 2);
        if (aov && state.depth == 0) aov->emission = light;
    }
}

// Emission seen by the path's last segment, weighted against NEE where NEE could have found it.
template <FeatureSet kF = kAllFeatures>
PT_HD void addSurfaceEmission(const RenderScene& scene, PathState& state, const SurfaceHit& surface) {
    const Material& m = scene.materials[surface.material];
    if (!m.isEmissive() || !surface.frontFace) return;
    float lightPdf = 0.0f;
    if (!state.lastWasDelta && neeEnabled(scene)) {
        lightPdf = surface.kind == GeometryKind::Triangles
                       ? triangleLightPdf(scene, surface.instance, surface.primitive, state.lastVertex,
                                          surface.position, surface.geometricNormal)
                   : hasFeature<kF>(feature::kSphereLights)
                       ? sphereLightPdf(scene, surface.instance, surface.primitive, state.lastVertex)
                       : 0.0f;
    }
    const float weight = bsdfSampledLightWeight(scene, state, lightPdf);
    if (weight > 0.0f) {
        const Vec3 light = state.throughput * emittedRadiance<kF>(scene, m, surface.uv) * weight;
        state.radiance += clampIndirect(scene, light, pathVertices<kF>(state) >= 2);
    }
}

// Next-event estimation at a surface (next_event.h), with the BSDF as the scattering function.
// The shadow ray is traced by the scheduler; `contribution` counts if it is unoccluded.
template <FeatureSet kF = kAllFeatures>
PT_HD ShadowRay sampleDirectLight(const RenderScene& scene, const PathState& state, const SurfaceHit& surface,
                                  const BsdfParams& bsdf, const Frame& frame, Vec3 wo, uint32_t dims) {
    LightSample light;
    if (!sampleLight<kF>(scene, surface.position, state.sampler.get(dims + SampleDims::kLightPick),
                         state.sampler.get2(dims + SampleDims::kLightPoint), light)) {
        return ShadowRay{};
    }
    const BsdfEval eval = evalBsdfWithPdf<kF>(bsdf, frame, wo, light.wi);
    // A light behind the surface is reached through it, in the volume it bounds.
    const bool crosses = (dot(light.wi, surface.geometricNormal) > 0.0f) != surface.frontFace;
    const uint32_t medium =
        mediumBeyond<kF>(scene, state.media, surface.material, crosses, surface.frontFace);
    return lightShadowRay<kF>(scene, state, light, eval.value, eval.pdf, shadowRayTo(surface, light), medium);
}

// KHR_materials_dispersion: a transmitting surface with dispersion refracts with the index of the
// path's wavelength, which the first such surface draws (and weights the throughput by).
template <FeatureSet kF = kAllFeatures>
PT_HD void disperse(PathState& state, const Material& m, BsdfParams& bsdf, uint32_t dims) {
    if (!hasFeature<kF>(feature::kDispersion) || !(m.dispersion > 0.0f) || !isTransmissive(bsdf)) return;
    if (state.wavelength == 0) {
        state.wavelength = packWavelength(state.sampler.get(dims + SampleDims::kWavelength));
        state.throughput *= wavelengthWeight(unpackWavelength(state.wavelength));
    }
    bsdf.ior = dispersedIor(bsdf.ior, m.dispersion, unpackWavelength(state.wavelength));
}

// Adds emission, queues a shadow ray, and turns `state.ray` into the next segment (or ends the
// path). `hit` is the closest hit of `state.ray`. A surface that is alpha-transparent there
// only moves the ray past it (transparency.h). On the camera segment, a non-null `aov`
// receives the surface the camera sees (all but its cost); elsewhere it is left alone.
template <FeatureSet kF = kAllFeatures>
PT_HD ShadowRay shadeSurface(const RenderScene& scene, PathState& state, const Hit& hit,
                             AovSample* aov = nullptr) {
    ShadowRay shadow{};
    if (hasFeature<kF>(feature::kVolume) && !state.media.empty() &&
        scatterInMedium<kF>(scene, state, hit.t, shadow))
        return shadow;
    SurfaceHit surface = surfaceAt<kF>(scene, state.ray, hit);
    if (passTransparentSurface<kF>(scene, state, surface)) return shadow;
    if (passIndexMatchedBoundary<kF>(scene, state, surface)) return shadow;
    state.transparentHits = 0;
    applyNormalMap<kF>(scene, hit, surface);
    // Until the first bounce, lastVertex is still the camera ray's origin.
    if (aov && state.depth == 0) recordAovSurface(scene, surface, state.lastVertex, *aov);
    addSurfaceEmission<kF>(scene, state, surface);
    const Material& m = scene.materials[surface.material];
    if (hasFeature<kF>(feature::kUnlit) && m.unlit) {
        // KHR_materials_unlit: what the path sees is the base colour, and nothing lies beyond it
        // (no light is sampled for it, so no MIS weight applies).
        const Vec3 color = bsdfParamsAt<kF>(scene, m, surface.uv).baseColor;
        state.radiance += clampIndirect(scene, state.throughput * color, state.depth >= 2);
        state.alive = false;
        return shadow;
    }
    if (state.depth >= scene.settings.maxDepth) {
        state.alive = false;
        return shadow;
    }
    const uint32_t dims = SampleDims::bounce(state.depth);
    BsdfParams bsdf = bsdfParamsAt<kF>(scene, m, surface.uv);
    disperse<kF>(state, m, bsdf, dims);
    // Shade the side the ray arrived on, except for glass, which needs to know in from out.
    const bool twoSidedFlip =
        !surface.frontFace && !(hasFeature<kF>(feature::kTransmission) && isTransmissive(bsdf));
    const Frame frame = anisotropicFrame<kF>(
        scene, hit, surface, bsdf,
        Frame::fromNormal(twoSidedFlip ? -surface.shadingNormal : surface.shadingNormal));
    const Vec3 wo = -state.ray.direction;

    if (neeEnabled(scene) && hasNonDeltaLobes<kF>(bsdf)) {
        shadow = sampleDirectLight<kF>(scene, state, surface, bsdf, frame, wo, dims);
    }
    const BsdfSample s = sampleBsdf<kF>(bsdf, frame, wo, state.sampler.get(dims + SampleDims::kBsdfLobe),
                                        state.sampler.get2(dims + SampleDims::kBsdfDir));
    // The sampled direction must leave on the side the BSDF meant (shading normals can
    // disagree with the geometry); otherwise light would leak through the surface.
    const Vec3 arrivalNormal = surface.frontFace ? surface.geometricNormal : -surface.geometricNormal;
    const bool sameSide = dot(s.wi, arrivalNormal) > 0.0f;
    if (isBlack(s.weight) || sameSide == s.transmitted) {
        state.alive = false;
        return shadow;
    }
    state.throughput *= s.weight;
    if (s.transmitted) {
        // Only a diffusely transmitting lobe passes without refracting: without one in kF, this
        // is the branch it always was.
        const bool refracted = !hasFeature<kF>(feature::kDiffuseTransmission) || s.refracted;
        if (refracted) {
            const float eta = surface.frontFace ? bsdf.ior : 1.0f / bsdf.ior;
            state.etaScale *= eta * eta;
        }
        crossVolumeBoundary<kF>(scene, state.media, surface.material, surface.frontFace);
    }
    state.lastVertex = surface.position;
    state.lastBsdfPdf = s.pdf;
    state.lastWasDelta = s.delta;
    state.ray.origin = spawnOrigin(surface, arrivalNormal, sameSide);
    state.ray.direction = s.wi;
    state.ray.tMax = kInf;
    state.depth += 1;
    state.alive = surviveRoulette<kF>(scene, state, state.sampler.get(dims + SampleDims::kRoulette));
    return shadow;
}

// The fused schedule, for paths that record no AOVs: each step traces one ray, the shadow ray
// the last shading queued or else the path's next segment, at one call site (intersectScene).
// A shadow ray that meets a surface letting rays through (alpha, culled back faces) walks on
// past it as shadowRayUnoccluded does. A warp whose threads are at different stages then walks
// the BVH together instead of twice in turn, and the kernel holds one copy of the walk. The
// rays, their order and the sums are those of tracePath's plain loop, so images match it bit
// for bit. The path is done once fusedPathDone() (no shadow ray pending, the path ended).
PT_HD bool fusedPathDone(const PathState& state, const ShadowRay& shadow) {
    return !shadow.valid && !state.alive;
}

// Where the path's segment ended: shaded at its hit (the shadow ray it queues, if any), or at
// the miss, which ends the path (no shadow ray).
template <FeatureSet kF>
PT_HD ShadowRay shadeSegmentEnd(const RenderScene& scene, PathState& state, bool found, const Hit& hit) {
    if (found) return shadeSurface<kF>(scene, state, hit);
    shadeMiss<kF>(scene, state);
    return ShadowRay{};
}

template <FeatureSet kF>
PT_HD void traceFusedStep(const RenderScene& scene, PathState& state, ShadowRay& shadow,
                          PathCounters& counters) {
    const bool shadowTurn = shadow.valid;
    Hit hit;
    ++counters.rays;
    const bool found = intersectScene<kF>(scene, shadowTurn ? shadow.ray : state.ray, shadowTurn, hit);
    if (shadowTurn) {
        if (shadowRayGetsThrough<kF>(scene, shadow, found, state.sampler, state.depth, counters)) {
            state.radiance += shadow.contribution;
        }
        shadow.valid = false;
    } else {
        shadow = shadeSegmentEnd<kF>(scene, state, found, hit);
    }
}

template <FeatureSet kF>
PT_HD void traceFusedPath(const RenderScene& scene, PathState& state, PathCounters& counters) {
    ShadowRay shadow{};
    while (!fusedPathDone(state, shadow)) traceFusedStep<kF>(scene, state, shadow, counters);
}

// The radiance a finished path adds to its pixel: non-finite samples are counted and dropped.
PT_HD Vec3 finishedRadiance(const PathState& state, PathCounters& counters) {
    if (isFinite(state.radiance)) return state.radiance;
    ++counters.nonfiniteSamples;
    return Vec3(0.0f);
}

// The rest of tracePath's fused schedule for a path whose camera ray was traced elsewhere (the
// CPU's 8-ray packets, render/bvh/packet_traversal.h): `hit` is that ray's closest hit as
// intersectClosest gives it. The same rays, order and sums as tracePath<false>, so the same
// radiance bit for bit.
template <FeatureSet kF = kAllFeatures>
PT_HD Vec3 finishPathFromCameraHit(const RenderScene& scene, PathState& state, const Hit& hit,
                                   PathCounters& counters) {
    ++counters.rays;
    ShadowRay shadow = shadeSegmentEnd<kF>(scene, state, hit.valid(), hit);
    while (!fusedPathDone(state, shadow)) traceFusedStep<kF>(scene, state, shadow, counters);
    return finishedRadiance(state, counters);
}

// One sample of pixel (x, y): the megakernel schedule of the stages above. With kAovs, `aov`
// receives the sample's AOVs, the camera segment's traversal work included; without, it is
// ignored and the loop is compiled with no AOV code at all (the choice is the caller's, once).
template <bool kAovs = false, FeatureSet kF = kAllFeatures>
PT_HD Vec3 tracePath(const RenderScene& scene, uint32_t x, uint32_t y, uint32_t sampleIndex,
                     PathCounters& counters, AovSample* aovOut = nullptr) {
    AovSample* const aov = kAovs ? aovOut : nullptr;
    PathState state = generatePath<kF>(scene, x, y, sampleIndex);
    if constexpr (!kAovs) {
        traceFusedPath<kF>(scene, state, counters);
    } else {
        if (kAovs) *aovOut = AovSample{};
        while (state.alive) {
            Hit hit;
            ++counters.rays;
            TraversalStats* cost = aov && state.depth == 0 ? &aov->cost : nullptr;
            if (!intersectClosest<kF>(scene, state.ray, hit, cost)) {
                shadeMiss<kF>(scene, state, aov);
                break;
            }
            ShadowRay shadow = shadeSurface<kF>(scene, state, hit, aov);
            if (shadow.valid &&
                shadowRayUnoccluded<kF>(scene, shadow, state.sampler, state.depth, counters)) {
                state.radiance += shadow.contribution;
            }
        }
    }
    return finishedRadiance(state, counters);
}

}  // namespace pt
