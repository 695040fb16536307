#pragma once
// Texture lookups: KHR_texture_transform, glTF wrap modes, bilinear or nearest filtering,
// and sRGB decode for color slots. Returns linear RGBA.
#include "render/kernel/render_scene.h"

namespace pt {

PT_HD float srgbToLinear(float c) {
    return c <= 0.04045f ? c * (1.0f / 12.92f) : powf((c + 0.055f) * (1.0f / 1.055f), 2.4f);
}

PT_HD Vec2 applyTextureTransform(const TextureRef& ref, Vec2 uv) {
    // glTF order: scale, then rotate, then translate.
    const Vec2 s{uv.x * ref.scale.x, uv.y * ref.scale.y};
    if (ref.rotation == 0.0f) return s + ref.offset;
    const float c = cosf(ref.rotation), n = sinf(ref.rotation);
    return Vec2{c * s.x + n * s.y, -n * s.x + c * s.y} + ref.offset;
}

PT_HD int wrapTexel(int i, int size, WrapMode mode) {
    switch (mode) {
        case WrapMode::ClampToEdge: return i < 0 ? 0 : (i >= size ? size - 1 : i);
        case WrapMode::MirroredRepeat: {
            const int period = 2 * size;
            int m = i % period;
            if (m < 0) m += period;
            return m < size ? m : period - 1 - m;
        }
        case WrapMode::Repeat:
        default: {
            const int m = i % size;
            return m < 0 ? m + size : m;
        }
    }
}

// Where a texture's texels live: the scene's two texel arrays, passed as plain pointers so the
// out-of-line sampler below takes no reference to the scene.
struct TexelArrays {
    const uint8_t* texels8;
    const float* texelsF;
};

PT_HD Vec4 fetchTexel(const TexelArrays& texels, const TextureView& tex, int x, int y, bool srgb) {
    const uint32_t index = tex.texelOffset + uint32_t(y) * tex.width + uint32_t(x);
    if (tex.format == TexelFormat::RGBA32F) {
        const float* t = texels.texelsF + size_t(index) * 4;
        return {t[0], t[1], t[2], t[3]};
    }
    const uint8_t* t = texels.texels8 + size_t(index) * 4;
    const float k = 1.0f / 255.0f;
    Vec4 c{t[0] * k, t[1] * k, t[2] * k, t[3] * k};
    if (srgb) c = {srgbToLinear(c.x), srgbToLinear(c.y), srgbToLinear(c.z), c.w};
    return c;
}

// Linear RGBA of texture `tex` at `uv` (glTF convention: v = 0 is the top row of the image).
// Out of line on the GPU (PT_HD_OUTLINED): material, alpha, normal-map, emission and
// environment lookups all call this one copy.
PT_HD_OUTLINED Vec4 sampleTextureView(TexelArrays texels, TextureView tex, TextureRef ref, Vec2 uv,
                                      bool srgb) {
    const Vec2 st = applyTextureTransform(ref, uv);
    const float fx = st.x * float(tex.width) - 0.5f, fy = st.y * float(tex.height) - 0.5f;
    const int w = int(tex.width), h = int(tex.height);
    if (tex.nearest) {
        return fetchTexel(texels, tex, wrapTexel(int(floorf(fx + 0.5f)), w, tex.wrapS),
                          wrapTexel(int(floorf(fy + 0.5f)), h, tex.wrapT), srgb);
    }
    const float x0f = floorf(fx), y0f = floorf(fy);
    const float ax = fx - x0f, ay = fy - y0f;
    const int x0 = int(x0f), y0 = int(y0f);
    const int xa = wrapTexel(x0, w, tex.wrapS), xb = wrapTexel(x0 + 1, w, tex.wrapS);
    const int ya = wrapTexel(y0, h, tex.wrapT), yb = wrapTexel(y0 + 1, h, tex.wrapT);
    // Decode before filtering: filtering sRGB-encoded values would darken edges.
    const Vec4 c00 = fetchTexel(texels, tex, xa, ya, srgb), c10 = fetchTexel(texels, tex, xb, ya, srgb);
    const Vec4 c01 = fetchTexel(texels, tex, xa, yb, srgb), c11 = fetchTexel(texels, tex, xb, yb, srgb);
    auto mix = [](Vec4 a, Vec4 b, float t) {
        return Vec4{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t,
                    a.w + (b.w - a.w) * t};
    };
    return mix(mix(c00, c10, ax), mix(c01, c11, ax), ay);
}

// Linear RGBA of the scene texture `ref` names at `uv`.
PT_HD Vec4 sampleTexture(const RenderScene& scene, const TextureRef& ref, Vec2 uv, bool srgb) {
    return sampleTextureView({scene.texels8.data, scene.texelsF.data}, scene.textures[uint32_t(ref.texture)],
                             ref, uv, srgb);
}

}  // namespace pt
