#pragma once
// glTF alpha coverage of a material at a surface point (alphaMode MASK and BLEND): what
// fraction of light the surface stops. Rays use it in render/integrator/transparency.h.
#include "render/materials/texture_sample.h"

namespace pt {

// glTF doubleSided = false means back-face culling: rays pass through the back of such a
// surface. Transmissive materials are exempt: glass must be met from inside to refract out.
PT_HD bool cullsBackFaces(const Material& m) { return !m.doubleSided && m.transmission <= 0.0f; }

// Whether `m` can be transparent anywhere (decides if rays need the alpha test at all).
PT_HD bool materialMayBeTransparent(const Material& m) {
    switch (m.alphaMode) {
        case AlphaMode::Mask: return m.baseColorTexture.present() || m.alpha < m.alphaCutoff;
        case AlphaMode::Blend: return m.baseColorTexture.present() || m.alpha < 1.0f;
        case AlphaMode::Opaque:
        default: return false;
    }
}

// baseColor alpha x the base colour texture's alpha at `uv`.
template <FeatureSet kF = kAllFeatures>
PT_HD float surfaceAlpha(const RenderScene& scene, const Material& m, Vec2 uv) {
    float alpha = m.alpha;
    if (hasFeature<kF>(feature::kBaseColorTexture) && m.baseColorTexture.present())
        alpha *= sampleTexture(scene, m.baseColorTexture, uv, true).w;
    return alpha;
}

// The expected fraction of rays the surface stops at `uv`: 0 or 1 for MASK, alpha for BLEND.
template <FeatureSet kF = kAllFeatures>
PT_HD float surfaceCoverage(const RenderScene& scene, const Material& m, Vec2 uv) {
    if (!hasFeature<kF>(feature::kAlphaMask | feature::kAlphaBlend) || !materialMayBeTransparent(m))
        return 1.0f;
    const float alpha = surfaceAlpha<kF>(scene, m, uv);
    if (m.alphaMode == AlphaMode::Mask) return alpha < m.alphaCutoff ? 0.0f : 1.0f;
    return clampf(alpha, 0.0f, 1.0f);
}

// Whether rays may pass through some surfaces of `m` (alpha, or culled back faces).
PT_HD bool materialMayLetRaysThrough(const Material& m) {
    return materialMayBeTransparent(m) || cullsBackFaces(m);
}

// Whether one ray passes through `m` at `uv`, meeting its front face or not; `u` in [0, 1)
// is the coin for blending (stochastic transparency: the surface stops a ray with
// probability alpha).
template <FeatureSet kF = kAllFeatures>
PT_HD bool passesThrough(const RenderScene& scene, const Material& m, Vec2 uv, bool frontFace, float u) {
    if (hasFeature<kF>(feature::kBackfaceCulling) && !frontFace && cullsBackFaces(m)) return true;
    if (!hasFeature<kF>(feature::kAlphaMask | feature::kAlphaBlend) || !materialMayBeTransparent(m))
        return false;
    const float alpha = surfaceAlpha<kF>(scene, m, uv);
    return m.alphaMode == AlphaMode::Mask ? alpha < m.alphaCutoff : u >= alpha;
}

}  // namespace pt
