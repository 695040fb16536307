#pragma once
// Beer-Lambert absorption inside volumetric materials (KHR_materials_volume): light
// travelling a distance d inside keeps exp(-sigma d) per channel, with
// sigma = -ln(attenuationColor) / attenuationDistance. There is no scattering in the volume.
// A material is a volume boundary when its thickness > 0 (thickness 0 is thin-walled); the
// path's MediumStack (path_state.h) records which volumes it is inside.
#include "render/integrator/path_state.h"
#include "render/scene/render_scene.h"

namespace pt {

PT_HD bool isVolumeBoundary(const Material& m) { return m.thickness > 0.0f; }

// Absorption coefficient per world unit; zero without absorption.
PT_HD Vec3 absorptionCoefficient(const Material& m) {
    if (!(m.attenuationDistance > 0.0f) || isInfinite(m.attenuationDistance)) return Vec3(0.0f);
    const Vec3 c = m.attenuationColor;
    const float k = -1.0f / m.attenuationDistance;
    return {k * logf(fmaxf(c.x, 1e-30f)), k * logf(fmaxf(c.y, 1e-30f)), k * logf(fmaxf(c.z, 1e-30f))};
}

// Transmittance over `distance` (may be infinite) inside the path's innermost volume.
template <FeatureSet kF = kAllFeatures>
PT_HD Vec3 mediumTransmittance(const RenderScene& scene, const MediumStack& media, float distance) {
    if (!hasFeature<kF>(feature::kVolume) || media.empty()) return Vec3(1.0f);
    const Vec3 sigma = absorptionCoefficient(scene.materials[media.innermost()]);
    Vec3 t(1.0f);
    for (int c = 0; c < 3; ++c) {
        if (sigma[c] > 0.0f) t[c] = expf(-sigma[c] * distance);  // exp(-inf) = 0; 0 x inf never formed
    }
    return t;
}

// After a refraction through `material`: entering from its front face, or leaving by its back.
template <FeatureSet kF = kAllFeatures>
PT_HD void crossVolumeBoundary(const RenderScene& scene, MediumStack& media, uint32_t material,
                               bool entering) {
    // Without absorbing volumes (scene_features.cpp) the stack would only ever give 1.
    if (!hasFeature<kF>(feature::kVolume) || !isVolumeBoundary(scene.materials[material])) return;
    if (entering)
        media.enter(material);
    else
        media.leave();
}

}  // namespace pt
