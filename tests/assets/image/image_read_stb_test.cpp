// The stb_image decoder (and stb_image_write encoder) that replace OpenImageIO in a PT_OIIO=OFF
// build. In the normal build they are held to OIIO: identical texels for every PNG, BMP, TGA
// and HDR fixture (tests/data/images, written by make_fixtures.py, and the tests/data/gltf
// images), JPEG within a small tolerance. In both builds: known texel values, errors naming
// the image, and what each build does with EXR.
#include "assets/image/image_read_stb.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "assets/image/image_read.h"
#include "assets/image/image_write.h"
#include "assets/image/image_write_stb.h"
#include "assets/input_error.h"
#include "assets/scene_test_helpers.h"
#include "support/input_error_of.h"
#include "support/test_paths.h"

namespace pt {
namespace {

using test::inputErrorOf;

std::vector<uint8_t> fileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const std::string& path, const std::vector<uint8_t>& bytes) {
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

std::string imagePath(const std::string& name) { return test::testDataPath("images/" + name); }

Texture stbDecodeFile(const std::string& path) { return decodeTextureWithStb(fileBytes(path), path); }

// Same size, format and texels, bit for bit; a failure names the first differing texel.
void expectIdentical(const Texture& oiio, const Texture& stb, const std::string& what) {
    ASSERT_EQ(oiio.width, stb.width) << what;
    ASSERT_EQ(oiio.height, stb.height) << what;
    ASSERT_EQ(oiio.format, stb.format) << what;
    ASSERT_EQ(oiio.texels8.size(), stb.texels8.size()) << what;
    ASSERT_EQ(oiio.texelsF.size(), stb.texelsF.size()) << what;
    for (size_t i = 0; i < oiio.texels8.size(); ++i) {
        ASSERT_EQ(int(oiio.texels8[i]), int(stb.texels8[i]))
            << what << ": texel " << i / 4 << " channel " << i % 4;
    }
    for (size_t i = 0; i < oiio.texelsF.size(); ++i) {
        ASSERT_TRUE(test::bitsEqual(oiio.texelsF[i], stb.texelsF[i]))
            << what << ": texel " << i / 4 << " channel " << i % 4 << ": " << oiio.texelsF[i] << " vs "
            << stb.texelsF[i];
    }
}

// Largest and mean absolute difference of two RGBA8 textures of one size.
std::pair<int, double> rgba8Difference(const Texture& a, const Texture& b) {
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    EXPECT_EQ(a.texels8.size(), b.texels8.size());
    int largest = 0;
    double sum = 0.0;
    const size_t n = std::min(a.texels8.size(), b.texels8.size());
    for (size_t i = 0; i < n; ++i) {
        const int d = std::abs(int(a.texels8[i]) - int(b.texels8[i]));
        largest = std::max(largest, d);
        sum += d;
    }
    return {largest, n ? sum / double(n) : 0.0};
}

// A smooth display image with some texture: what renders look like.
std::vector<uint8_t> testPattern(uint32_t width, uint32_t height) {
    std::vector<uint8_t> rgb(size_t(width) * height * 3);
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            uint8_t* p = &rgb[(size_t(y) * width + x) * 3];
            p[0] = uint8_t(x * 255 / (width - 1));
            p[1] = uint8_t(y * 255 / (height - 1));
            p[2] = uint8_t(((x / 8 + y / 8) % 2) ? 200 : 60);
        }
    }
    return rgb;
}

// texel(x, y) of make_fixtures.py's BMP and TGA fixtures.
std::vector<uint8_t> fixtureTexel(int x, int y, int alpha = 255) {
    return {uint8_t(40 * x + 10), uint8_t(60 * y + 20), uint8_t(200 - 30 * x), uint8_t(alpha)};
}

std::vector<uint8_t> texelAt(const Texture& t, uint32_t x, uint32_t y) {
    const size_t at = (size_t(y) * t.width + x) * 4;
    return {t.texels8.begin() + std::ptrdiff_t(at), t.texels8.begin() + std::ptrdiff_t(at + 4)};
}

const char* const kPngFixtures[] = {
    "images/ramp16.png",    "images/palette_trns.png", "images/gray_alpha.png",
    "images/gray_trns.png", "images/gray2.png",        "images/interlaced.png",
    "gltf/checker.png",     "gltf/gray.png",           "gltf/rgba16.png"};

// --- stb against OpenImageIO ----------------------------------------------------------------

TEST(ImageReadStb, PngTexelsIdenticalToOpenImageIo) {
    PT_REQUIRE_OIIO();
    for (const char* fixture : kPngFixtures) {
        const std::string path = test::testDataPath(fixture);
        expectIdentical(readTextureFile(path), stbDecodeFile(path), fixture);
        expectIdentical(decodeTextureFromMemory(fileBytes(path), fixture, "image/png"), stbDecodeFile(path),
                        std::string(fixture) + " from memory");
    }
}

TEST(ImageReadStb, BmpAndTgaTexelsIdenticalToOpenImageIo) {
    PT_REQUIRE_OIIO();
    for (const char* fixture : {"rgb24.bmp", "bottom_up.tga", "rle_top_down.tga"}) {
        expectIdentical(readTextureFile(imagePath(fixture)), stbDecodeFile(imagePath(fixture)), fixture);
    }
}

TEST(ImageReadStb, HdrTexelsIdenticalToOpenImageIo) {
    PT_REQUIRE_OIIO();
    for (const std::string& path : {imagePath("rle.hdr"), test::testDataPath("gltf/tiny.hdr"),
                                    test::testDataPath("json/images/sky.hdr")}) {
        expectIdentical(readTextureFile(path), stbDecodeFile(path), path);
    }
}

TEST(ImageReadStb, SharedHdrIdenticalToOpenImageIo) {
    PT_REQUIRE_OIIO();
    PT_REQUIRE_SHARED_ASSET("environments/venice_sunset_1k.hdr");
    const std::string path = test::sharedAsset("environments/venice_sunset_1k.hdr");
    expectIdentical(readTextureFile(path), stbDecodeFile(path), path);
}

// JPEG decoders differ in their inverse DCT and chroma upsampling by a few levels.
TEST(ImageReadStb, JpegWithinAFewLevelsOfOpenImageIo) {
    PT_REQUIRE_OIIO();
    const std::string path = test::testFolder() + "/pattern.jpg";
    writeDisplayImage(path, 96, 64, testPattern(96, 64));  // OIIO: quality 98, 4:2:0 chroma
    const auto [largest, mean] = rgba8Difference(readTextureFile(path), stbDecodeFile(path));
    EXPECT_LE(largest, 4);
    EXPECT_LT(mean, 0.5);
}

TEST(ImageReadStb, SharedJpegWithinAFewLevelsOfOpenImageIo) {
    PT_REQUIRE_OIIO();
    PT_REQUIRE_SHARED_ASSET("AnisotropyBarnLamp/AnisotropyBarnLamp_basecolor.jpeg");
    const std::string path = test::sharedAsset("AnisotropyBarnLamp/AnisotropyBarnLamp_basecolor.jpeg");
    const auto [largest, mean] = rgba8Difference(readTextureFile(path), stbDecodeFile(path));
    EXPECT_LE(largest, 4);
    EXPECT_LT(mean, 0.05);
}

// --- stb on its own (both builds) -----------------------------------------------------------

TEST(ImageReadStb, SixteenBitsRoundToNearestEightBitLevel) {
    const Texture t = stbDecodeFile(imagePath("ramp16.png"));
    ASSERT_EQ(t.format, TexelFormat::RGBA8);
    ASSERT_EQ(t.texels8.size(), size_t(65536) * 4);
    for (uint32_t v = 0; v < 65536; ++v) {
        const int expected = int(std::lround(double(v) * 255.0 / 65535.0));
        ASSERT_EQ(int(t.texels8[v * 4]), expected) << "16-bit value " << v;
        ASSERT_EQ(int(t.texels8[v * 4 + 3]), 255) << "16-bit value " << v;
    }
}

TEST(ImageReadStb, TopRowFirstWhateverTheFileOrder) {
    for (const char* fixture : {"rgb24.bmp", "bottom_up.tga"}) {
        const Texture t = stbDecodeFile(imagePath(fixture));
        ASSERT_EQ(t.width, 3u) << fixture;
        ASSERT_EQ(t.height, 2u) << fixture;
        for (uint32_t y = 0; y < 2; ++y) {
            for (uint32_t x = 0; x < 3; ++x) {
                EXPECT_EQ(texelAt(t, x, y), fixtureTexel(int(x), int(y))) << fixture << " " << x << "," << y;
            }
        }
    }
    const Texture rle = stbDecodeFile(imagePath("rle_top_down.tga"));
    ASSERT_EQ(rle.width, 4u);
    EXPECT_EQ(texelAt(rle, 1, 0), fixtureTexel(0, 0, 255));  // the run repeats texel 0
    EXPECT_EQ(texelAt(rle, 3, 1), fixtureTexel(3, 1, 255 - 60 * 3));
}

TEST(ImageReadStb, PaletteAndTransparencyKeysBecomeStraightAlpha) {
    EXPECT_EQ(stbDecodeFile(imagePath("palette_trns.png")).texels8,
              (std::vector<uint8_t>{255, 0,  0,   0,   0,   255, 0,   255,     // palette 0, 1
                                    0,   0,  255, 128, 255, 255, 255, 255,     // palette 2, 3
                                    10,  20, 30,  255, 255, 255, 255, 255,     // palette 4, 3
                                    0,   0,  255, 128, 0,   255, 0,   255}));  // palette 2, 1
    EXPECT_EQ(stbDecodeFile(imagePath("gray_trns.png")).texels8,
              (std::vector<uint8_t>{0, 0, 0, 255, 100, 100, 100, 0, 200, 200, 200, 255}));
    EXPECT_EQ(stbDecodeFile(imagePath("gray_alpha.png")).texels8,
              (std::vector<uint8_t>{0, 0, 0, 255, 100, 100, 100, 128, 250, 250, 250, 0}));
    EXPECT_EQ(stbDecodeFile(test::testDataPath("gltf/checker.png")).texels8,
              (std::vector<uint8_t>{255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 0, 255, 255, 255, 255}));
}

TEST(ImageReadStb, RadianceHdrAsRgba32F) {
    const Texture t = stbDecodeFile(test::testDataPath("gltf/tiny.hdr"));
    ASSERT_EQ(t.format, TexelFormat::RGBA32F);
    EXPECT_EQ(t.texelsF, (std::vector<float>{1.0f, 0.5f, 0.25f, 1.0f, 2.0f, 4.0f, 8.0f, 1.0f}));
    EXPECT_TRUE(t.texels8.empty());
    const Texture rle = stbDecodeFile(imagePath("rle.hdr"));
    ASSERT_EQ(rle.width, 16u);
    ASSERT_EQ(rle.height, 3u);
    const size_t flat = (1 * 16 + 3) * 4, black = (2 * 16 + 5) * 4;
    EXPECT_EQ(std::vector<float>(rle.texelsF.begin() + flat, rle.texelsF.begin() + flat + 4),
              (std::vector<float>{0.5f, 0.5f, 0.5f, 1.0f}));
    EXPECT_EQ(std::vector<float>(rle.texelsF.begin() + black, rle.texelsF.begin() + black + 4),
              (std::vector<float>{0.0f, 0.0f, 0.0f, 1.0f}));
}

TEST(ImageReadStb, CorruptImagesGiveInputErrorsNamingThem) {
    const std::string broken = test::testDataPath("gltf/broken.png");
    EXPECT_EQ(inputErrorOf([&] { stbDecodeFile(broken); }).rfind(broken + ": cannot decode: ", 0), 0u);
    EXPECT_EQ(inputErrorOf([&] {
                  decodeTextureWithStb({1, 2, 3, 4, 5}, "model.glb: images[3]");
              }).rfind("model.glb: images[3]: cannot decode: ", 0),
              0u);
    EXPECT_EQ(inputErrorOf([&] { decodeTextureWithStb({}, "empty"); }), "empty: image is empty");

    // A JPEG cut off inside its entropy-coded data, through the public reader of this build.
    const std::string folder = test::testFolder();
    const std::vector<uint8_t> jpeg = encodeJpegWithStb("pattern.jpg", 64, 64, testPattern(64, 64));
    const std::string cut = folder + "/cut.jpg";
    writeBytes(cut, std::vector<uint8_t>(jpeg.begin(), jpeg.begin() + 200));
    EXPECT_EQ(inputErrorOf([&] { stbDecodeFile(cut); }).rfind(cut + ": cannot decode: ", 0), 0u);
    EXPECT_EQ(inputErrorOf([&] { readTextureFile(cut); }).rfind(cut + ": ", 0), 0u);
    EXPECT_EQ(inputErrorOf([&] { readTextureFile(broken); }).rfind(broken + ": ", 0), 0u);
}

// Found by fuzzing (tests/fuzz, issue 17): Debian's stb_image 2.27 never returned from a run-length
// encoded Radiance row that the file ends inside of (CVE-2021-42715).
TEST(ImageReadStb, CutOffRunLengthHdrRowIsAnErrorNotAHang) {
    const std::string header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 8\n";
    // An encoded row of width 8: per channel a run of 8 (128 + 8) of one value. R = G = B = 128
    // with exponent 129 is 1.0.
    std::vector<uint8_t> row = {2, 2, 0, 8};
    for (uint8_t value : {128, 128, 128, 129}) row.insert(row.end(), {128 + 8, value});
    std::vector<uint8_t> whole(header.begin(), header.end());
    whole.insert(whole.end(), row.begin(), row.end());
    whole.insert(whole.end(), row.begin(), row.end());
    const Texture t = decodeTextureWithStb(whole, "whole.hdr");
    EXPECT_EQ(t.texelsF, std::vector<float>(8 * 2 * 4, 1.0f));

    // Row 1 cut off after a literal of 3 in its red channel; then a count of 0 inside a row.
    std::vector<uint8_t> cut(whole.begin(), whole.end() - 8);
    cut.insert(cut.end(), {3, 128, 128, 128});
    EXPECT_EQ(inputErrorOf([&] { decodeTextureWithStb(cut, "cut.hdr"); }),
              "cut.hdr: cannot decode: bad run-length data in row 1 (cut off, or a count of 0)");
    std::vector<uint8_t> zero = whole;
    zero[header.size() + 4] = 0;  // row 0's red run
    EXPECT_EQ(inputErrorOf([&] { decodeTextureWithStb(zero, "zero.hdr"); }),
              "zero.hdr: cannot decode: bad run-length data in row 0 (cut off, or a count of 0)");
}

// A few bytes claiming 11111 x 11111 flat pixels (found by fuzz_image: stb reads the missing
// pixels as zeros, allocating 2 GB twice) are refused before stb allocates anything; a flat
// file that holds its pixels decodes.
TEST(ImageReadStb, CutOffFlatHdrIsAnErrorNotAHugeImage) {
    const std::string huge = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 11111 +X 11111\n\xa0";
    EXPECT_EQ(inputErrorOf(
                  [&] { decodeTextureWithStb(std::vector<uint8_t>(huge.begin(), huge.end()), "huge.hdr"); }),
              "huge.hdr: cannot decode: the pixels end before row 11111 (cut off at row 0 or after)");
    const std::string header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 3\n";  // narrow: flat
    std::vector<uint8_t> flat(header.begin(), header.end());
    for (int i = 0; i < 6; ++i) flat.insert(flat.end(), {128, 128, 128, 129});
    EXPECT_EQ(decodeTextureWithStb(flat, "flat.hdr").texelsF, std::vector<float>(3 * 2 * 4, 1.0f));
    flat.resize(flat.size() - 4);
    EXPECT_NE(inputErrorOf([&] {
                  decodeTextureWithStb(flat, "short.hdr");
              }).find("short.hdr: cannot decode: the pixels end"),
              std::string::npos);
}

// Debian's stb_image 2.27 decodes a 16-bit PGM into a buffer of half the size its 16-bit result
// has (CVE-2021-42716); under a name stb is asked for (here .tga, which has no signature) it
// was read past its end. Formats we do not ask stb for never reach it.
TEST(ImageReadStb, FormatsNotAskedForAreRefusedBeforeStb) {
    const std::string pgm16 = "P5\n3 1\n65535\n\x12\x34\x56\x78\x9a\xbc";
    const std::string refused = ": cannot decode: not a PNG, JPEG, BMP, TGA or Radiance HDR image";
    for (const std::string& bytes : {pgm16, std::string("P6\n1 1\n255\nabc"), std::string("8BPS"),
                                     std::string("GIF89a"), std::string("\x53\x80\xf6\x34PICT")}) {
        EXPECT_EQ(inputErrorOf([&] {
                      decodeTextureWithStb({bytes.begin(), bytes.end()}, "image.tga");
                  }),
                  "image.tga" + refused)
            << bytes.substr(0, 2);
    }
    // The same through the reader of a build without OpenImageIO (with it, OpenImageIO reads
    // the PGM, whatever the file is called, and stb is not asked).
    if (!PT_TEST_HAVE_OIIO) {
        const std::string path = test::writeTempFile("pgm16.tga", pgm16);
        EXPECT_EQ(inputErrorOf([&] { readTextureFile(path); }), path + refused);
    }
}

TEST(ImageReadStb, HugeHeaderIsRefusedBeforeDecoding) {
    std::vector<uint8_t> bytes = fileBytes(test::testDataPath("images/rgb24.bmp"));
    const uint8_t size[8] = {0x00, 0x00, 0x01, 0x00, 0x00, 0x10, 0x00, 0x00};  // 65536 x 4096
    std::copy(size, size + 8, bytes.begin() + 18);  // BITMAPINFOHEADER width and height
    EXPECT_EQ(inputErrorOf([&] { decodeTextureWithStb(bytes, "huge.bmp"); }),
              "huge.bmp: unsupported image size 65536x4096x1 with 3 channels");
}

// --- EXR: OpenImageIO's, or a clear error ---------------------------------------------------

TEST(ImageReadStb, ExrReadsWithOpenImageIoAndIsAClearErrorWithout) {
    const std::string exr = test::testDataPath("reference/cornell_128.exr");
    const std::string written = test::testFolder() + "/out.exr";
    const std::vector<float> rgba(4 * 4 * 4, 0.5f);
    if (PT_TEST_HAVE_OIIO) {
        EXPECT_EQ(readTextureFile(exr).format, TexelFormat::RGBA32F);
        writeExr(written, 4, 4, rgba);
        uint32_t w = 0, h = 0;
        EXPECT_EQ(readImageRgba(written, w, h), rgba);
        return;
    }
    const std::string without =
        " images need OpenImageIO, which this build does not have (configured with PT_OIIO=OFF)";
    EXPECT_EQ(inputErrorOf([&] { readTextureFile(exr); }), exr + ": EXR" + without);
    EXPECT_EQ(inputErrorOf([&] { decodeTextureFromMemory(fileBytes(exr), "sky.exr"); }),
              "sky.exr: EXR" + without);
    uint32_t w = 0, h = 0;
    EXPECT_EQ(inputErrorOf([&] { readImageRgba(exr, w, h); }), exr + ": EXR" + without);
    EXPECT_EQ(inputErrorOf([&] { writeExr(written, 4, 4, rgba); }), written + ": EXR" + without);
    EXPECT_FALSE(std::filesystem::exists(written));
    const std::string tiff = test::testFolder() + "/out.tif";
    EXPECT_EQ(inputErrorOf([&] { writeDisplayImage(tiff, 2, 2, std::vector<uint8_t>(12)); }),
              tiff + ": TIFF" + without);
}

// --- stb_image_write (both builds; read back by this build's reader) ------------------------

TEST(ImageWriteStb, PngRoundTripsExactlyAndCarriesSrgbAndMetadata) {
    const std::vector<uint8_t> rgb = testPattern(40, 24);
    const std::vector<uint8_t> png =
        encodePngWithStb("out.png", 40, 24, rgb, {{"pt:spp", "4"}, {"Software", "pt-render 0.1"}});
    const Texture t = decodeTextureFromMemory(png, "out.png", "image/png");
    ASSERT_EQ(t.width, 40u);
    ASSERT_EQ(t.height, 24u);
    for (size_t i = 0; i < size_t(40) * 24; ++i) {
        ASSERT_EQ(texelAt(t, uint32_t(i % 40), uint32_t(i / 40)),
                  (std::vector<uint8_t>{rgb[i * 3], rgb[i * 3 + 1], rgb[i * 3 + 2], 255}))
            << "texel " << i;
    }
    const std::string bytes(png.begin(), png.end());
    EXPECT_NE(bytes.find(std::string("sRGB\x03", 5)), std::string::npos);
    EXPECT_NE(bytes.find(std::string("tEXtpt:spp\0"
                                     "4",
                                     12)),
              std::string::npos);
    EXPECT_NE(bytes.find(std::string("tEXtSoftware\0pt-render 0.1", 26)), std::string::npos);
}

TEST(ImageWriteStb, JpegDecodesWithinAFewLevels) {
    const std::vector<uint8_t> rgb = testPattern(64, 48);
    const Texture t = decodeTextureFromMemory(encodeJpegWithStb("out.jpg", 64, 48, rgb), "out.jpg");
    Texture original;
    original.width = 64;
    original.height = 48;
    for (size_t i = 0; i < rgb.size(); i += 3) {
        original.texels8.insert(original.texels8.end(), {rgb[i], rgb[i + 1], rgb[i + 2], 255});
    }
    const auto [largest, mean] = rgba8Difference(t, original);
    EXPECT_LE(largest, 8);  // measured 3 at quality 98
    EXPECT_LT(mean, 1.0);
}

TEST(ImageWriteStb, WrongPixelCountIsRefused) {
    EXPECT_EQ(inputErrorOf([] { encodePngWithStb("out.png", 4, 4, std::vector<uint8_t>(47), {}); }),
              "out.png: 47 bytes of pixels for a 4x4 RGB image");
}

// writeDisplayImage / readImageRgba of this build (OIIO or stb) agree on 8-bit PNGs.
TEST(ImageWriteStb, DisplayImagePngThroughThisBuild) {
    const std::string path = test::testFolder() + "/render.png";
    const std::vector<uint8_t> rgb = testPattern(16, 8);
    writeDisplayImage(path, 16, 8, rgb, {{"pt:spp", "4"}});
    uint32_t w = 0, h = 0;
    const std::vector<float> rgba = readImageRgba(path, w, h);
    ASSERT_EQ(w, 16u);
    ASSERT_EQ(h, 8u);
    ASSERT_EQ(rgba.size(), size_t(16) * 8 * 4);
    for (size_t i = 0; i < size_t(16) * 8; ++i) {
        for (size_t c = 0; c < 3; ++c) {
            ASSERT_EQ(rgba[i * 4 + c], float(rgb[i * 3 + c]) * (1.0f / 255.0f)) << i << " " << c;
        }
        ASSERT_EQ(rgba[i * 4 + 3], 1.0f);
    }
}

}  // namespace
}  // namespace pt
