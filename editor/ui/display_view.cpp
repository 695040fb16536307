#include "editor/ui/display_view.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "render/backend/backend.h"

namespace pt::editor {
namespace {

// The formulas of render/display/display_transform.h, in GLSL; keep the two equal.
constexpr const char* kVertexShader = R"(#version 330 core
out vec2 uv;
void main() {
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    uv = vec2(corner.x, 1.0 - corner.y);
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
)";

constexpr const char* kFragmentShader = R"(#version 330 core
in vec2 uv;
out vec4 color;
uniform sampler2D image;
uniform float exposure;      // 2^stops
uniform int toneMapper;      // 0 standard, 1 Reinhard, 2 ACES fitted
uniform float whitePoint;
uniform int mode;            // 0 beauty, 1 linear value, 2 signed vector, 3 id colours, 4 heat map
uniform float scale;         // heat map: 1 / maximum

float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }
vec3 reinhard(vec3 c) {
    float y = luminance(c);
    if (!(y > 0.0)) return vec3(0.0);
    return c * ((1.0 + y / (whitePoint * whitePoint)) / (1.0 + y));
}
vec3 acesFitted(vec3 c) {
    vec3 a = vec3(dot(c, vec3(0.59719, 0.35458, 0.04823)), dot(c, vec3(0.07600, 0.90834, 0.01566)),
                  dot(c, vec3(0.02840, 0.13383, 0.83777)));
    vec3 f = (a * (a + 0.0245786) - 0.000090537) / (a * (0.983729 * a + 0.4329510) + 0.238081);
    return vec3(dot(f, vec3(1.60475, -0.53108, -0.07367)), dot(f, vec3(-0.10208, 1.10813, -0.00605)),
                dot(f, vec3(-0.00327, -0.07276, 1.07602)));
}
vec3 srgb(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
vec3 heat(float t) {  // black -> blue -> green -> yellow -> red
    t = clamp(t, 0.0, 1.0);
    return clamp(vec3(4.0 * t - 2.0, t < 0.5 ? 2.0 * t : 2.0 - 2.0 * t, 1.0 - 2.0 * t) * 1.5, 0.0, 1.0);
}
vec3 idColour(float id) {
    if (id < 0.0) return vec3(0.0);
    uint h = uint(id) * 2654435761u;
    return vec3(float((h >> 8) & 255u), float((h >> 16) & 255u), float((h >> 24) & 255u)) / 255.0 * 0.8 + 0.2;
}
void main() {
    vec4 texel = texture(image, uv);
    vec3 c = texel.rgb;
    if (mode == 0) {
        c *= exposure;
        if (toneMapper == 1) c = reinhard(c);
        else if (toneMapper == 2) c = acesFitted(c);
        c = srgb(c);
    } else if (mode == 1) {
        c = srgb(c * exposure);
    } else if (mode == 2) {
        c = srgb(c * 0.5 + 0.5);
    } else if (mode == 3) {
        c = srgb(idColour(texel.r));
    } else {
        c = srgb(heat(texel.r * scale));
    }
    color = vec4(c, 1.0);
}
)";

GLuint compile(GLenum kind, const char* source) {
    const GLuint shader = glCreateShader(kind);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048] = {};
        glGetShaderInfoLog(shader, sizeof(log), nullptr, log);
        throw std::runtime_error(std::string("display shader: ") + log);
    }
    return shader;
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

DisplayView::DisplayView() {
    const GLuint vs = compile(GL_VERTEX_SHADER, kVertexShader), fs = compile(GL_FRAGMENT_SHADER, kFragmentShader);
    program_ = glCreateProgram();
    glAttachShader(program_, vs);
    glAttachShader(program_, fs);
    glLinkProgram(program_);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(program_, GL_LINK_STATUS, &ok);
    if (!ok) throw std::runtime_error("display shader: link failed");
    glGenVertexArrays(1, &vao_);
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

DisplayView::~DisplayView() {
    glDeleteTextures(1, &texture_);
    glDeleteVertexArrays(1, &vao_);
    glDeleteProgram(program_);
}

void DisplayView::upload(const DisplayFrame& frame) {
    if (frame.rgba.size() != size_t(frame.width) * frame.height * 4 || frame.width == 0) return;
    glBindTexture(GL_TEXTURE_2D, texture_);
    if (frame.width != width_ || frame.height != height_) {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, GLsizei(frame.width), GLsizei(frame.height), 0, GL_RGBA, GL_FLOAT,
                     frame.rgba.data());
        width_ = frame.width;
        height_ = frame.height;
    } else {
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, GLsizei(width_), GLsizei(height_), GL_RGBA, GL_FLOAT, frame.rgba.data());
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

void DisplayView::prepareDeviceFrame(const DisplayFrame& frame) {
    if (frame.width != width_ || frame.height != height_) {
        glBindTexture(GL_TEXTURE_2D, texture_);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, GLsizei(frame.width), GLsizei(frame.height), 0, GL_RGBA, GL_FLOAT,
                     nullptr);
        width_ = frame.width;
        height_ = frame.height;
    }
    aov_ = frame.aov;
    aovMax_ = 1.0f;
}

ImageRect DisplayView::draw(const ViewerSettings& viewer, float x, float y, float w, float h, float framebufferHeight,
                            float pixelScale) {
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
    glUseProgram(program_);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glUniform1i(glGetUniformLocation(program_, "image"), 0);
    glUniform1f(glGetUniformLocation(program_, "exposure"), std::exp2(viewer.display.exposureStops));
    glUniform1i(glGetUniformLocation(program_, "toneMapper"), int(viewer.display.toneMapper));
    glUniform1f(glGetUniformLocation(program_, "whitePoint"), viewer.display.whitePoint);
    glUniform1i(glGetUniformLocation(program_, "mode"), displayMode(aov_));
    glUniform1f(glGetUniformLocation(program_, "scale"), 1.0f / aovMax_);
    glBindVertexArray(vao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glUseProgram(0);
    return rect;
}

}  // namespace pt::editor
