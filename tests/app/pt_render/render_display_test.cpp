// pt-render's display flags end to end: the PNG is the EXR beauty through the chosen view,
// its metadata names the view, and bad flags fail with one clear line.
#include <gtest/gtest.h>

#include <algorithm>

#include "app/cli_runner.h"
#include "assets/color/color_processor.h"
#include "assets/image/image_metadata.h"
#include "assets/image/image_read.h"
#include "support/test_paths.h"

namespace pt {
namespace {

using test::runCli;

std::string cornell() { return "'" + test::projectPath("scenes/cornell.json") + "'"; }

std::string metadataValue(const ImageMetadata& metadata, const std::string& key) {
    const auto it =
        std::find_if(metadata.begin(), metadata.end(), [&](const auto& kv) { return kv.first == key; });
    return it == metadata.end() ? std::string() : it->second;
}

// Renders cornell at 24x16 to EXR + PNG with `flags`; returns the beauty, and the PNG as RGB.
void renderBoth(const std::string& flags, std::vector<float>& beauty, std::vector<uint8_t>& png,
                ImageMetadata& metadata) {
    const std::string exr = test::tempDir() + "/display.exr", pngPath = test::tempDir() + "/display.png";
    const auto r = runCli("render " + cornell() + " -o " + exr + " --png " + pngPath +
                          " --spp 2 --size 24x16 --quiet " + flags);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    uint32_t w = 0, h = 0;
    beauty = readImageRgba(exr, w, h);
    const Texture image = readTextureFile(pngPath);
    ASSERT_EQ(image.width, 24u);
    png.clear();
    for (size_t i = 0; i < image.texels8.size(); i += 4) {
        png.insert(png.end(), {image.texels8[i], image.texels8[i + 1], image.texels8[i + 2]});
    }
    metadata = readImageMetadata(pngPath);
}

TEST(RenderDisplay, BuiltinOperatorWithExposureAndDither) {
    PT_REQUIRE_OIIO();  // reads the EXR back
    std::vector<float> beauty;
    std::vector<uint8_t> png;
    ImageMetadata metadata;
    renderBoth("--tonemap agx --exposure 0.5", beauty, png, metadata);
    DisplaySettings settings;
    settings.toneMapper = ToneMapper::AgX;
    settings.exposureStops = 0.5f;
    EXPECT_EQ(png, DisplayProcessor(settings).encode8(beauty, 24, true));
    EXPECT_EQ(metadataValue(metadata, "pt:view"), "built-in: agx, exposure +0.5 stops");
    EXPECT_EQ(metadataValue(metadata, "pt:dither"), "on");
}

#if defined(PT_HAVE_OCIO)
TEST(RenderDisplay, OcioViewOfTheShippedConfig) {
    PT_REQUIRE_OIIO();
    std::vector<float> beauty;
    std::vector<uint8_t> png;
    ImageMetadata metadata;
    renderBoth("--view AgX --display Rec.1886 --no-dither", beauty, png, metadata);
    const auto config = ColorConfig::load(test::projectPath("scenes/ocio/config.ocio"));
    EXPECT_EQ(
        png,
        DisplayProcessor(*config, config->resolve({"Rec.1886", "AgX", ""}), 0.0f).encode8(beauty, 24, false));
    EXPECT_EQ(metadataValue(metadata, "pt:view"), "OCIO config.ocio: Rec.1886 / AgX");
    EXPECT_NE(metadataValue(metadata, "pt:ocio_config").find("config.ocio"), std::string::npos);
    EXPECT_EQ(metadataValue(metadata, "pt:dither"), "off");
}
#endif

TEST(RenderDisplay, BadDisplayFlagsFailWithOneClearLine) {
    const std::string png = " --png " + test::tempDir() + "/bad.png --spp 1 --size 8x8 --quiet";
    struct Case {
        std::string args;
        int code;
        std::string needle;
    };
    std::vector<Case> cases = {
        {"--tonemap agx --view AgX" + png, 2, "exclude"},
        {"--tonemap filmic" + png, 2, "filmic"},
        {"--white-point 3" + png, 2, "--tonemap reinhard"},
        {"--exposure bright" + png, 2, "--exposure"},
    };
#if defined(PT_HAVE_OCIO)
    // A view without a PNG to apply it to (without OpenColorIO, --view itself is refused first).
    cases.push_back({"--view AgX -o " + test::tempDir() + "/only.exr", 2, "--png"});
    cases.push_back({"--view Nope" + png, 1, "\"Nope\""});
    cases.push_back({"--ocio /nonexistent/config.ocio" + png, 1, "/nonexistent/config.ocio"});
#else
    cases.push_back({"--view AgX" + png, 2, "OpenColorIO"});
#endif
    for (const Case& c : cases) {
        const auto r = runCli("render " + cornell() + " " + c.args);
        EXPECT_EQ(r.exitCode, c.code) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.needle), std::string::npos) << c.args << "\n" << r.err;
    }
}

}  // namespace
}  // namespace pt
