// bsdfParamsAt: glTF factors times their textures (sRGB base color, linear metallic-roughness
// G/B and transmission R), through KHR_texture_transform, clamped for the BSDF.
#include "render/materials/material_eval.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace pt {
namespace {

// Three 2 x 1 RGBA8 textures with nearest filtering: base color, metallic-roughness, transmission.
struct TexturedScene {
    std::vector<uint8_t> texels = {
        128, 64,  255, 200, /**/ 255, 255, 255, 255,  // base color: left texel, right texel
        0,   128, 255, 0,   /**/ 0,   255, 51,  0,    // metallic-roughness: G roughness, B metallic
        51,  0,   0,   0,   /**/ 255, 0,   0,   0,    // transmission: R
    };
    std::vector<TextureView> views;
    RenderScene scene{};

    TexturedScene() {
        for (uint32_t i = 0; i < 3; ++i) {
            views.push_back({2, 1, TexelFormat::RGBA8, WrapMode::Repeat, WrapMode::Repeat, 1, 2 * i});
        }
        scene.textures = {views.data(), uint32_t(views.size())};
        scene.texels8 = {texels.data(), uint32_t(texels.size())};
    }
};

Material texturedMaterial() {
    Material m;
    m.baseColor = {0.5f, 1.0f, 1.0f};
    m.metallic = 0.8f;
    m.roughness = 0.6f;
    m.transmission = 0.5f;
    m.baseColorTexture.texture = 0;
    m.metallicRoughnessTexture.texture = 1;
    m.transmissionTexture.texture = 2;
    return m;
}

TEST(MaterialEval, FactorsMultiplyTheirTextures) {
    TexturedScene t;
    const Material m = texturedMaterial();
    const BsdfParams p = bsdfParamsAt(t.scene, m, {0.25f, 0.5f});  // the left texels
    EXPECT_NEAR(p.baseColor.x, 0.5f * srgbToLinear(128.0f / 255.0f), 1e-6f);
    EXPECT_NEAR(p.baseColor.y, srgbToLinear(64.0f / 255.0f), 1e-6f);
    EXPECT_NEAR(p.baseColor.z, 1.0f, 1e-6f);
    EXPECT_NEAR(p.roughness, 0.6f * 128.0f / 255.0f, 1e-6f);  // linear, not sRGB
    EXPECT_NEAR(p.metallic, 0.8f, 1e-6f);
    EXPECT_NEAR(p.transmission, 0.5f * 0.2f, 1e-6f);
    EXPECT_FLOAT_EQ(p.ior, m.ior);
    EXPECT_FLOAT_EQ(p.specular, m.specular);
}

TEST(MaterialEval, TexturesFollowTheTextureTransform) {
    TexturedScene t;
    Material m = texturedMaterial();
    m.metallicRoughnessTexture.offset = {0.5f, 0.0f};  // the left uv now reads the right texel
    const BsdfParams p = bsdfParamsAt(t.scene, m, {0.25f, 0.5f});
    EXPECT_NEAR(p.roughness, 0.6f, 1e-6f);
    EXPECT_NEAR(p.metallic, 0.8f * 0.2f, 1e-6f);
}

TEST(MaterialEval, WithoutTexturesTheFactorsPassThroughClamped) {
    const RenderScene scene{};
    Material m;
    m.baseColor = {0.2f, 0.3f, 0.4f};
    m.roughness = 1.5f;
    m.metallic = -0.1f;
    m.ior = 0.5f;
    m.clearcoat = 0.7f;
    m.clearcoatRoughness = 0.1f;
    m.specular = 0.3f;
    m.specularColor = {2.0f, 1.0f, 0.5f};
    const BsdfParams p = bsdfParamsAt(scene, m, {0.0f, 0.0f});
    EXPECT_EQ(p.baseColor, m.baseColor);
    EXPECT_FLOAT_EQ(p.roughness, 1.0f);
    EXPECT_FLOAT_EQ(p.metallic, 0.0f);
    EXPECT_FLOAT_EQ(p.ior, 1.0f);
    EXPECT_FLOAT_EQ(p.clearcoat, 0.7f);
    EXPECT_FLOAT_EQ(p.clearcoatRoughness, 0.1f);
    EXPECT_FLOAT_EQ(p.specular, 0.3f);
    EXPECT_EQ(p.specularColor, m.specularColor);  // may exceed 1 (KHR_materials_specular)
    m.ior = NAN;
    EXPECT_FLOAT_EQ(bsdfParamsAt(scene, m, {0.0f, 0.0f}).ior, 1.0f);
}

}  // namespace
}  // namespace pt
