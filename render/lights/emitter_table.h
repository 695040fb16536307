#pragma once
// Host: the light table that next-event estimation samples, one alias table over every
// light, each weighted by an estimate of its power / pi:
//   emissive triangle    world area x luminance(emission)
//   emissive sphere      4 pi r^2 x luminance(emission)           (uniformly scaled instances)
//   point light          4 x luminance(I)                          (power 4 pi I)
//   spot light           2 (1 - cos theta_mid) luminance(I)        (theta_mid: between inner and outer)
//   directional light    R^2 x luminance(E)                        (E through the scene's bounding disk)
//   environment          4 pi R^2 x average luminance              (L through the bounding sphere)
// where R is the radius of the scene's bounding sphere. One table rather than a separate
// probability for environment versus local lights: the weights are all flux estimates, and
// MIS needs only one number per light (weight / total), which the integrator recomputes from
// the same inputs when BSDF sampling hits a light. The environment's estimate is the crudest
// (a large ground plane makes R, and so the sky, huge), so beside local lights its share of
// the samples is kept within [1/4, 3/4]: a dim sky next to a bright lamp, or a lamp under a
// bright sky, still gets at least a quarter of the samples, and neither starves the other.
#include <vector>

#include "render/kernel/render_scene.h"
#include "render/lights/environment_distribution.h"

namespace pt {

struct EmitterTable {
    std::vector<Emitter> emitters;
    std::vector<AliasEntry> alias;
    float totalWeight = 0.0f;
    uint32_t triangles = 0, spheres = 0, punctual = 0;  // counts by kind
    float environmentWeight = 0.0f;                     // 0: the environment is not in the table
};

// Reads geometry, instances, materials, punctual lights and the environment from `scene`
// (which must already point at them); `environmentAverageLuminance` is the mean luminance
// of the environment image before intensity (EnvironmentDistribution::averageLuminance),
// unused for a constant environment.
EmitterTable buildEmitterTable(const RenderScene& scene, double environmentAverageLuminance);

// Radius of the bounding sphere of everything the TLAS holds (1 for an empty scene).
float sceneBoundingRadius(const RenderScene& scene);

}  // namespace pt
