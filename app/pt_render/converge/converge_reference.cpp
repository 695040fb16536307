#include "pt_render/converge/converge_reference.h"

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <utility>

#include "assets/image/reference_image.h"
#include "cli/cli_options.h"

namespace pt::cli {

ConvergeReference readReferenceImage(const std::string& path, uint32_t width, uint32_t height) {
    ReferenceImage image = loadReferenceImage(path);
    if (image.width != width || image.height != height) {
        const std::string size = std::to_string(image.width) + "x" + std::to_string(image.height);
        throw std::runtime_error(path + ": the reference is " + size + " but the render is " +
                                 std::to_string(width) + "x" + std::to_string(height) +
                                 " (render the reference at this size, or pass --size " + size + ")");
    }
    return {std::move(image.rgba), image.noiseRelMse};
}

ConvergeReference constantReference(const std::string& rgb, uint32_t width, uint32_t height) {
    float color[3];
    const char* text = rgb.c_str();
    for (int c = 0; c < 3; ++c) {
        char* end = nullptr;
        const double v = std::strtod(text, &end);
        if (end == text || !std::isfinite(v) || v < 0) {
            throw UsageError("--reference-constant: expected R,G,B (finite, >= 0), got \"" + rgb + "\"");
        }
        color[c] = float(v);
        if (c == 0 && *end == '\0') {  // one number: grey
            color[1] = color[2] = color[0];
            break;
        }
        if (*end != (c < 2 ? ',' : '\0')) {
            throw UsageError("--reference-constant: expected R,G,B (finite, >= 0), got \"" + rgb + "\"");
        }
        text = end + 1;
    }
    ConvergeReference reference;
    reference.rgba.resize(size_t(width) * height * 4);
    for (size_t i = 0; i < reference.rgba.size(); i += 4) {
        reference.rgba[i] = color[0], reference.rgba[i + 1] = color[1], reference.rgba[i + 2] = color[2];
        reference.rgba[i + 3] = 1.0f;
    }
    return reference;
}

}  // namespace pt::cli
