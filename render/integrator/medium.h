#pragma once
// The homogeneous media inside volumetric materials. A material is a volume boundary when its
// thickness > 0 (KHR_materials_volume; thickness 0 is thin-walled) or it has subsurface
// scattering; the path's MediumStack (path_state.h) records which volumes it is inside.
//
// Inside, light is absorbed (Beer-Lambert: it keeps exp(-sigma_t d) over a distance d) and, with
// feature::kScatteringMedia, scattered (medium_scattering.h). The coefficients come from
//   - KHR_materials_volume: sigma_t = -ln(attenuationColor) / attenuationDistance, all absorbed
//     unless KHR_materials_volume_scatter's multiscatterColor gives an albedo (van de Hulst);
//   - subsurface: colour and mean free path by Chiang et al.'s inversion (random_walk_albedo.h).
#include "render/integrator/path_state.h"
#include "render/kernel/render_scene.h"
#include "render/materials/random_walk_albedo.h"

namespace pt {

PT_HD bool isVolumeBoundary(const Material& m) { return m.thickness > 0.0f || m.subsurface > 0.0f; }

// An index-matched volume boundary: index 1 and nothing but untextured transmission, so rays
// cross it unbent and unreflected, tinted by the base colour (the glass lobe at eta = 1). Rays
// and shadow rays then pass it without a bounce (transparency.h), which is what lets light be
// sampled into and out of fog in a box.
PT_HD bool isIndexMatchedBoundary(const Material& m) {
    return m.thickness > 0.0f && m.ior == 1.0f && m.transmission >= 1.0f && m.metallic <= 0.0f &&
           m.subsurface <= 0.0f && m.clearcoat <= 0.0f && m.unlit == 0 && m.alphaMode == AlphaMode::Opaque &&
           !m.isEmissive() && !m.transmissionTexture.present() && !m.metallicRoughnessTexture.present() &&
           !m.baseColorTexture.present() && maxComponent(m.sheenColor) <= 0.0f && m.iridescence <= 0.0f;
}

// Absorption coefficient per world unit of KHR_materials_volume; zero without absorption.
PT_HD Vec3 absorptionCoefficient(const Material& m) {
    if (!(m.attenuationDistance > 0.0f) || isInfinite(m.attenuationDistance)) return Vec3(0.0f);
    const Vec3 c = m.attenuationColor;
    const float k = -1.0f / m.attenuationDistance;
    return {k * logf(fmaxf(c.x, 1e-30f)), k * logf(fmaxf(c.y, 1e-30f)), k * logf(fmaxf(c.z, 1e-30f))};
}

struct HomogeneousMedium {
    Vec3 sigmaT;  // extinction per world unit
    Vec3 sigmaS;  // scattering per world unit (<= sigmaT)
    float g;      // Henyey-Greenstein anisotropy

    PT_HD bool scatters() const { return maxComponent(sigmaS) > 0.0f; }
};

// The medium inside `m`. Without kScatteringMedia in kF it only absorbs.
template <FeatureSet kF = kAllFeatures>
PT_HD HomogeneousMedium mediumOf(const Material& m) {
    HomogeneousMedium medium{absorptionCoefficient(m), Vec3(0.0f), m.scatterAnisotropy};
    if constexpr (hasFeature<kF>(feature::kScatteringMedia)) {
        if (m.subsurface > 0.0f) {
            for (int c = 0; c < 3; ++c) {
                const float color = m.subsurfaceColor[c];
                const float meanFreePath = m.subsurfaceRadius * m.subsurfaceRadiusScale[c];
                medium.sigmaT[c] = meanFreePath > 0.0f ? randomWalkExtinction(color, meanFreePath) : 0.0f;
                medium.sigmaS[c] = medium.sigmaT[c] * randomWalkSingleScatterAlbedo(color);
            }
        } else if (maxComponent(m.scatterColor) > 0.0f) {
            for (int c = 0; c < 3; ++c)
                medium.sigmaS[c] =
                    medium.sigmaT[c] * vanDeHulstSingleScatterAlbedo(m.scatterColor[c], medium.g);
        }
    }
    return medium;
}

// Transmittance over `distance` (may be infinite) in one medium.
PT_HD Vec3 transmittance(Vec3 sigmaT, float distance) {
    Vec3 t(1.0f);
    for (int c = 0; c < 3; ++c) {
        if (sigmaT[c] > 0.0f) t[c] = expf(-sigmaT[c] * distance);  // exp(-inf) = 0; 0 x inf never formed
    }
    return t;
}

// Transmittance over `distance` inside `medium` (a material index; kNoMedium: none).
template <FeatureSet kF = kAllFeatures>
PT_HD Vec3 mediumTransmittance(const RenderScene& scene, uint32_t medium, float distance) {
    if (!hasFeature<kF>(feature::kVolume) || medium == kNoMedium) return Vec3(1.0f);
    return transmittance(mediumOf<kF>(scene.materials[medium]).sigmaT, distance);
}

// Transmittance over `distance` inside the path's innermost volume.
template <FeatureSet kF = kAllFeatures>
PT_HD Vec3 mediumTransmittance(const RenderScene& scene, const MediumStack& media, float distance) {
    if (!hasFeature<kF>(feature::kVolume) || media.empty()) return Vec3(1.0f);
    return mediumTransmittance<kF>(scene, media.innermost(), distance);
}

// After a refraction through `material`: entering from its front face, or leaving by its back.
template <FeatureSet kF = kAllFeatures>
PT_HD void crossVolumeBoundary(const RenderScene& scene, MediumStack& media, uint32_t material,
                               bool entering) {
    // Without volumes (scene_features.cpp) the stack would only ever give 1.
    if (!hasFeature<kF>(feature::kVolume) || !isVolumeBoundary(scene.materials[material])) return;
    if (entering)
        media.enter(material);
    else
        media.leave();
}

// The medium on the far side of `material` for a ray leaving a point of it that `media`
// describes, crossing it (entering by its front face or leaving by its back) or not.
template <FeatureSet kF = kAllFeatures>
PT_HD uint32_t mediumBeyond(const RenderScene& scene, MediumStack media, uint32_t material, bool crosses,
                            bool entering) {
    if (!hasFeature<kF>(feature::kVolume)) return kNoMedium;
    if (crosses) crossVolumeBoundary<kF>(scene, media, material, entering);
    return media.empty() ? kNoMedium : media.innermost();
}

}  // namespace pt
