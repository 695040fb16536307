// Radiance .hdr environment maps whose header carries the degenerate chromaticity line
// "PRIMARIES=0 0 0 0 0 0 0 0" (Photoshop writes it; the Poly Haven 1k maps in the shared assets
// have it), built here byte by byte: through readTextureFile (OpenImageIO, or stb with
// PT_OIIO=OFF), the stb decoder, decoding from memory and a scene's environment.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "assets/image/image_read.h"
#include "assets/image/image_read_stb.h"
#include "assets/scene_loader.h"
#include "support/test_paths.h"

namespace pt {
namespace {

constexpr const char* kPhotoshopHeader =
    "#?RADIANCE\n# Made with Adobe Photoshop\nGAMMA=1\nPRIMARIES=0 0 0 0 0 0 0 0\nFORMAT=32-bit_rle_rgbe\n\n";

struct HdrFile {
    std::vector<uint8_t> bytes;
    std::vector<float> rgba;  // what it decodes to, RGBA32F
};

using Rgbe = std::array<uint8_t, 4>;

// Pixel x of row y: the left half one constant colour (a run when RLE encoded), the right half
// varying. All values are exact in float (mantissa x 2^(exponent - 136)).
Rgbe pixelAt(uint32_t x, uint32_t y, uint32_t width) {
    if (x < width / 2) return {128, 64, 32, 129};  // (1, 0.5, 0.25)
    return {uint8_t(100 + x), uint8_t(50 + 3 * x), uint8_t(200 - x), uint8_t(130 + y)};
}

// Radiance's "new" run-length encoding of one scanline: each component separately, as a run
// chunk (128 + n, value) for the constant left half and a literal chunk (n, values...) for the
// right half.
void appendRleScanline(std::vector<uint8_t>& out, uint32_t y, uint32_t width) {
    out.insert(out.end(), {2, 2, uint8_t(width >> 8), uint8_t(width & 0xff)});
    const uint32_t half = width / 2;
    for (int c = 0; c < 4; ++c) {
        out.push_back(uint8_t(128 + half));
        out.push_back(pixelAt(0, y, width)[size_t(c)]);
        out.push_back(uint8_t(width - half));
        for (uint32_t x = half; x < width; ++x) out.push_back(pixelAt(x, y, width)[size_t(c)]);
    }
}

// `rle`: widths from 8 up are run-length encoded, as real files are; else flat RGBE.
HdrFile makeHdr(uint32_t width, uint32_t height, bool rle) {
    HdrFile file;
    const std::string header = std::string(kPhotoshopHeader) + "-Y " + std::to_string(height) + " +X " +
                               std::to_string(width) + "\n";
    file.bytes.assign(header.begin(), header.end());
    for (uint32_t y = 0; y < height; ++y) {
        if (rle) appendRleScanline(file.bytes, y, width);
        for (uint32_t x = 0; x < width; ++x) {
            const Rgbe p = pixelAt(x, y, width);
            if (!rle) file.bytes.insert(file.bytes.end(), p.begin(), p.end());
            for (int c = 0; c < 3; ++c) file.rgba.push_back(std::ldexp(float(p[size_t(c)]), int(p[3]) - 136));
            file.rgba.push_back(1.0f);
        }
    }
    return file;
}

std::string writeFile(const std::string& path, const std::vector<uint8_t>& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    return path;
}

void expectDecoded(const Texture& t, const HdrFile& file, uint32_t width, uint32_t height,
                   const std::string& via) {
    ASSERT_EQ(t.format, TexelFormat::RGBA32F) << via;
    ASSERT_EQ(t.width, width) << via;
    ASSERT_EQ(t.height, height) << via;
    ASSERT_EQ(t.texelsF.size(), file.rgba.size()) << via;
    for (size_t i = 0; i < file.rgba.size(); ++i)
        ASSERT_EQ(t.texelsF[i], file.rgba[i]) << via << ", value " << i;
}

struct Case {
    uint32_t width, height;
    bool rle;
};

TEST(ImageReadHdr, PhotoshopPrimariesLineLoadsThroughEveryReader) {
    for (const Case c : {Case{16, 3, true}, Case{3, 2, false}}) {
        SCOPED_TRACE(std::to_string(c.width) + "x" + std::to_string(c.height) + (c.rle ? " RLE" : " flat"));
        const HdrFile file = makeHdr(c.width, c.height, c.rle);
        const std::string path = writeFile(test::tempDir() + "/primaries.hdr", file.bytes);
        expectDecoded(readTextureFile(path), file, c.width, c.height, "readTextureFile");
        expectDecoded(decodeTextureFromMemory(file.bytes, "primaries.hdr"), file, c.width, c.height,
                      "memory");
        expectDecoded(decodeTextureWithStb(file.bytes, "primaries.hdr"), file, c.width, c.height, "stb");
    }
}

TEST(ImageReadHdr, SceneEnvironmentWithPrimariesLineLoads) {
    const std::string dir = test::tempDir();
    const HdrFile file = makeHdr(16, 8, true);
    writeFile(dir + "/sky.hdr", file.bytes);
    const std::string json = R"({"version": 1, "environment": {"image": "sky.hdr", "intensity": 2}})";
    writeFile(dir + "/sky.json", std::vector<uint8_t>(json.begin(), json.end()));
    const LoadResult loaded = loadScene(dir + "/sky.json");
    ASSERT_TRUE(loaded.ok()) << loaded.error;
    const Scene& scene = *loaded.scene;
    ASSERT_GE(scene.environment.texture, 0);
    expectDecoded(scene.textures.at(size_t(scene.environment.texture)), file, 16, 8, "scene environment");
}

}  // namespace
}  // namespace pt
