#pragma once
// Radiance from the environment for rays that leave the scene: a constant color, or an
// equirectangular image (+Y up; u = 0.5 looks down -Z, u grows towards +X; v = 0 is up),
// rotated about +Y and scaled by its intensity.
#include "render/kernel/render_scene.h"
#include "render/materials/texture_sample.h"

namespace pt {

PT_HD Vec2 directionToEquirect(Vec3 d, float rotationRadians) {
    const float phi = atan2f(d.x, -d.z) - rotationRadians;
    float u = phi * (0.5f * kInvPi) + 0.5f;
    u -= floorf(u);
    const float v = acosf(clampf(d.y, -1.0f, 1.0f)) * kInvPi;
    return {u, v};
}

// The inverse of directionToEquirect: the unit direction at (u, v) of the equirect square.
PT_HD Vec3 equirectToDirection(Vec2 uv, float rotationRadians) {
    const float phi = (uv.x - 0.5f) * (2.0f * kPi) + rotationRadians;
    const float theta = uv.y * kPi;
    const float sinTheta = sinf(theta);
    return {sinTheta * sinf(phi), cosf(theta), -sinTheta * cosf(phi)};
}

template <FeatureSet kF = kAllFeatures>
PT_HD Vec3 environmentRadiance(const RenderScene& scene, Vec3 direction) {
    const RenderEnvironment& env = scene.environment;
    if (!hasFeature<kF>(feature::kImageEnvironment) || env.texture < 0) return env.color;
    TextureRef ref;
    ref.texture = env.texture;
    const Vec3 d = normalize(direction);
    return sampleTexture(scene, ref, directionToEquirect(d, env.rotationRadians), false).xyz() *
           env.intensity;
}

}  // namespace pt
