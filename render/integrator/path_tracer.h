#pragma once
// The integrator as stage functions over a PathState (generate, shade surface, shade miss,
// accumulate), and tracePath(), the megakernel loop that schedules them for one sample.
// Unidirectional path tracing with next-event estimation on emissive triangles, combined
// with BSDF sampling by multiple importance sampling (power heuristic; Veach 1997), and
// Russian roulette. NEE, MIS and roulette are switches in IntegratorSettings.
#include "render/bvh/traversal.h"
#include "render/integrator/camera.h"
#include "render/integrator/path_state.h"
#include "render/integrator/surface_hit.h"
#include "render/lights/emitter_sample.h"
#include "render/lights/environment.h"
#include "render/materials/bsdf.h"
#include "render/materials/texture_sample.h"

namespace pt {

PT_HD PathState generatePath(const RenderScene& scene, uint32_t x, uint32_t y, uint32_t sampleIndex) {
    const IntegratorSettings& s = scene.settings;
    PathState state{};
    state.sampler = {y * s.width + x, sampleIndex, s.seed};
    state.ray = generateCameraRay(scene.camera, s.width, s.height, x, y,
                                  state.sampler.get2(SampleDims::kPixel),
                                  state.sampler.get2(SampleDims::kLens));
    state.throughput = Vec3(1.0f);
    state.etaScale = 1.0f;
    state.lastWasDelta = true;
    state.alive = true;
    return state;
}

PT_HD void shadeMiss(const RenderScene& scene, PathState& state) {
    // The environment is not light-sampled yet, so BSDF sampling carries it at full weight.
    state.radiance += state.throughput * environmentRadiance(scene, state.ray.direction);
    state.alive = false;
}

PT_HD bool neeEnabled(const RenderScene& scene) {
    return scene.settings.nextEventEstimation && scene.emitterAlias.count > 0;
}

PT_HD BsdfParams bsdfParamsAt(const RenderScene& scene, const Material& m, Vec2 uv) {
    BsdfParams p{m.baseColor, m.metallic, m.transmission, m.ior};
    if (m.baseColorTexture.present()) p.baseColor *= sampleTexture(scene, m.baseColorTexture, uv, true).xyz();
    return p;
}

// Emission seen by the path's last segment, weighted against NEE where NEE could have found it.
PT_HD void addSurfaceEmission(const RenderScene& scene, PathState& state, const SurfaceHit& surface,
                              float hitDistance) {
    const Material& m = scene.materials[surface.material];
    if (!m.isEmissive() || !surface.frontFace) return;
    const Vec3 emitted = emittedRadiance(scene, m, surface.uv);
    float weight = 1.0f;
    if (surface.isEmitterTriangle && neeEnabled(scene) && !state.lastWasDelta) {
        if (!scene.settings.multipleImportance) return;  // NEE alone accounts for this light
        const float cosLight = fabsf(dot(surface.geometricNormal, state.ray.direction));
        const float lightPdf = emitterPickProbability(scene, surface.triangleArea, m) /
                               surface.triangleArea * hitDistance * hitDistance / cosLight;
        weight = powerHeuristic(state.lastBsdfPdf, lightPdf);
    }
    state.radiance += state.throughput * emitted * weight;
}

PT_HD ShadowRay sampleDirectLight(const RenderScene& scene, const PathState& state,
                                  const SurfaceHit& surface, const BsdfParams& bsdf,
                                  const Frame& frame, Vec3 wo, uint32_t dims) {
    ShadowRay shadow{};
    EmitterSample light;
    if (!sampleEmitter(scene, state.sampler.get(dims + SampleDims::kLightPick),
                       state.sampler.get2(dims + SampleDims::kLightPoint), light)) {
        return shadow;
    }
    const Vec3 toLight = light.point - surface.position;
    const float distance2 = lengthSquared(toLight);
    if (!(distance2 > 0.0f)) return shadow;
    const Vec3 wi = toLight / sqrtf(distance2);
    const float cosLight = -dot(light.normal, wi);
    if (cosLight <= 0.0f) return shadow;  // the light's back faces us
    const Vec3 f = evalBsdf(bsdf, frame, wo, wi);
    if (isBlack(f)) return shadow;
    const float lightPdf = light.pdfArea * distance2 / cosLight;
    const float weight = scene.settings.multipleImportance
                             ? powerHeuristic(lightPdf, pdfBsdf(bsdf, frame, wo, wi))
                             : 1.0f;
    const Vec3 origin = offsetRayOrigin(surface.position, surface.geometricNormal,
                                        dot(wi, surface.geometricNormal) > 0.0f);
    const Vec3 target = offsetRayOrigin(light.point, light.normal, true);
    shadow.ray = {origin, target - origin, 1.0f};
    shadow.contribution = state.throughput * f * light.radiance * (weight / lightPdf);
    shadow.valid = true;
    return shadow;
}

PT_HD bool surviveRoulette(const RenderScene& scene, PathState& state, uint32_t dims) {
    if (!scene.settings.russianRoulette || state.depth < scene.settings.russianRouletteDepth) return true;
    const float q = fminf(maxComponent(state.throughput) * state.etaScale, 1.0f);
    if (q >= 1.0f) return true;
    if (state.sampler.get(dims + SampleDims::kRoulette) >= q) return false;
    state.throughput *= 1.0f / q;
    return true;
}

// Adds emission, queues a shadow ray, and turns `state.ray` into the next segment (or ends the
// path). `hit` is the closest hit of `state.ray`.
PT_HD ShadowRay shadeSurface(const RenderScene& scene, PathState& state, const Hit& hit) {
    ShadowRay shadow{};
    const SurfaceHit surface = surfaceAt(scene, state.ray, hit);
    addSurfaceEmission(scene, state, surface, hit.t);
    if (state.depth >= scene.settings.maxDepth) {
        state.alive = false;
        return shadow;
    }
    const Material& m = scene.materials[surface.material];
    const BsdfParams bsdf = bsdfParamsAt(scene, m, surface.uv);
    // Shade the side the ray arrived on, except for glass, which needs to know in from out.
    const bool twoSidedFlip = !surface.frontFace && lobeWeights(bsdf).glass == 0.0f;
    const Vec3 ns = twoSidedFlip ? -surface.shadingNormal : surface.shadingNormal;
    const Vec3 ng = twoSidedFlip ? -surface.geometricNormal : surface.geometricNormal;
    SurfaceHit oriented = surface;
    oriented.geometricNormal = ng;
    const Frame frame = Frame::fromNormal(ns);
    const Vec3 wo = -state.ray.direction;
    const uint32_t dims = SampleDims::bounce(state.depth);

    if (neeEnabled(scene) && hasNonDeltaLobes(bsdf)) {
        shadow = sampleDirectLight(scene, state, oriented, bsdf, frame, wo, dims);
    }
    const BsdfSample s = sampleBsdf(bsdf, frame, wo, state.sampler.get(dims + SampleDims::kBsdfLobe),
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
        const float eta = surface.frontFace ? bsdf.ior : 1.0f / bsdf.ior;
        state.etaScale *= eta * eta;
    }
    state.lastBsdfPdf = s.pdf;
    state.lastWasDelta = s.delta;
    state.ray.origin = offsetRayOrigin(surface.position, arrivalNormal, sameSide);
    state.ray.direction = s.wi;
    state.ray.tMax = kInf;
    state.depth += 1;
    state.alive = surviveRoulette(scene, state, dims);
    return shadow;
}

// One sample of pixel (x, y): the megakernel schedule of the stages above.
PT_HD Vec3 tracePath(const RenderScene& scene, uint32_t x, uint32_t y, uint32_t sampleIndex,
                     PathCounters& counters) {
    PathState state = generatePath(scene, x, y, sampleIndex);
    while (state.alive) {
        Hit hit;
        ++counters.rays;
        if (!intersectClosest(scene, state.ray, hit)) {
            shadeMiss(scene, state);
            break;
        }
        const ShadowRay shadow = shadeSurface(scene, state, hit);
        if (shadow.valid) {
            ++counters.rays;
            if (!intersectAny(scene, shadow.ray)) state.radiance += shadow.contribution;
        }
    }
    if (!isFinite(state.radiance)) {
        ++counters.nonfiniteSamples;
        return Vec3(0.0f);
    }
    return state.radiance;
}

}  // namespace pt
