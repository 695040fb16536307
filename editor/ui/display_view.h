#pragma once
// DisplayView: the render on screen. The linear frame goes into a float texture and a
// fragment shader (display_shader.h) applies the display transform on the GPU: exposure, then
// the scene's OpenColorIO view or a built-in operator, then dither, so display edits never
// touch the accumulation. AOVs are shown through a false-colour mode
// suited to each (normals remapped to [0, 1], ids hashed to colours, costs as a heat map).
#include <cstdint>
#include <memory>
#include <string>

#include "editor/color_view.h"
#include "editor/document.h"
#include "editor/error_tracker.h"
#include "editor/render_worker.h"
#include "editor/ui/display_shader.h"
#include "editor/ui/gl.h"

namespace pt::editor {

// Where the image lies in the window, in window pixels (y down), fitted into the viewport
// with its aspect ratio kept.
struct ImageRect {
    float x = 0, y = 0, width = 0, height = 0;
    uint32_t imageWidth = 0, imageHeight = 0;
    bool contains(float px, float py) const {
        return px >= x && py >= y && px < x + width && py < y + height;
    }
    // Window point -> image pixel coordinates (continuous; y down).
    float toImageX(float px) const { return (px - x) / width * float(imageWidth); }
    float toImageY(float py) const { return (py - y) / height * float(imageHeight); }
};

// With a reference image loaded, the beauty can be swapped for it or for the absolute
// difference |render - reference| (exposure applied, no tone mapping): an A/B switch.
enum class CompareView { Render = 0, Reference = 1, Difference = 2 };

class DisplayView {
public:
    DisplayView();
    ~DisplayView();
    DisplayView(const DisplayView&) = delete;
    DisplayView& operator=(const DisplayView&) = delete;

    void upload(const DisplayFrame& frame);
    // Rebuilds the shader when the OpenColorIO view changed. Where the view's shader does not
    // build, the built-in operators draw and shaderError() says why.
    void setColorView(const ColorView& color);
    const std::string& shaderError() const { return shaderError_; }
    // A frame whose pixels arrive on the GPU (InteropFrame): sizes the texture, keeps the AOV.
    void prepareDeviceFrame(const DisplayFrame& frame);
    GLuint texture() const { return texture_; }
    // Uploads the reference once per image (it is compared by pointer); nullptr: none.
    void setReference(const std::shared_ptr<const ReferenceImage>& reference);
    // Draws into the window area (x, y, w, h) in window pixels (y down) of a framebuffer of
    // `framebufferHeight` pixels; returns where the image went.
    ImageRect draw(const ViewerSettings& viewer, CompareView compare, float x, float y, float w, float h,
                   float framebufferHeight, float pixelScale);
    bool hasImage() const { return width_ > 0; }
    void clear() { width_ = height_ = 0; }  // nothing drawn until the next frame comes
    // The largest value of the shown AOV's first channel, for the heat map's legend.
    float aovMaximum() const { return aovMax_; }

private:
    std::unique_ptr<DisplayShader> shader_;
    std::string colorKey_ = "built-in", shaderError_;
    GLuint texture_ = 0, referenceTexture_ = 0, vao_ = 0;
    std::shared_ptr<const ReferenceImage> reference_;
    uint32_t width_ = 0, height_ = 0;
    int32_t aov_ = -1;
    float aovMax_ = 1.0f;
};

}  // namespace pt::editor
