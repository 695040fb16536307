// readTextureFile / decodeTextureFromMemory on the images of tests/data/gltf (written by
// make_fixtures.py: checker.png is 2x2 RGBA red, green at alpha 128, blue at alpha 0, white;
// gray.png 2x1 gray 0 and 200; rgba16.png one 16-bit texel; tiny.hdr 2x1 (1, .5, .25) and
// (2, 4, 8)) and on the shared JPEG and HDR files.
#include "assets/image/image_read.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "assets/input_error.h"
#include "support/test_paths.h"

namespace pt {
namespace {

std::vector<uint8_t> fileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string decodeError(const std::vector<uint8_t>& bytes, const std::string& name,
                        const std::string& mimeType = "") {
    try {
        decodeTextureFromMemory(bytes, name, mimeType);
    } catch (const InputError& e) {
        return e.what();
    }
    ADD_FAILURE() << name << " decoded without an error";
    return "";
}

const std::vector<uint8_t> kChecker = {255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 0, 255, 255, 255, 255};

TEST(ImageRead, PngFileAsRgba8WithStraightAlpha) {
    const Texture t = readTextureFile(test::testDataPath("gltf/checker.png"));
    EXPECT_EQ(t.width, 2u);
    EXPECT_EQ(t.height, 2u);
    EXPECT_EQ(t.format, TexelFormat::RGBA8);
    EXPECT_EQ(t.texels8, kChecker);  // first row first; transparent blue keeps its color
    EXPECT_TRUE(t.texelsF.empty());
    EXPECT_EQ(t.name, "checker.png");
    EXPECT_EQ(t.sourcePath, test::testDataPath("gltf/checker.png"));
}

TEST(ImageRead, PngFromMemoryMatchesTheFile) {
    const Texture t = decodeTextureFromMemory(fileBytes(test::testDataPath("gltf/checker.png")),
                                              "model.glb: images[0]", "image/png");
    EXPECT_EQ(t.texels8, kChecker);
    EXPECT_EQ(t.name, "model.glb: images[0]");
}

TEST(ImageRead, GrayExpandsToRgbaWithOpaqueAlpha) {
    const Texture t = readTextureFile(test::testDataPath("gltf/gray.png"));
    EXPECT_EQ(t.texels8, (std::vector<uint8_t>{0, 0, 0, 255, 200, 200, 200, 255}));
}

TEST(ImageRead, SixteenBitPngRoundsToEightBits) {
    const Texture t = readTextureFile(test::testDataPath("gltf/rgba16.png"));
    ASSERT_EQ(t.format, TexelFormat::RGBA8);
    EXPECT_EQ(t.texels8, (std::vector<uint8_t>{255, 128, 0, 255}));
}

TEST(ImageRead, RadianceHdrAsRgba32F) {
    for (const Texture& t :
         {readTextureFile(test::testDataPath("gltf/tiny.hdr")),
          decodeTextureFromMemory(fileBytes(test::testDataPath("gltf/tiny.hdr")), "tiny.hdr")}) {
        ASSERT_EQ(t.format, TexelFormat::RGBA32F);
        ASSERT_EQ(t.texelsF.size(), 8u);
        const float expected[8] = {1.0f, 0.5f, 0.25f, 1.0f, 2.0f, 4.0f, 8.0f, 1.0f};
        for (int i = 0; i < 8; ++i) EXPECT_NEAR(t.texelsF[size_t(i)], expected[i], 1e-3f) << i;
        EXPECT_TRUE(t.texels8.empty());
    }
}

TEST(ImageRead, UndecodableBytesGiveInputErrorsNamingTheImage) {
    EXPECT_NE(decodeError(fileBytes(test::testDataPath("gltf/fake.ktx2")), "lamp.gltf: images[1]")
                  .find("lamp.gltf: images[1]: KTX2"),
              std::string::npos);
    EXPECT_NE(decodeError(fileBytes(test::testDataPath("gltf/broken.png")), "broken").find("broken: "),
              std::string::npos);
    EXPECT_NE(decodeError({1, 2, 3, 4, 5}, "junk", "image/x-unknown").find("junk: not an image format"),
              std::string::npos);
    // A known type (glTF's EXT_texture_webp) whose bytes are not one: the reader's error, named.
    const std::string webp = decodeError({1, 2, 3, 4, 5}, "junk.webp", "image/webp");
    EXPECT_EQ(webp.rfind("junk.webp: ", 0), 0u) << webp;
    EXPECT_NE(decodeError({}, "empty").find("empty: image is empty"), std::string::npos);
}

TEST(ImageRead, MissingOrBrokenFileGivesInputErrorNamingThePath) {
    const std::string missing = test::testDataPath("gltf/no_such_image.png");
    try {
        readTextureFile(missing);
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
    }
    EXPECT_THROW(readTextureFile(test::testDataPath("gltf/broken.png")), InputError);
}

TEST(ImageRead, SharedJpegAndHdr) {
    PT_REQUIRE_SHARED_ASSET("AnisotropyBarnLamp/AnisotropyBarnLamp_basecolor.jpeg");
    const std::string jpeg = test::sharedAsset("AnisotropyBarnLamp/AnisotropyBarnLamp_basecolor.jpeg");
    const Texture fromFile = readTextureFile(jpeg);
    EXPECT_EQ(fromFile.format, TexelFormat::RGBA8);
    EXPECT_EQ(fromFile.texels8.size(), size_t(fromFile.width) * fromFile.height * 4);
    EXPECT_EQ(decodeTextureFromMemory(fileBytes(jpeg), "jpeg").texels8, fromFile.texels8);
    const Texture hdr = readTextureFile(test::sharedAsset("environments/venice_sunset_1k.hdr"));
    EXPECT_EQ(hdr.width, 1024u);
    EXPECT_EQ(hdr.height, 512u);
    EXPECT_EQ(hdr.format, TexelFormat::RGBA32F);
}

}  // namespace
}  // namespace pt
