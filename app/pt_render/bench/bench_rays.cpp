#include "pt_render/bench/bench_rays.h"

#include <tbb/parallel_for.h>

#include "render/bvh/traversal.h"
#include "render/integrator/camera.h"
#include "render/integrator/spawn_ray.h"
#include "render/integrator/surface_hit.h"
#include "render/lights/light_sample.h"
#include "render/math/frame.h"
#include "render/sampling/sampler.h"
#include "render/sampling/warp.h"

namespace pt::cli {

BenchRays makeBenchRays(const CompiledScene& compiled, uint32_t width, uint32_t height, uint32_t seed) {
    const RenderScene scene = compiled.view();
    const size_t pixels = size_t(width) * height;
    BenchRays rays;
    rays.primary.resize(pixels);
    std::vector<Ray> diffuse(pixels), shadow(pixels);
    std::vector<char> hasDiffuse(pixels, 0), hasShadow(pixels, 0);
    tbb::parallel_for(size_t(0), pixels, [&](size_t i) {
        const uint32_t x = uint32_t(i % width), y = uint32_t(i / width);
        const PathSampler sampler{uint32_t(i), 0, seed};
        Ray ray = generateCameraRay(compiled.camera, width, height, x, y, sampler.get2(SampleDims::kPixel),
                                    sampler.get2(SampleDims::kLens));
        rays.primary[i] = ray;
        Hit hit;
        if (!intersectClosest(scene, ray, hit)) return;
        const SurfaceHit surface = surfaceAt(scene, ray, hit);
        const Vec3 normal = surface.frontFace ? surface.geometricNormal : -surface.geometricNormal;
        // The integrator's own spawn rules (render/integrator/spawn_ray.h), so these rays are
        // the ones a render traces.
        const Vec3 origin = spawnOrigin(surface, normal, true);
        const Frame frame = Frame::fromNormal(normal);
        const uint32_t dims = SampleDims::bounce(0);
        diffuse[i] = {
            origin, frame.toWorld(squareToCosineHemisphere(sampler.get2(dims + SampleDims::kBsdfDir))), kInf};
        hasDiffuse[i] = 1;
        LightSample light;
        // Only lights above the surface: an opaque surface's BSDF is zero below it, so a render
        // traces no shadow ray there (these would cross the mesh's interior, tens of times
        // slower, and make shadow rays look far costlier than a render's are).
        if (sampleLight(scene, surface.position, sampler.get(dims + SampleDims::kLightPick),
                        sampler.get2(dims + SampleDims::kLightPoint), light) &&
            dot(light.wi, normal) > 0.0f) {
            shadow[i] = shadowRayTo(surface, light);
            hasShadow[i] = 1;
        }
    });
    for (size_t i = 0; i < pixels; ++i) {
        if (hasDiffuse[i]) rays.diffuse.push_back(diffuse[i]);
        if (hasShadow[i]) rays.shadow.push_back(shadow[i]);
    }
    return rays;
}

}  // namespace pt::cli
