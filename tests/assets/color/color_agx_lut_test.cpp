// The committed AgX sigmoid LUT is exactly what the project's generator writes from the one
// curve function (render/display/agx.h), so the config's "AgX" view and the built-in "agx"
// operator cannot drift apart.
#include "assets/color/color_agx_lut.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "render/display/agx.h"
#include "support/test_paths.h"

namespace pt {
namespace {

const char* kLutPath = "scenes/ocio/luts/agx_sigmoid.spi1d";

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(ColorAgxLut, CommittedFileIsTheGeneratorsOutput) {
    const std::string path = test::projectPath(kLutPath);
    const std::string generated = agxSigmoidSpi1d();
    if (const char* regenerate = std::getenv("PT_REGENERATE_AGX_LUT"); regenerate && *regenerate == '1') {
        std::ofstream(path, std::ios::binary) << generated;
    }
    EXPECT_TRUE(readText(path) == generated)
        << path << " differs from agxSigmoidSpi1d() (assets/color_agx_lut.cpp). If the curve in "
        << "render/display/agx.h changed on purpose, regenerate the file with\n"
        << "  PT_REGENERATE_AGX_LUT=1 <build>/tests/pt_assets_tests --gtest_filter=ColorAgxLut.*\n"
        << "and commit it.";
}

TEST(ColorAgxLut, SamplesTheCurveOverTheUnitDomain) {
    const std::string text = agxSigmoidSpi1d(5);
    EXPECT_EQ(text.rfind("Version 1\nFrom 0.0 1.0\nLength 5\nComponents 1\n{\n", 0), 0u) << text;
    std::istringstream lines(text.substr(text.find('{') + 1));
    for (int i = 0; i < 5; ++i) {
        float value = 0.0f;
        ASSERT_TRUE(lines >> value);
        EXPECT_EQ(value, agxSigmoid(float(i) / 4.0f))
            << "sample " << i << " (9 digits restore a float exactly)";
    }
    std::string close;
    lines >> close;
    EXPECT_EQ(close, "}");
}

}  // namespace
}  // namespace pt
