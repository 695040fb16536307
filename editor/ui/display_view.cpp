#include "editor/ui/display_view.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "render/backend/backend.h"

#ifdef PT_HAVE_OCIO
#include "assets/color/color_gpu_shader.h"
#endif

namespace pt::editor {
namespace {

GLuint createImageTexture() {
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return texture;
}

// How each AOV is made visible.
int displayMode(int32_t aov) {
    if (aov < 0) return 0;
    switch (Aov(aov)) {
        case Aov::ShadingNormal:
        case Aov::GeometricNormal: return 2;
        case Aov::InstanceId:
        case Aov::MaterialId: return 3;
        case Aov::Depth:
        case Aov::BvhCost:
        case Aov::SampleCount:
        case Aov::Variance: return 4;
        default: return 1;
    }
}

}  // namespace

DisplayView::DisplayView() : shader_(std::make_unique<DisplayShader>(nullptr)) {
    glGenVertexArrays(1, &vao_);
    texture_ = createImageTexture();
    referenceTexture_ = createImageTexture();
}

DisplayView::~DisplayView() {
    glDeleteTextures(1, &texture_);
    glDeleteTextures(1, &referenceTexture_);
    glDeleteVertexArrays(1, &vao_);
}

void DisplayView::setColorView(const ColorView& color) {
    const std::string key = color.key();
    if (key == colorKey_) return;
    colorKey_ = key;
    shaderError_.clear();
    try {
#ifdef PT_HAVE_OCIO
        if (color.config) {
            const GpuColorShader ocio = makeGpuColorShader(*color.config, color.view);
            shader_ = std::make_unique<DisplayShader>(&ocio);
            return;
        }
#endif
        shader_ = std::make_unique<DisplayShader>(nullptr);
    } catch (const std::exception& e) {
        // The view's shader does not build here: keep drawing with the built-in operators.
        shaderError_ = e.what();
        shader_ = std::make_unique<DisplayShader>(nullptr);
    }
}

void DisplayView::upload(const DisplayFrame& frame) {
    if (frame.rgba.size() != size_t(frame.width) * frame.height * 4 || frame.width == 0) return;
    glBindTexture(GL_TEXTURE_2D, texture_);
    if (frame.width != width_ || frame.height != height_) {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, GLsizei(frame.width), GLsizei(frame.height), 0, GL_RGBA,
                     GL_FLOAT, frame.rgba.data());
        width_ = frame.width;
        height_ = frame.height;
    } else {
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, GLsizei(width_), GLsizei(height_), GL_RGBA, GL_FLOAT,
                        frame.rgba.data());
    }
    aov_ = frame.aov;
    aovMax_ = 0.0f;
    if (displayMode(aov_) == 4) {
        for (size_t i = 0; i < frame.rgba.size(); i += 4) {
            if (std::isfinite(frame.rgba[i])) aovMax_ = std::max(aovMax_, frame.rgba[i]);
        }
    }
    if (!(aovMax_ > 0.0f)) aovMax_ = 1.0f;
}

void DisplayView::setReference(const std::shared_ptr<const ReferenceImage>& reference) {
    if (reference == reference_) return;
    reference_ = reference;
    if (!reference_) return;
    glBindTexture(GL_TEXTURE_2D, referenceTexture_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, GLsizei(reference_->width), GLsizei(reference_->height), 0,
                 GL_RGBA, GL_FLOAT, reference_->rgba.data());
}

void DisplayView::prepareDeviceFrame(const DisplayFrame& frame) {
    if (frame.width != width_ || frame.height != height_) {
        glBindTexture(GL_TEXTURE_2D, texture_);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, GLsizei(frame.width), GLsizei(frame.height), 0, GL_RGBA,
                     GL_FLOAT, nullptr);
        width_ = frame.width;
        height_ = frame.height;
    }
    aov_ = frame.aov;
    aovMax_ = 1.0f;
}

ImageRect DisplayView::draw(const ViewerSettings& viewer, CompareView compare, float x, float y, float w,
                            float h, float framebufferHeight, float pixelScale) {
    ImageRect rect;
    if (width_ == 0 || w <= 0 || h <= 0) return rect;
    const float aspect = float(width_) / float(height_);
    rect.width = std::min(w, h * aspect);
    rect.height = rect.width / aspect;
    rect.x = x + 0.5f * (w - rect.width);
    rect.y = y + 0.5f * (h - rect.height);
    rect.imageWidth = width_;
    rect.imageHeight = height_;
    glViewport(GLint(rect.x * pixelScale), GLint(framebufferHeight - (rect.y + rect.height) * pixelScale),
               GLsizei(rect.width * pixelScale), GLsizei(rect.height * pixelScale));
    const GLuint program = shader_->program();
    glUseProgram(program);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture_);
    // A render smaller than its place on screen (a resolution scale, the coarse frames while
    // navigating) is filtered, not shown as blocks; ids stay unblended, and 1:1 stays exact.
    const bool upscaled = rect.width * pixelScale > float(width_) + 0.5f;
    const GLint filter = upscaled && displayMode(aov_) != 3 ? GL_LINEAR : GL_NEAREST;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glUniform1i(glGetUniformLocation(program, "image"), 0);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, referenceTexture_);
    glUniform1i(glGetUniformLocation(program, "reference"), 1);
    glActiveTexture(GL_TEXTURE0);
    shader_->bindLuts(2);
    glUniform1i(glGetUniformLocation(program, "compare"), reference_ ? int(compare) : 0);
    glUniform1f(glGetUniformLocation(program, "exposure"), std::exp2(viewer.display.exposureStops));
    glUniform1i(glGetUniformLocation(program, "useOcio"),
                shader_->hasOcioView() && !viewer.builtinDisplay ? 1 : 0);
    glUniform1i(glGetUniformLocation(program, "toneMapper"), int(viewer.display.toneMapper));
    glUniform1f(glGetUniformLocation(program, "whitePoint"), viewer.display.whitePoint);
    glUniform1i(glGetUniformLocation(program, "dither"), viewer.display.dither ? 1 : 0);
    glUniform1i(glGetUniformLocation(program, "mode"), displayMode(aov_));
    glUniform1f(glGetUniformLocation(program, "scale"), 1.0f / aovMax_);
    glBindVertexArray(vao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glUseProgram(0);
    return rect;
}

}  // namespace pt::editor
