#pragma once
// Texture lookups: KHR_texture_transform, glTF wrap modes, bilinear or nearest filtering,
// and sRGB decode for color slots. Returns linear RGBA.
#include "render/scene/render_scene.h"

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

PT_HD Vec4 fetchTexel(const RenderScene& scene, const TextureView& tex, int x, int y, bool srgb) {
    const uint32_t index = tex.texelOffset + uint32_t(y) * tex.width + uint32_t(x);
    if (tex.format == TexelFormat::RGBA32F) {
        const float* t = scene.texelsF.data + size_t(index) * 4;
        return {t[0], t[1], t[2], t[3]};
    }
    const uint8_t* t = scene.texels8.data + size_t(index) * 4;
    const float k = 1.0f / 255.0f;
    Vec4 c{t[0] * k, t[1] * k, t[2] * k, t[3] * k};
    if (srgb) c = {srgbToLinear(c.x), srgbToLinear(c.y), srgbToLinear(c.z), c.w};
    return c;
}

// Linear RGBA at `uv` (glTF convention: v = 0 is the top row of the image).
PT_HD Vec4 sampleTexture(const RenderScene& scene, const TextureRef& ref, Vec2 uv, bool srgb) {
    const TextureView& tex = scene.textures[uint32_t(ref.texture)];
    const Vec2 st = applyTextureTransform(ref, uv);
    const float fx = st.x * float(tex.width) - 0.5f, fy = st.y * float(tex.height) - 0.5f;
    const int w = int(tex.width), h = int(tex.height);
    if (tex.nearest) {
        return fetchTexel(scene, tex, wrapTexel(int(floorf(fx + 0.5f)), w, tex.wrapS),
                          wrapTexel(int(floorf(fy + 0.5f)), h, tex.wrapT), srgb);
    }
    const float x0f = floorf(fx), y0f = floorf(fy);
    const float ax = fx - x0f, ay = fy - y0f;
    const int x0 = int(x0f), y0 = int(y0f);
    const int xa = wrapTexel(x0, w, tex.wrapS), xb = wrapTexel(x0 + 1, w, tex.wrapS);
    const int ya = wrapTexel(y0, h, tex.wrapT), yb = wrapTexel(y0 + 1, h, tex.wrapT);
    // Decode before filtering: filtering sRGB-encoded values would darken edges.
    const Vec4 c00 = fetchTexel(scene, tex, xa, ya, srgb), c10 = fetchTexel(scene, tex, xb, ya, srgb);
    const Vec4 c01 = fetchTexel(scene, tex, xa, yb, srgb), c11 = fetchTexel(scene, tex, xb, yb, srgb);
    auto mix = [](Vec4 a, Vec4 b, float t) {
        return Vec4{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t,
                    a.w + (b.w - a.w) * t};
    };
    return mix(mix(c00, c10, ax), mix(c01, c11, ax), ay);
}

}  // namespace pt
