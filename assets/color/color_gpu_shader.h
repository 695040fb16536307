#pragma once
// An OpenColorIO view as plain data for the editor's OpenGL code: GLSL text defining one
// function, and the lookup tables it samples. OpenColorIO types stay out of this header.
//
// Use: paste `glsl` into a "#version 330 core" fragment shader, create one texture per GpuLut
// bound to the uniform sampler named `samplerName`, apply the exposure multiply, then call
// vec4 <functionName>(vec4 inPixel). The text is OpenColorIO's GLSL 4.0 flavour: its 1.30 one
// samples with texture1D/2D/3D, which core-profile 3.30 lacks, and the two differ in nothing
// else; tests/assets/color_gpu_shader_test.cpp compiles the shipped views as 3.30 core with
// glslangValidator where it is installed. Only with PT_HAVE_OCIO.
#include <cstdint>
#include <string>
#include <vector>

#include "assets/color/color_config.h"

namespace pt {

// One texture the shader samples. Texel values are `width * height * depth * channels`
// floats, x fastest, as OpenColorIO lays them out; upload as GL_R32F (channels 1) or
// GL_RGB32F (channels 3) with CLAMP_TO_EDGE wrapping.
//   depth > 1:            a 3D texture (sampler3D), width = height = depth;
//   height > 1:           a 2D texture (sampler2D; OpenColorIO folds a long 1D LUT into rows);
//   height == depth == 1: a 1D texture (sampler1D).
struct GpuLut {
    std::string samplerName;
    uint32_t width = 0, height = 1, depth = 1;
    uint32_t channels = 3;
    bool linearFilter = true;  // GL_LINEAR, else GL_NEAREST
    std::vector<float> values;
};

struct GpuColorShader {
    std::string functionName;  // vec4 functionName(vec4): display-referred RGBA from linear RGBA
    std::string glsl;          // the function, its helpers and its sampler uniforms
    std::vector<GpuLut> luts;
};

// The GPU form of DisplayProcessor(config, view, exposure) without the exposure (applied by
// the caller) and without dithering (the caller mirrors render/display/dither.h). `view` must
// be complete (ColorConfig::resolve). Names are prefixed "ocio_" so they do not collide with
// the caller's. Throws InputError if OpenColorIO cannot build the processor or the shader
// needs dynamic uniforms (which the editor does not feed).
GpuColorShader makeGpuColorShader(const ColorConfig& config, const ViewTransform& view);

}  // namespace pt
