#pragma once
// Resolves a Material at a surface point into BsdfParams: glTF factors times their textures
// (with KHR_texture_transform), clamped to the ranges the BSDF assumes. Normal maps, emission
// and alpha coverage (alpha.h) are resolved elsewhere.
#include "render/materials/bsdf.h"
#include "render/materials/texture_sample.h"

namespace pt {

template <FeatureSet kF = kAllFeatures>
PT_HD BsdfParams bsdfParamsAt(const RenderScene& scene, const Material& m, Vec2 uv) {
    BsdfParams p{m.baseColor, m.metallic, m.transmission, m.ior};
    p.roughness = m.roughness;
    p.specular = m.specular;
    p.specularColor = m.specularColor;
    p.clearcoat = m.clearcoat;
    p.clearcoatRoughness = m.clearcoatRoughness;
    if (hasFeature<kF>(feature::kBaseColorTexture) && m.baseColorTexture.present()) {
        p.baseColor *= sampleTexture(scene, m.baseColorTexture, uv, true).xyz();  // sRGB
    }
    if (hasFeature<kF>(feature::kMetallicRoughnessTexture) && m.metallicRoughnessTexture.present()) {
        const Vec4 mr = sampleTexture(scene, m.metallicRoughnessTexture, uv, false);
        p.roughness *= mr.y;
        p.metallic *= mr.z;
    }
    if (hasFeature<kF>(feature::kTransmissionTexture) && m.transmissionTexture.present()) {
        p.transmission *= sampleTexture(scene, m.transmissionTexture, uv, false).x;
    }
    p.baseColor = vmax(p.baseColor, Vec3(0.0f));
    p.metallic = clampf(p.metallic, 0.0f, 1.0f);
    p.roughness = clampf(p.roughness, 0.0f, 1.0f);
    p.transmission = clampf(p.transmission, 0.0f, 1.0f);
    if (hasFeature<kF>(feature::kScatteringMedia) && m.subsurface > 0.0f) {
        // Subsurface takes its share of what would be diffuse and passes it through the same
        // dielectric interface as transmission, untinted (the medium colours it).
        const float subsurface = (1.0f - p.transmission) * fminf(m.subsurface, 1.0f);
        p.transmission += subsurface;
        p.untintedTransmission = subsurface / p.transmission;
    }
    p.ior = p.ior >= 1.0f ? p.ior : 1.0f;  // also maps NaN to index-matched
    p.specular = clampf(p.specular, 0.0f, 1.0f);
    p.clearcoat = clampf(p.clearcoat, 0.0f, 1.0f);
    p.clearcoatRoughness = clampf(p.clearcoatRoughness, 0.0f, 1.0f);
    if (hasFeature<kF>(feature::kDiffuseTransmission)) {
        p.diffuseTransmission = m.diffuseTransmission;
        p.diffuseTransmissionColor = m.diffuseTransmissionColor;
        if (m.diffuseTransmissionTexture.present())
            p.diffuseTransmission *= sampleTexture(scene, m.diffuseTransmissionTexture, uv, false).w;
        if (m.diffuseTransmissionColorTexture.present())
            p.diffuseTransmissionColor *=
                sampleTexture(scene, m.diffuseTransmissionColorTexture, uv, true).xyz();
        p.diffuseTransmission = clampf(p.diffuseTransmission, 0.0f, 1.0f);
        p.diffuseTransmissionColor = vmax(p.diffuseTransmissionColor, Vec3(0.0f));
    }
    if (hasFeature<kF>(feature::kSheen)) {
        p.sheenColor = m.sheenColor;
        p.sheenRoughness = m.sheenRoughness;
        if (m.sheenColorTexture.present())
            p.sheenColor *= sampleTexture(scene, m.sheenColorTexture, uv, true).xyz();
        if (m.sheenRoughnessTexture.present())
            p.sheenRoughness *= sampleTexture(scene, m.sheenRoughnessTexture, uv, false).w;
        p.sheenColor = vmin(vmax(p.sheenColor, Vec3(0.0f)), Vec3(1.0f));
        p.sheenRoughness = clampf(p.sheenRoughness, 0.0f, 1.0f);
    }
    if (hasFeature<kF>(feature::kAnisotropy) && m.anisotropyStrength > 0.0f) {
        // KHR_materials_anisotropy: the texture's RG is a direction in [-1, 1] tangent space, B
        // scales the strength; the rotation turns the direction counter-clockwise.
        Vec2 direction{1.0f, 0.0f};
        p.anisotropy = m.anisotropyStrength;
        if (m.anisotropyTexture.present()) {
            const Vec4 t = sampleTexture(scene, m.anisotropyTexture, uv, false);
            direction = {2.0f * t.x - 1.0f, 2.0f * t.y - 1.0f};
            p.anisotropy *= t.z;
        }
        const float c = cosf(m.anisotropyRotation), s = sinf(m.anisotropyRotation);
        const Vec2 turned{c * direction.x - s * direction.y, s * direction.x + c * direction.y};
        const float length = sqrtf(turned.x * turned.x + turned.y * turned.y);
        p.anisotropyDirection = length > 0.0f ? turned * (1.0f / length) : Vec2{c, s};
        p.anisotropy = clampf(p.anisotropy, 0.0f, 1.0f);
    }
    if (hasFeature<kF>(feature::kIridescence) && m.iridescence > 0.0f) {
        // KHR_materials_iridescence: R scales the weight, G picks the thickness between the
        // minimum and the maximum (the maximum without a texture).
        p.iridescence = m.iridescence;
        p.iridescenceIor = m.iridescenceIor;
        p.iridescenceThickness = m.iridescenceThicknessMax;
        if (m.iridescenceTexture.present())
            p.iridescence *= sampleTexture(scene, m.iridescenceTexture, uv, false).x;
        if (m.iridescenceThicknessTexture.present()) {
            const float g = sampleTexture(scene, m.iridescenceThicknessTexture, uv, false).y;
            p.iridescenceThickness =
                m.iridescenceThicknessMin + (m.iridescenceThicknessMax - m.iridescenceThicknessMin) * g;
        }
        p.iridescence = clampf(p.iridescence, 0.0f, 1.0f);
        p.iridescenceIor = p.iridescenceIor >= 1.0f ? p.iridescenceIor : 1.0f;
        p.iridescenceThickness = clampf(p.iridescenceThickness, 0.0f, 1e5f);  // also maps NaN to 0
    }
    return p;
}

}  // namespace pt
