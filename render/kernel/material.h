#pragma once
// Material: the glTF 2.0 metallic-roughness model and the KHR_materials_* extensions the
// renderer knows, as one plain struct shared by host and device. The defaults are those an
// artist expects from a fresh material (dielectric, roughness 0.5), not glTF's (metallic 1,
// roughness 1): the glTF importer writes glTF's defaults explicitly. Scene JSON leaves out
// every field equal to these defaults.
#include <cstdint>

#include "render/math/vec.h"

namespace pt {

// A texture slot: index into RenderScene::textures (-1: none) and KHR_texture_transform.
struct TextureRef {
    int32_t texture = -1;
    int32_t texCoord = 0;  // UV set; only set 0 is imported today
    Vec2 offset{0.0f, 0.0f};
    Vec2 scale{1.0f, 1.0f};
    float rotation = 0.0f;  // radians, counter-clockwise in UV space

    PT_HD bool present() const { return texture >= 0; }
};

enum class AlphaMode : uint32_t { Opaque = 0, Mask = 1, Blend = 2 };

struct Material {
    Vec3 baseColor{0.8f, 0.8f, 0.8f};  // linear Rec.709
    float alpha = 1.0f;
    float metallic = 0.0f;
    float roughness = 0.5f;
    Vec3 emission{0.0f, 0.0f, 0.0f};  // emissiveFactor
    float emissionStrength = 1.0f;    // KHR_materials_emissive_strength; radiance = emission * strength
    float ior = 1.5f;                 // KHR_materials_ior
    float transmission = 0.0f;        // KHR_materials_transmission
    float specular = 1.0f;            // KHR_materials_specular: specularFactor
    Vec3 specularColor{1.0f, 1.0f, 1.0f};
    float clearcoat = 0.0f;  // KHR_materials_clearcoat
    float clearcoatRoughness = 0.0f;
    float thickness = 0.0f;  // KHR_materials_volume: thicknessFactor
    Vec3 attenuationColor{1.0f, 1.0f, 1.0f};
    float attenuationDistance = kInf;  // world units; infinity means no absorption
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    float normalScale = 1.0f;
    uint32_t doubleSided = 1;  // back faces shade as front faces with a flipped normal
    // KHR_materials_unlit: the surface shows its base colour (factor times texture) as radiance
    // and scatters no light; the path ends there (path_tracer.h).
    uint32_t unlit = 0;

    TextureRef baseColorTexture;          // sRGB
    TextureRef metallicRoughnessTexture;  // linear: G = roughness, B = metallic
    TextureRef normalTexture;             // linear, tangent space
    TextureRef emissiveTexture;           // sRGB
    TextureRef transmissionTexture;       // linear, R

    // The rare lobes' parameters (scene_features.h, kRareLobes) come after the fields every
    // kernel reads, which keep the offsets they had before these were added.
    float diffuseTransmission = 0.0f;  // KHR_materials_diffuse_transmission: diffuseTransmissionFactor
    Vec3 diffuseTransmissionColor{1.0f, 1.0f, 1.0f};
    TextureRef diffuseTransmissionTexture;       // linear, A
    TextureRef diffuseTransmissionColorTexture;  // sRGB
    Vec3 sheenColor{0.0f, 0.0f, 0.0f};           // KHR_materials_sheen: sheenColorFactor; black: no sheen
    float sheenRoughness = 0.0f;
    TextureRef sheenColorTexture;      // sRGB
    TextureRef sheenRoughnessTexture;  // linear, A
    // KHR_materials_anisotropy: GGX roughness stretched along a direction of the tangent plane.
    float anisotropyStrength = 0.0f;  // 0: isotropic
    float anisotropyRotation = 0.0f;  // radians, counter-clockwise from the tangent (increasing U)
    TextureRef anisotropyTexture;     // linear: RG direction in tangent space ([-1, 1]), B strength
    // KHR_materials_iridescence: a thin film over the specular layer and the metal.
    float iridescence = 0.0f;                // iridescenceFactor; 0: no film
    float iridescenceIor = 1.3f;             // the film's index
    float iridescenceThicknessMin = 100.0f;  // nanometres, at thickness texture G = 0
    float iridescenceThicknessMax = 400.0f;  // nanometres, at G = 1 and without a texture
    TextureRef iridescenceTexture;           // linear, R
    TextureRef iridescenceThicknessTexture;  // linear, G
    // KHR_materials_dispersion: 20 / Abbe number of the transmitting interior; 0: none.
    float dispersion = 0.0f;
    // Scattering media (render/integrator/medium.h). The KHR_materials_volume_scatter proposal:
    // the interior of a volume scatters, its extinction the attenuation above, its albedo what
    // multiple scattering should look like.
    Vec3 scatterColor{0.0f, 0.0f, 0.0f};  // multiscatterColor; black: absorption only
    float scatterAnisotropy = 0.0f;       // Henyey-Greenstein g, here and in the subsurface medium
    // Random-walk subsurface scattering, as OpenPBR and Cycles name it: this share of the
    // non-metal base enters, through the dielectric surface, a medium of the colour and mean free
    // path below (Chiang et al. 2016's inversion: random_walk_albedo.h).
    float subsurface = 0.0f;
    Vec3 subsurfaceColor{0.8f, 0.8f, 0.8f};
    float subsurfaceRadius = 0.05f;  // world units: the mean free path, scaled per channel by
    Vec3 subsurfaceRadiusScale{1.0f, 0.5f, 0.25f};

    PT_HD Vec3 emittedRadiance() const { return emission * emissionStrength; }
    PT_HD bool isEmissive() const { return maxComponent(emission) * emissionStrength > 0.0f; }
};

}  // namespace pt
