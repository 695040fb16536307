#pragma once
// Internal to pt_assets (OpenColorIO builds only): the OpenColorIO objects behind
// ColorConfig, and the one processor both the CPU path (color_processor_ocio.cpp) and the
// GLSL path (color_gpu_shader.cpp) are made from, so that the editor's view and an exported
// file agree.
#include <OpenColorIO/OpenColorIO.h>

#include "assets/color/color_config.h"

namespace pt {

namespace OCIO = OCIO_NAMESPACE;

struct ColorConfig::Impl {
    OCIO::ConstConfigRcPtr config;
};

// scene_linear -> [look, in scene_linear] -> display / view. `view` must be complete
// (ColorConfig::resolve). Throws InputError "<config>: <display> / <view>: <OCIO's message>".
OCIO::ConstProcessorRcPtr ocioDisplayProcessor(const ColorConfig& config, const ViewTransform& view);

// The optimisation both the CPU and the GPU processor are built with.
constexpr OCIO::OptimizationFlags kOcioOptimization = OCIO::OPTIMIZATION_DEFAULT;

}  // namespace pt
