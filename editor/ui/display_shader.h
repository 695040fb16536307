#pragma once
// The viewport's fragment program: the display transform applied on the GPU to the linear
// frame. For the beauty: exposure, then either the OpenColorIO view's generated GLSL (with its
// lookup tables as textures) or the built-in operators, then the same dither and 8-bit rounding
// as file export, so the window shows the bytes an exported PNG holds (the CPU side:
// assets/color_processor.h; render/display/ holds the formulas this mirrors). AOVs get false
// colours; a reference image can replace the beauty or be subtracted from it.
#include <string>
#include <vector>

#include "editor/ui/gl.h"

namespace pt {
struct GpuColorShader;
}

namespace pt::editor {

class DisplayShader {
public:
    // `color`: the OpenColorIO view's shader (assets/color_gpu_shader.h), or nullptr for the
    // built-in operators only. Throws std::runtime_error with the GL compiler's log.
    explicit DisplayShader(const GpuColorShader* color);
    ~DisplayShader();
    DisplayShader(const DisplayShader&) = delete;
    DisplayShader& operator=(const DisplayShader&) = delete;

    GLuint program() const { return program_; }
    bool hasOcioView() const { return hasOcio_; }
    // Binds the view's lookup tables to texture units `firstUnit`, `firstUnit` + 1, ...
    void bindLuts(GLint firstUnit) const;

private:
    struct Lut {
        GLenum target;
        GLuint texture;
        std::string sampler;
    };
    GLuint program_ = 0;
    bool hasOcio_ = false;
    std::vector<Lut> luts_;
};

}  // namespace pt::editor
