// EXT_texture_webp (assets/gltf_textures.h): a texture's WebP source (encoded here with libwebp,
// lossless) is the image a material shows where the build decodes WebP, its PNG fallback where
// it does not; a texture with only a WebP source shows it, or warns once and falls back to the
// factors.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "assets/gltf_quad_json.h"
#include "assets/model_import.h"
#include "assets/scene_test_helpers.h"
#if PT_TEST_HAVE_WEBP
#include <webp/encode.h>
#endif

namespace pt {
namespace {

#if PT_TEST_HAVE_WEBP

// 2 x 2 texels no PNG in tests/data holds.
const std::vector<uint8_t> kTexels = {200, 10, 20, 255, 30, 210, 40, 255, 50, 60, 220, 255, 90, 90, 90, 255};

// A quad (the fixtures' buffer) with material 0 showing texture `texture`: 0 has a PNG source
// and a WebP one, 1 only a WebP one.
std::string quadGltf(int texture) {
    const std::string folder = test::testFolder();
    uint8_t* webp = nullptr;
    const size_t bytes = WebPEncodeLosslessRGBA(kTexels.data(), 2, 2, 8, &webp);
    test::writeFile(folder, "tex.webp", std::string(reinterpret_cast<const char*>(webp), bytes));
    WebPFree(webp);
    std::filesystem::copy_file(test::testDataPath("gltf/checker.png"), folder + "/fallback.png");
    return test::writeFile(folder, "quad.gltf",
                           R"({"asset": {"version": "2.0"}, "extensionsUsed": ["EXT_texture_webp"],
  "images": [{"uri": "tex.webp", "mimeType": "image/webp"}, {"uri": "fallback.png"}],
  "textures": [{"source": 1, "extensions": {"EXT_texture_webp": {"source": 0}}},
               {"extensions": {"EXT_texture_webp": {"source": 0}}}],
  "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": )" +
                               std::to_string(texture) + R"(}}}],
  )" + test::quadGltfGeometry() +
                               R"(,
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3, "material": 0}]}],
  "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})");
}

// The texels of the texture the quad's material shows (empty: none).
std::vector<uint8_t> shown(const Scene& scene) {
    for (const NamedMaterial& m : scene.materials) {
        const int32_t t = m.params.baseColorTexture.texture;
        if (t >= 0) return scene.textures.at(size_t(t)).texels8;
    }
    return {};
}

TEST(GltfWebp, TheWebpSourceWhereItCanBeDecodedElseThePngFallback) {
    Scene scene;
    importGltf(quadGltf(0), 0, scene);
    const std::vector<uint8_t> texels = shown(scene);
    ASSERT_FALSE(texels.empty()) << "the material shows a texture either way";
    if (PT_TEST_HAVE_OIIO) {
        EXPECT_EQ(texels, kTexels) << "the WebP image, texel for texel (lossless)";
        for (const std::string& w : scene.warnings)
            EXPECT_EQ(w.find("EXT_texture_webp"), std::string::npos) << w;
    } else {
        EXPECT_NE(texels, kTexels) << "without OpenImageIO: the PNG fallback";
        // ... and the extension, which this build cannot decode, is named once as ignored.
        ASSERT_EQ(scene.warnings.size(), 1u);
        EXPECT_NE(scene.warnings[0].find("EXT_texture_webp is not supported; ignored"), std::string::npos)
            << scene.warnings[0];
    }
}

TEST(GltfWebp, OnlyAWebpSource) {
    Scene scene;
    importGltf(quadGltf(1), 0, scene);
    if (PT_TEST_HAVE_OIIO) {
        EXPECT_EQ(shown(scene), kTexels);
    } else {
        EXPECT_TRUE(shown(scene).empty()) << "nothing to decode it with: the factors";
        ASSERT_FALSE(scene.warnings.empty());
    }
}

#else

TEST(GltfWebp, NeedsLibwebp) {
    GTEST_SKIP() << "libwebp is not installed here (libwebp-dev), to encode the fixture";
}

#endif

}  // namespace
}  // namespace pt
