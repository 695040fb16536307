// OpenColorIO's GLSL for the editor: the function it defines and the lookup tables it
// samples, as plain data. (The GLSL-against-CPU image comparison runs with the editor.)
#if defined(PT_HAVE_OCIO)
#include "assets/color/color_gpu_shader.h"

#include <OpenColorIO/OpenColorIO.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <iterator>

#include "assets/color/color_ocio.h"
#include "support/test_paths.h"

namespace pt {
namespace {

std::shared_ptr<const ColorConfig> shipped() {
    static const auto config = ColorConfig::load(test::projectPath("scenes/ocio/config.ocio"));
    return config;
}

// What OpenColorIO itself reports for the view's shader: 1D/2D and 3D texture counts.
std::pair<unsigned, unsigned> ocioTextureCounts(const ViewTransform& view) {
    OCIO::GpuShaderDescRcPtr desc = OCIO::GpuShaderDesc::CreateShaderDesc();
    desc->setLanguage(OCIO::GPU_LANGUAGE_GLSL_4_0);
    ocioDisplayProcessor(*shipped(), view)
        ->getOptimizedGPUProcessor(kOcioOptimization)
        ->extractGpuShaderInfo(desc);
    return {desc->getNumTextures(), desc->getNum3DTextures()};
}

TEST(ColorGpuShader, AgxViewGivesItsFunctionAndTheSigmoidLut) {
    const ViewTransform view = shipped()->resolve({"sRGB", "AgX", ""});
    const GpuColorShader shader = makeGpuColorShader(*shipped(), view);
    EXPECT_EQ(shader.functionName, "ocio_display");
    EXPECT_NE(shader.glsl.find("vec4 ocio_display("), std::string::npos) << shader.glsl;
    const auto [textures, textures3d] = ocioTextureCounts(view);
    ASSERT_EQ(shader.luts.size(), size_t(textures + textures3d));
    ASSERT_GE(shader.luts.size(), 1u) << "the AgX sigmoid is a 1D LUT";
    for (const GpuLut& lut : shader.luts) {
        EXPECT_NE(shader.glsl.find("uniform sampler"), std::string::npos);
        EXPECT_NE(shader.glsl.find(lut.samplerName), std::string::npos) << lut.samplerName;
        EXPECT_EQ(lut.samplerName.rfind("ocio_", 0), 0u) << "prefixed: " << lut.samplerName;
        EXPECT_TRUE(lut.channels == 1 || lut.channels == 3);
        EXPECT_EQ(lut.values.size(), size_t(lut.width) * lut.height * lut.depth * lut.channels);
        EXPECT_TRUE(lut.linearFilter);
    }
    const GpuLut& sigmoid = shader.luts[0];
    EXPECT_EQ(sigmoid.depth, 1u);
    EXPECT_EQ(size_t(sigmoid.width) * sigmoid.height, 1024u) << "the spi1d's 1024 entries, in one texture";
}

TEST(ColorGpuShader, EveryShippedViewBuildsWithoutDynamicUniforms) {
    for (const std::string& display : shipped()->displays()) {
        for (const std::string& name : shipped()->views(display)) {
            const ViewTransform view = shipped()->resolve({display, name, "Exposure +1"});
            GpuColorShader shader;
            ASSERT_NO_THROW(shader = makeGpuColorShader(*shipped(), view)) << display << " / " << name;
            EXPECT_NE(shader.glsl.find("ocio_display"), std::string::npos) << display << " / " << name;
            const auto [textures, textures3d] = ocioTextureCounts(view);
            EXPECT_EQ(shader.luts.size(), size_t(textures + textures3d)) << display << " / " << name;
        }
    }
}

// The editor pastes the text into a "#version 330 core" fragment shader; every shipped view
// must compile there. Needs glslangValidator (Debian's glslang-tools); skips without it.
TEST(ColorGpuShader, ShippedViewsCompileAsGlsl330Core) {
    if (std::system("command -v glslangValidator > /dev/null 2>&1") != 0) {
        GTEST_SKIP() << "glslangValidator is not installed (apt-get install glslang-tools)";
    }
    const std::string folder = test::tempDir();
    for (const std::string& display : shipped()->displays()) {
        for (const std::string& name : shipped()->views(display)) {
            const GpuColorShader shader =
                makeGpuColorShader(*shipped(), shipped()->resolve({display, name, ""}));
            const std::string path = folder + "/ocio_view.frag", log = folder + "/ocio_view.log";
            std::ofstream(path) << "#version 330 core\n"
                                << shader.glsl << "\nuniform sampler2D image;\nin vec2 uv;\nout vec4 color;\n"
                                << "void main() { color = " << shader.functionName
                                << "(texture(image, uv)); }\n";
            const int status = std::system(("glslangValidator '" + path + "' > '" + log + "' 2>&1").c_str());
            std::ifstream in(log);
            const std::string output((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
            EXPECT_EQ(status, 0) << display << " / " << name << ":\n" << output;
        }
    }
}

}  // namespace
}  // namespace pt
#endif  // PT_HAVE_OCIO
