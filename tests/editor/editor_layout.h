#pragma once
// Where the editor window draws what, for programs that drive it with X input events (the
// end-to-end test, the latency driver): derived from the editor's code and ImGui 1.86's default
// style, not from pixels of one run. A driver checks what it hit through the editor's own
// output (its screenshots, the edits it logs), so a layout that moved fails loudly.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "render/integrator/camera.h"

namespace pt::test {

// ImGui 1.86's default style and font (the editor changes neither): ProggyClean 13 px,
// FramePadding (4, 3), ItemSpacing (8, 4), WindowPadding (8, 8), GrabMinSize 10, and a
// slider's grab inset of 2 px; the default item width is 65% of the window's width.
constexpr float kFontSize = 13.0f;
constexpr float kFrameHeight = kFontSize + 2 * 3.0f;  // menu bar, headers, one-line widgets: 19
constexpr float kItemSpacingY = 4.0f;
constexpr float kRow = kFrameHeight + kItemSpacingY;   // one widget row: 23
constexpr float kTextRow = kFontSize + kItemSpacingY;  // one line of text, a list row: 17
constexpr float kWindowPadding = 8.0f;
constexpr float kGrabMinSize = 10.0f, kGrabPadding = 2.0f;
// The editor's own (editor_window.cpp kPanelWidth, outliner_panel.cpp BeginChild height,
// editor_ui.h kStatusBarHeight).
constexpr float kPanelWidth = 400.0f;
constexpr float kStatusBarHeight = 19.0f;
constexpr float kOutlinerHeight = 180.0f;

struct Point {
    float x = 0, y = 0;
};

struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // [x0, x1) x [y0, y1), window pixels
};

// What the Inspector shows for an object picked with one of its instances (inspector_panel.cpp
// objectInspector): Name, Hidden, Translate, Rotate, Scale, the variant combo where the object
// has variants, the "Instance:" line, the morph section where its mesh has targets (header, a
// slider a target, the reset button), then a header and the editor of each of its materials.
struct InspectedObject {
    bool variants = false;
    uint32_t morphTargets = 0;
    bool baseColorTexture = false;  // of its first material: a checkbox row after Base color
};

struct Layout {
    float width = 0, height = 0;  // the window, in pixels (no window manager: no frame)
    uint32_t renderWidth = 0, renderHeight = 0;
    float imageX = 0, imageY = 0, imageWidth = 0, imageHeight = 0;  // the render, fit to the viewport

    Layout(float w, float h, uint32_t rw, uint32_t rh)
        : width(w), height(h), renderWidth(rw), renderHeight(rh) {
        // DisplayView::draw: the viewport is left of the panel, below the menu bar and above
        // the status bar; the image keeps its aspect and is centred.
        const float vw = width - kPanelWidth, vh = height - kFrameHeight - kStatusBarHeight;
        const float s = rw > 0 && rh > 0 ? std::min(vw / float(rw), vh / float(rh)) : 0.0f;
        imageWidth = s * float(rw);
        imageHeight = s * float(rh);
        imageX = 0.5f * (vw - imageWidth);
        imageY = kFrameHeight + 0.5f * (vh - imageHeight);
    }
    float scale() const { return renderWidth > 0 ? imageWidth / float(renderWidth) : 0.0f; }
    // Whole pixels of the window that show the render.
    PixelRect viewport() const {
        return {int(std::ceil(imageX)), int(std::ceil(imageY)), int(std::floor(imageX + imageWidth)),
                int(std::floor(imageY + imageHeight))};
    }
    Point fromRender(Point p) const { return {imageX + p.x * scale(), imageY + p.y * scale()}; }
    Point viewportCentre() const { return {imageX + 0.5f * imageWidth, imageY + 0.5f * imageHeight}; }

    float panelX() const { return width - kPanelWidth; }
    // The Outliner's rows: "Camera" is row 0, the scene's objects follow (outliner_panel.cpp).
    float outlinerRowCentreY(int row) const {
        return kFrameHeight + kWindowPadding + kRow + kWindowPadding + float(row) * kTextRow +
               0.5f * kFontSize;
    }
    // Top of the Inspector's first widget: the panel's padding, the Outliner (header, list,
    // hint line) and the Inspector header.
    float inspectorTop() const {
        return kFrameHeight + kWindowPadding + kRow + (kOutlinerHeight + kItemSpacingY) + kTextRow + kRow;
    }
    // Top of the morph section's header, below the object's rows and the "Instance:" line.
    float morphTop(const InspectedObject& o) const {
        return inspectorTop() + (o.variants ? 6 : 5) * kRow + kTextRow;
    }
    float morphSliderCentreY(const InspectedObject& o, uint32_t target) const {
        return morphTop(o) + float(1 + target) * kRow + 0.5f * kFrameHeight;
    }
    // The first material's header; its editor: Base color, [texture], Metallic, Roughness, ...
    float materialTop(const InspectedObject& o = {}) const {
        return morphTop(o) + (o.morphTargets > 0 ? float(o.morphTargets + 2) * kRow : 0.0f);
    }
    float roughnessCentreY(const InspectedObject& o = {}) const {
        return materialTop(o) + (o.baseColorTexture ? 4 : 3) * kRow + 0.5f * kFrameHeight;
    }
    // A slider's frame starts at the panel's padding and is 65% of the panel wide; the grab's
    // centre runs over [usableMin, usableMin + usableSize] as the value runs over its range.
    float sliderLeft() const { return panelX() + kWindowPadding; }
    float sliderWidth() const { return std::floor(0.65f * kPanelWidth); }
    float usableMin() const { return sliderLeft() + kGrabPadding + 0.5f * kGrabMinSize; }
    float usableSize() const { return sliderWidth() - 2 * kGrabPadding - kGrabMinSize; }
    float sliderX(float t) const { return usableMin() + t * usableSize(); }
    // The Inspector rows the selection fills (Name .. Scale): panels that do not change from
    // frame to frame before it (the hint, the Camera, Render settings and Display headers).
    PixelRect inspectorRows() const {
        return {int(panelX()), int(inspectorTop()), int(width), int(materialTop())};
    }
    // Where the pointer rests between actions: a viewport corner hovers over nothing (the
    // status bar below would show its notice's tooltip).
    Point restingPoint() const { return {imageX + 4, height - kStatusBarHeight - 4}; }
};

// Where a world point lands in the render (pixels, y down), the inverse of generateCameraRay.
inline Point projectToRender(const Camera& camera, Vec3 p, uint32_t width, uint32_t height) {
    const Vec2 at = projectToImage(makeRenderCamera(camera, width, height), p, width, height, nullptr);
    return {at.x, at.y};
}

}  // namespace pt::test
