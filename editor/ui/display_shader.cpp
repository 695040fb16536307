#include "editor/ui/display_shader.h"

#include <stdexcept>

#ifdef PT_HAVE_OCIO
#include "assets/color/color_gpu_shader.h"
#endif

namespace pt::editor {
namespace {

constexpr const char* kVertexShader = R"(#version 330 core
out vec2 uv;
void main() {
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    uv = vec2(corner.x, 1.0 - corner.y);  // v = 0 at the image's top row, as it is stored
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
)";

constexpr const char* kUniforms = R"(#version 330 core
in vec2 uv;
out vec4 color;
uniform sampler2D image;
uniform sampler2D reference;
uniform int compare;         // 0 the render, 1 the reference, 2 |render - reference| (beauty only)
uniform float exposure;      // 2^stops
uniform int useOcio;         // 1: the OpenColorIO view below, 0: the built-in tone mapper
uniform int toneMapper;      // 0 standard, 1 Reinhard, 2 ACES fitted, 3 AgX
uniform float whitePoint;
uniform int dither;          // 1: triangular dither before 8-bit rounding
uniform int mode;            // 0 beauty, 1 linear value, 2 signed vector, 3 id colours, 4 heat map
uniform float scale;         // heat map: 1 / maximum
)";

// What stands in for the OpenColorIO view where there is none.
constexpr const char* kNoOcioView = "vec4 ptOcioView(vec4 c) { return c; }\n";

// The formulas of render/display/display_transform.h, agx.h and dither.h, in GLSL; keep them
// equal (the display GL test compares the two paths).
constexpr const char* kBody = R"(
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
vec3 rows(vec3 r0, vec3 r1, vec3 r2, vec3 v) { return vec3(dot(r0, v), dot(r1, v), dot(r2, v)); }
float agxSigmoid(float x) {
    float x2 = x * x;
    float x4 = x2 * x2;
    return 15.5 * x4 * x2 - 40.14 * x4 * x + 31.96 * x4 - 6.868 * x2 * x + 0.4298 * x2 + 0.1191 * x - 0.00232;
}
vec3 agx(vec3 c) {
    c = rows(vec3(0.627403896, 0.329283038, 0.043313066), vec3(0.069097289, 0.919540395, 0.011362316),
             vec3(0.016391439, 0.088013308, 0.895595253), c);
    c = rows(vec3(0.856627153, 0.095121241, 0.048251606), vec3(0.137318973, 0.761241991, 0.101439036),
             vec3(0.111898213, 0.076799419, 0.811302368), c);
    for (int i = 0; i < 3; ++i) {
        float ev = log2(max(c[i], 1e-10));
        c[i] = agxSigmoid(clamp((ev + 12.47393) / (4.026069 + 12.47393), 0.0, 1.0));
    }
    c = rows(vec3(1.127100582, -0.110606643, -0.016493939), vec3(-0.141329763, 1.157823702, -0.016493939),
             vec3(-0.141329763, -0.110606643, 1.251936407), c);
    c = pow(max(c, 0.0), vec3(2.2));
    c = rows(vec3(1.660491002, -0.587641139, -0.072849863), vec3(-0.124550475, 1.132899897, -0.008349423),
             vec3(-0.018150763, -0.100578898, 1.118729661), c);
    return clamp(c, 0.0, 1.0);
}
vec3 srgb(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
uint hashU32(uint v) {
    v ^= v >> 16u; v *= 0x7feb352du; v ^= v >> 15u; v *= 0x846ca68bu; v ^= v >> 16u;
    return v;
}
float ditherOffset(uvec2 p) {
    uint h = hashU32(p.x ^ hashU32(p.y + 0x68bc21ebu));
    float a = (float(h & 0xffffu) + 0.5) / 65536.0;
    float b = (float(h >> 16u) + 0.5) / 65536.0;
    return a + b - 1.0;
}
vec3 quantize8(vec3 v, float offset) { return clamp(floor(v * 255.0 + 0.5 + offset), 0.0, 255.0) / 255.0; }
vec3 heat(float t) {  // black -> blue -> green -> yellow -> red
    t = clamp(t, 0.0, 1.0);
    return clamp(vec3(4.0 * t - 2.0, t < 0.5 ? 2.0 * t : 2.0 - 2.0 * t, 1.0 - 2.0 * t) * 1.5, 0.0, 1.0);
}
vec3 idColour(float id) {
    if (id < 0.0) return vec3(0.0);
    uint h = uint(id) * 2654435761u;
    return vec3(float((h >> 8) & 255u), float((h >> 16) & 255u), float((h >> 24) & 255u)) / 255.0 * 0.8 + 0.2;
}
vec3 displayBeauty(vec3 c, uvec2 pixel) {
    c *= exposure;
    for (int i = 0; i < 3; ++i) {
        if (isnan(c[i]) || isinf(c[i])) c[i] = 0.0;  // channel by channel, as the CPU path
    }
    if (useOcio == 1) {
        c = ptOcioView(vec4(c, 1.0)).rgb;
    } else {
        if (toneMapper == 1) c = reinhard(c);
        else if (toneMapper == 2) c = acesFitted(c);
        else if (toneMapper == 3) c = agx(c);
        c = srgb(c);
    }
    return quantize8(c, dither == 1 ? ditherOffset(pixel) : 0.0);
}
void main() {
    ivec2 size = textureSize(image, 0);
    uvec2 pixel = uvec2(clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1));  // the image pixel, row 0 on top
    vec4 texel = texture(image, uv);
    vec3 c = texel.rgb;
    if (mode == 0 && compare == 1) c = texture(reference, uv).rgb;
    if (mode == 0 && compare == 2) {
        c = srgb(abs(c - texture(reference, uv).rgb) * exposure);  // no tone mapping: differences stay linear
    } else if (mode == 0) {
        c = displayBeauty(c, pixel);
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

GLuint compile(GLenum kind, const std::string& source) {
    const GLuint shader = glCreateShader(kind);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[4096] = {};
        glGetShaderInfoLog(shader, sizeof(log), nullptr, log);
        glDeleteShader(shader);
        throw std::runtime_error(std::string("display shader: ") + log);
    }
    return shader;
}

GLuint link(const std::string& fragmentSource) {
    const GLuint vs = compile(GL_VERTEX_SHADER, kVertexShader);
    GLuint fs = 0;
    try {
        fs = compile(GL_FRAGMENT_SHADER, fragmentSource);
    } catch (...) {
        glDeleteShader(vs);
        throw;
    }
    const GLuint program = glCreateProgram();
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    glLinkProgram(program);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[4096] = {};
        glGetProgramInfoLog(program, sizeof(log), nullptr, log);
        glDeleteProgram(program);
        throw std::runtime_error(std::string("display shader: link failed: ") + log);
    }
    return program;
}

}  // namespace

DisplayShader::DisplayShader(const GpuColorShader* color) {
    std::string source = kUniforms;
#ifdef PT_HAVE_OCIO
    if (color) {
        source += color->glsl;
        source += "\nvec4 ptOcioView(vec4 c) { return " + color->functionName + "(c); }\n";
        hasOcio_ = true;
    } else {
        source += kNoOcioView;
    }
#else
    (void)color;
    source += kNoOcioView;
#endif
    source += kBody;
    program_ = link(source);
#ifdef PT_HAVE_OCIO
    if (!color) return;
    for (const GpuLut& lut : color->luts) {
        Lut made{lut.depth > 1    ? GLenum(GL_TEXTURE_3D)
                 : lut.height > 1 ? GLenum(GL_TEXTURE_2D)
                                  : GLenum(GL_TEXTURE_1D),
                 0, lut.samplerName};
        const GLenum internal = lut.channels == 1 ? GL_R32F : GL_RGB32F,
                     format = lut.channels == 1 ? GL_RED : GL_RGB;
        const GLint filter = lut.linearFilter ? GL_LINEAR : GL_NEAREST;
        glGenTextures(1, &made.texture);
        glBindTexture(made.target, made.texture);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        if (made.target == GL_TEXTURE_3D) {
            glTexImage3D(made.target, 0, internal, GLsizei(lut.width), GLsizei(lut.height),
                         GLsizei(lut.depth), 0, format, GL_FLOAT, lut.values.data());
            glTexParameteri(made.target, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
        } else if (made.target == GL_TEXTURE_2D) {
            glTexImage2D(made.target, 0, internal, GLsizei(lut.width), GLsizei(lut.height), 0, format,
                         GL_FLOAT, lut.values.data());
        } else {
            glTexImage1D(made.target, 0, internal, GLsizei(lut.width), 0, format, GL_FLOAT,
                         lut.values.data());
        }
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTexParameteri(made.target, GL_TEXTURE_MIN_FILTER, filter);
        glTexParameteri(made.target, GL_TEXTURE_MAG_FILTER, filter);
        glTexParameteri(made.target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(made.target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        luts_.push_back(made);
    }
#endif
}

DisplayShader::~DisplayShader() {
    for (const Lut& lut : luts_) glDeleteTextures(1, &lut.texture);
    glDeleteProgram(program_);
}

void DisplayShader::bindLuts(GLint firstUnit) const {
    for (size_t i = 0; i < luts_.size(); ++i) {
        const GLint unit = firstUnit + GLint(i);
        glActiveTexture(GLenum(GL_TEXTURE0 + unit));
        glBindTexture(luts_[i].target, luts_[i].texture);
        glUniform1i(glGetUniformLocation(program_, luts_[i].sampler.c_str()), unit);
    }
    glActiveTexture(GL_TEXTURE0);
}

}  // namespace pt::editor
