// The viewport's display transform on the GPU (editor/ui/display_shader.h: OpenColorIO's
// generated GLSL and LUT textures, or the built-in operators, then the dither) against the CPU
// path that exported images take (assets/color_processor.h), in a real OpenGL 3.3 context under
// a private Xvfb (Mesa). Every view of every display of the shipped config, and every built-in
// operator, dithered and not, must give the same 8-bit values within 1 (1/255) per channel on
// an image of grey ramps over 20 stops, saturated colours and non-finite pixels.
//
// Skips where Xvfb is absent, and where this build has no OpenColorIO for the config's part.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "assets/color/color_processor.h"
#include "editor/color_view.h"
#include "editor/ui/display_view.h"
#include "editor/x11_session.h"

namespace pt::editor {
namespace {

constexpr uint32_t kWidth = 64, kHeight = 12;

// Rows: greys from 2^-12 to 2^8, then colours at those levels, then odd values.
std::vector<float> testImage() {
    const Vec3 hues[] = {{1, 1, 1},          {1, 0, 0},           {0, 1, 0},       {0, 0, 1},
                         {0, 1, 1},          {1, 0.2f, 0.05f},    {0.3f, 0.5f, 1}, {1, 1, 0},
                         {0.9f, 0.6f, 0.4f}, {0.05f, 0.8f, 0.3f}, {1, 0, 1}};
    std::vector<float> rgba(size_t(kWidth) * kHeight * 4, 1.0f);
    for (uint32_t y = 0; y < kHeight; ++y) {
        for (uint32_t x = 0; x < kWidth; ++x) {
            float* p = &rgba[(size_t(y) * kWidth + x) * 4];
            const float level = std::exp2(-12.0f + 20.0f * float(x) / float(kWidth - 1));
            const Vec3 c = y < 11 ? hues[y] * level : Vec3(float(x) / kWidth - 0.25f, 0.5f, 2.0f);
            p[0] = c.x, p[1] = c.y, p[2] = c.z;
        }
    }
    float* last = &rgba[(size_t(kHeight - 1) * kWidth) * 4];
    last[0] = std::numeric_limits<float>::quiet_NaN();
    last[5] = std::numeric_limits<float>::infinity();
    last[8] = -1.0f;
    return rgba;
}

// A hidden GLFW window with an OpenGL 3.3 core context on a private X server.
class GlContext {
public:
    bool start(std::string& why) {
        const std::filesystem::path dir = std::filesystem::temp_directory_path() / "pt_display_gl_test";
        std::filesystem::create_directories(dir);
        if (test::findOnPath("Xvfb").empty()) return why = "Xvfb is not on PATH", false;
        x_ = test::X11Session::start((dir / "xvfb.log").string(), 20.0, why);
        if (!x_) return false;
        setenv("DISPLAY", x_->display().c_str(), 1);
        if (!glfwInit()) return why = "glfwInit failed on " + x_->display(), false;
        glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        window_ = glfwCreateWindow(int(kWidth), int(kHeight), "display test", nullptr, nullptr);
        if (!window_) return why = "no OpenGL 3.3 core context on " + x_->display(), false;
        glfwMakeContextCurrent(window_);
        return true;
    }
    ~GlContext() {
        if (window_) glfwDestroyWindow(window_);
        glfwTerminate();
    }

private:
    std::unique_ptr<test::X11Session> x_;
    GLFWwindow* window_ = nullptr;
};

// Draws `image` through `view` into an 8-bit framebuffer of its size and reads it back as RGB,
// rows from the top (the CPU's order).
std::vector<uint8_t> drawOnGpu(DisplayView& view, const ViewerSettings& viewer,
                               const std::vector<float>& image) {
    DisplayFrame frame;
    frame.width = kWidth, frame.height = kHeight, frame.rgba = image, frame.serial = 1;
    view.upload(frame);
    GLuint fbo = 0, colour = 0;
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glGenRenderbuffers(1, &colour);
    glBindRenderbuffer(GL_RENDERBUFFER, colour);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, GLsizei(kWidth), GLsizei(kHeight));
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
    EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
    view.draw(viewer, CompareView::Render, 0.0f, 0.0f, float(kWidth), float(kHeight), float(kHeight), 1.0f);
    std::vector<uint8_t> rgba(size_t(kWidth) * kHeight * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, GLsizei(kWidth), GLsizei(kHeight), GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteRenderbuffers(1, &colour);
    glDeleteFramebuffers(1, &fbo);
    std::vector<uint8_t> rgb(size_t(kWidth) * kHeight * 3);
    for (uint32_t y = 0; y < kHeight; ++y) {
        for (uint32_t x = 0; x < kWidth; ++x) {
            const uint8_t* from =
                &rgba[(size_t(kHeight - 1 - y) * kWidth + x) * 4];  // GL rows start at the bottom
            std::copy(from, from + 3, &rgb[(size_t(y) * kWidth + x) * 3]);
        }
    }
    return rgb;
}

struct Agreement {
    int maxDifference = 0;
    size_t differing = 0, channels = 0;
};

Agreement compare(const std::vector<uint8_t>& gpu, const std::vector<uint8_t>& cpu) {
    Agreement a;
    a.channels = cpu.size();
    for (size_t i = 0; i < cpu.size() && i < gpu.size(); ++i) {
        const int d = std::abs(int(gpu[i]) - int(cpu[i]));
        a.maxDifference = std::max(a.maxDifference, d);
        a.differing += d != 0;
    }
    return a;
}

void expectAgreement(const std::string& what, const std::vector<uint8_t>& gpu,
                     const std::vector<uint8_t>& cpu) {
    ASSERT_EQ(gpu.size(), cpu.size()) << what;
    const Agreement a = compare(gpu, cpu);
    std::printf("  %-44s max |GPU - CPU| = %d/255, %5.2f%% of channels differ\n", what.c_str(),
                a.maxDifference, 100.0 * double(a.differing) / double(a.channels));
    EXPECT_LE(a.maxDifference, 1) << what;
    for (size_t i = 0; i < cpu.size(); ++i) {
        if (std::abs(int(gpu[i]) - int(cpu[i])) > 1) {
            ADD_FAILURE() << what << ": pixel " << (i / 3) % kWidth << ", " << (i / 3) / kWidth << " channel "
                          << i % 3 << ": GPU " << int(gpu[i]) << ", CPU " << int(cpu[i]);
        }
    }
}

class DisplayGl : public ::testing::Test {
protected:
    void SetUp() override {
        std::string why;
        if (!context_.start(why)) GTEST_SKIP() << "no OpenGL context: " << why;
        view_ = std::make_unique<DisplayView>();
    }
    GlContext context_;
    std::unique_ptr<DisplayView> view_;
    const std::vector<float> image_ = testImage();
};

TEST_F(DisplayGl, BuiltInOperatorsMatchTheCpu) {
    for (int op = 0; op < int(ToneMapper::Count); ++op) {
        for (bool dither : {false, true}) {
            ViewerSettings viewer;
            viewer.builtinDisplay = true;
            viewer.display.toneMapper = ToneMapper(op);
            viewer.display.exposureStops = op == 1 ? 1.5f : 0.0f;
            viewer.display.dither = dither;
            const DisplayProcessor cpu(viewer.display);
            expectAgreement(
                std::string("built-in ") + toneMapperName(ToneMapper(op)) + (dither ? ", dithered" : ""),
                drawOnGpu(*view_, viewer, image_), cpu.encode8(image_, kWidth, dither));
        }
    }
}

TEST_F(DisplayGl, EveryViewOfTheShippedConfigMatchesTheCpu) {
#ifndef PT_HAVE_OCIO
    GTEST_SKIP() << "built without OpenColorIO (PT_OCIO=OFF)";
#else
    const std::string path = shippedColorConfigPath();
    const ColorView base = resolveColorView(path, {}, {});
    ASSERT_TRUE(base.config) << base.error;
    size_t views = 0;
    for (const std::string& display : base.config->displays()) {
        for (const std::string& name : base.config->views(display)) {
            for (const std::string& look : {std::string(), std::string("Exposure +1")}) {
                if (!look.empty() && name != "AgX") continue;  // one look is enough to show it applies
                ColorSettings settings;
                settings.display = display, settings.view = name, settings.look = look;
                const ColorView color = resolveColorView(path, settings, base);
                ASSERT_TRUE(color.error.empty()) << color.error;
                view_->setColorView(color);
                ASSERT_EQ(view_->shaderError(), "") << display << " / " << name;
                for (bool dither : {false, true}) {
                    ViewerSettings viewer;
                    viewer.display.exposureStops = 0.5f;
                    viewer.display.dither = dither;
                    const DisplayProcessor cpu(*color.config, color.view, viewer.display.exposureStops);
                    expectAgreement(display + " / " + name + (look.empty() ? "" : " / " + look) +
                                        (dither ? ", dithered" : ""),
                                    drawOnGpu(*view_, viewer, image_), cpu.encode8(image_, kWidth, dither));
                }
                ++views;
            }
        }
    }
    EXPECT_GE(views, 6u) << "the shipped config has at least Standard, AgX and ACES on two displays";
#endif
}

// The check itself must be able to fail: a view drawn on the GPU against another view's CPU
// bytes differs by far more than 1.
TEST_F(DisplayGl, DifferentTransformsDoNotAgree) {
    ViewerSettings viewer;
    viewer.builtinDisplay = true;
    viewer.display.toneMapper = ToneMapper::AgX;
    viewer.display.dither = false;
    DisplaySettings other = viewer.display;
    other.toneMapper = ToneMapper::Clamp;
    EXPECT_GT(
        compare(drawOnGpu(*view_, viewer, image_), DisplayProcessor(other).encode8(image_, kWidth, false))
            .maxDifference,
        10);
}

}  // namespace
}  // namespace pt::editor
