#pragma once
// KHR_lights_punctual lights: point, spot and directional. Delta lights: NEE samples them
// with probability 1 once picked, and BSDF sampling never hits them. Spot lights fade
// between the inner and outer cone with the extension's smooth falloff (its implementation
// note): t = saturate((cos(angle) - cos(outer)) / max(1e-3, cos(inner) - cos(outer))), t^2.
#include "render/kernel/render_scene.h"

namespace pt {

struct PunctualSample {
    Vec3 wi;         // unit, towards the light
    Vec3 radiance;   // what arrives from wi, integrated over the delta: I / d^2 x falloff, or E
    Vec3 point;      // the light's position (point, spot)
    float distance;  // kInf for directional lights
};

PT_HD float spotFalloff(const PunctualLight& light, float cosAngle) {
    const float scale = 1.0f / fmaxf(1e-3f, light.cosInner - light.cosOuter);
    const float t = clampf((cosAngle - light.cosOuter) * scale, 0.0f, 1.0f);
    return t * t;
}

PT_HD bool samplePunctualLight(const PunctualLight& light, Vec3 ref, PunctualSample& out) {
    if (light.type == LightType::Directional) {
        out.wi = -light.direction;
        out.radiance = light.intensity;
        out.point = Vec3(0.0f);
        out.distance = kInf;
        return true;
    }
    const Vec3 toLight = light.position - ref;
    const float distance2 = lengthSquared(toLight);
    if (!(distance2 > 0.0f)) return false;
    out.distance = sqrtf(distance2);
    out.wi = toLight / out.distance;
    out.point = light.position;
    out.radiance = light.intensity * (1.0f / distance2);
    if (light.type == LightType::Spot) {
        const float falloff = spotFalloff(light, -dot(out.wi, light.direction));
        if (!(falloff > 0.0f)) return false;
        out.radiance *= falloff;
    }
    return isFinite(out.radiance);
}

// Light-table weight: power / pi. Point: 4 pi I; spot: I over the cone halfway between the
// inner and outer angles, 2 pi I (1 - cos); directional: E over the scene's bounding disk of
// radius `sceneRadius`, pi R^2 E.
PT_HD float punctualLightWeight(const PunctualLight& light, float sceneRadius) {
    const float i = luminance(light.intensity);
    switch (light.type) {
        case LightType::Point: return 4.0f * i;
        case LightType::Spot: return 2.0f * i * fmaxf(1.0f - 0.5f * (light.cosInner + light.cosOuter), 1e-6f);
        case LightType::Directional: return i * sceneRadius * sceneRadius;
    }
    return 0.0f;
}

}  // namespace pt
