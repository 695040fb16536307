#include "assets/color/color_agx_lut.h"

#include <cstdio>

#include "render/display/agx.h"

namespace pt {

std::string agxSigmoidSpi1d(uint32_t entries) {
    std::string text = "Version 1\nFrom 0.0 1.0\nLength " + std::to_string(entries) + "\nComponents 1\n{\n";
    char line[64];
    for (uint32_t i = 0; i < entries; ++i) {
        const float x = float(i) / float(entries - 1);
        std::snprintf(line, sizeof(line), "    %.9g\n", double(agxSigmoid(x)));
        text += line;
    }
    return text + "}\n";
}

}  // namespace pt
