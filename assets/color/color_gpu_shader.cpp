#include "assets/color/color_gpu_shader.h"

#include "assets/color/color_ocio.h"
#include "assets/input_error.h"

namespace pt {

namespace {

constexpr const char* kFunctionName = "ocio_display";

// OpenColorIO's textures as plain data (OCIO 2.1 GpuShaderDesc: 1D/2D through getTexture,
// 3D through get3DTexture).
void copyLuts(const OCIO::GpuShaderDesc& desc, std::vector<GpuLut>& luts) {
    for (unsigned i = 0; i < desc.getNumTextures(); ++i) {
        const char* textureName = nullptr;
        const char* samplerName = nullptr;
        unsigned width = 0, height = 0;
        OCIO::GpuShaderDesc::TextureType channel = OCIO::GpuShaderDesc::TEXTURE_RGB_CHANNEL;
        OCIO::Interpolation interpolation = OCIO::INTERP_LINEAR;
        desc.getTexture(i, textureName, samplerName, width, height, channel, interpolation);
        const float* values = nullptr;
        desc.getTextureValues(i, values);
        GpuLut lut;
        lut.samplerName = samplerName;
        lut.width = width;
        lut.height = height;
        lut.channels = channel == OCIO::GpuShaderDesc::TEXTURE_RED_CHANNEL ? 1 : 3;
        lut.linearFilter = interpolation != OCIO::INTERP_NEAREST;
        lut.values.assign(values, values + size_t(width) * height * lut.channels);
        luts.push_back(std::move(lut));
    }
    for (unsigned i = 0; i < desc.getNum3DTextures(); ++i) {
        const char* textureName = nullptr;
        const char* samplerName = nullptr;
        unsigned edge = 0;
        OCIO::Interpolation interpolation = OCIO::INTERP_LINEAR;
        desc.get3DTexture(i, textureName, samplerName, edge, interpolation);
        const float* values = nullptr;
        desc.get3DTextureValues(i, values);
        GpuLut lut;
        lut.samplerName = samplerName;
        lut.width = lut.height = lut.depth = edge;
        lut.channels = 3;
        lut.linearFilter = interpolation != OCIO::INTERP_NEAREST;
        lut.values.assign(values, values + size_t(edge) * edge * edge * 3);
        luts.push_back(std::move(lut));
    }
}

}  // namespace

GpuColorShader makeGpuColorShader(const ColorConfig& config, const ViewTransform& view) {
    const OCIO::ConstProcessorRcPtr processor = ocioDisplayProcessor(config, view);
    const std::string where = config.path() + ": " + view.display + " / " + view.view;
    GpuColorShader out;
    out.functionName = kFunctionName;
    try {
        const OCIO::ConstGPUProcessorRcPtr gpu = processor->getOptimizedGPUProcessor(kOcioOptimization);
        OCIO::GpuShaderDescRcPtr desc = OCIO::GpuShaderDesc::CreateShaderDesc();
        desc->setLanguage(OCIO::GPU_LANGUAGE_GLSL_4_0);  // texture(), as core-profile 3.30 wants
        desc->setFunctionName(kFunctionName);
        desc->setResourcePrefix("ocio_");
        gpu->extractGpuShaderInfo(desc);
        if (desc->getNumUniforms() > 0) {
            throw InputError(where + ": the view needs " + std::to_string(desc->getNumUniforms()) +
                             " dynamic uniforms, which the display shader does not feed");
        }
        out.glsl = desc->getShaderText();
        copyLuts(*desc, out.luts);
    } catch (const OCIO::Exception& e) {
        throw InputError(where + ": " + e.what());
    }
    return out;
}

}  // namespace pt
