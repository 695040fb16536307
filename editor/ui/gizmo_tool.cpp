#include "editor/ui/gizmo_tool.h"

#include <imgui.h>

#include <cmath>

#include "editor/scene_edits.h"
#include "editor/ui/gl.h"
#include "editor/ui/input_events.h"

namespace pt::editor {
namespace {

constexpr float kHandleScreenPixels = 90.0f;  // an axis handle's length at interface scale 1
constexpr float kSlopScreenPixels = 7.0f;     // how near the cursor must come to a handle

const char* verb(GizmoMode mode) {
    return mode == GizmoMode::Translate ? "Move" : mode == GizmoMode::Rotate ? "Rotate" : "Scale";
}

ImU32 handleColour(int handle, bool lit) {
    if (lit) return IM_COL32(255, 220, 60, 255);
    switch (handle) {
        case 0: return IM_COL32(235, 75, 75, 255);
        case 1: return IM_COL32(120, 205, 70, 255);
        case 2: return IM_COL32(80, 140, 245, 255);
        default: return IM_COL32(235, 235, 235, 255);
    }
}

GizmoView viewOf(const EditorUi& ui, const ImageRect& image) {
    return {ui.doc().scene.camera, image.imageWidth, image.imageHeight};
}

// A window point in the pixels of `view`'s image. The image on screen may change resolution
// during a drag (a coarse render while the selection moves), so a drag keeps the view of its
// press and maps the cursor into that.
Vec2 toView(const ImageRect& image, const GizmoView& view, float x, float y) {
    return {(x - image.x) / image.width * float(view.width),
            (y - image.y) / image.height * float(view.height)};
}

Vec2 toImage(const ImageRect& image, float x, float y) { return {image.toImageX(x), image.toImageY(y)}; }

ImVec2 toScreen(const ImageRect& image, Vec2 p) {
    return {image.x + p.x * image.width / float(image.imageWidth),
            image.y + p.y * image.height / float(image.imageHeight)};
}

}  // namespace

std::optional<GizmoTool::Target> GizmoTool::target(const EditorUi& ui) const {
    const Selection& sel = ui.selection;
    const Scene& scene = ui.doc().scene;
    Target t;
    if (sel.kind == Selection::Kind::Object && sel.index >= 0 && size_t(sel.index) < scene.objects.size()) {
        t.object = sel.index;
        t.placement = scene.objects[size_t(sel.index)].transform.toAffine();
        return t;
    }
    if (sel.kind == Selection::Kind::Instance && sel.index >= 0 &&
        size_t(sel.index) < scene.instances.size()) {
        t.instance = sel.index;
        t.placement = scene.instances[size_t(sel.index)].objectToWorld;
        return t;
    }
    return std::nullopt;
}

std::optional<Gizmo> GizmoTool::place(const EditorUi& ui, const ImageRect& image,
                                      const Target& target) const {
    if (image.imageWidth == 0 || image.width <= 0.0f) return std::nullopt;
    const float pixels = kHandleScreenPixels * ui.layout.scale * float(image.imageWidth) / image.width;
    return placeGizmo(target.placement, mode_, space_, viewOf(ui, image), pixels);
}

void GizmoTool::keys() {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput || io.WantCaptureKeyboard || drag_) return;
    const InputEvents& events = inputEvents();
    if (events.chord(GLFW_KEY_1, 0)) mode_ = GizmoMode::Translate;
    if (events.chord(GLFW_KEY_2, 0)) mode_ = GizmoMode::Rotate;
    if (events.chord(GLFW_KEY_3, 0)) mode_ = GizmoMode::Scale;
    if (events.chord(GLFW_KEY_L, 0))
        space_ = space_ == GizmoSpace::World ? GizmoSpace::Local : GizmoSpace::World;
}

void GizmoTool::dragTo(EditorUi& ui, const ImageRect& image) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.MousePos.x == lastX_ && io.MousePos.y == lastY_ && io.KeyCtrl == lastCtrl_) return;
    lastX_ = io.MousePos.x;
    lastY_ = io.MousePos.y;
    lastCtrl_ = io.KeyCtrl;
    const bool snap = snap_ != io.KeyCtrl;  // Ctrl flips snapping for as long as it is held
    const GizmoEdit edit =
        drag_->moveTo(toView(image, drag_->view(), io.MousePos.x, io.MousePos.y), snap ? &steps_ : nullptr);
    if (dragged_.object >= 0) {
        ui.apply(setObjectTransform(ui.doc(), uint32_t(dragged_.object),
                                    applyGizmoEdit(pressTransform_, edit), verb(mode_)));
    } else {
        ui.apply(setInstanceTransform(ui.doc(), uint32_t(dragged_.instance),
                                      applyGizmoEdit(dragged_.placement, edit), verb(mode_)));
    }
    applied_ = true;
}

bool GizmoTool::handle(EditorUi& ui, const ImageRect& image) {
    keys();
    const ImGuiIO& io = ImGui::GetIO();
    const bool anyDown = ImGui::IsMouseDown(ImGuiMouseButton_Left) ||
                         ImGui::IsMouseDown(ImGuiMouseButton_Right) ||
                         ImGui::IsMouseDown(ImGuiMouseButton_Middle);
    if (heldAfterCancel_) {  // the button that cancelled is no orbit or click once released
        heldAfterCancel_ = anyDown;
        return true;
    }
    const std::optional<Target> selected = target(ui);
    const std::optional<Gizmo> gizmo = selected ? place(ui, image, *selected) : std::nullopt;
    const float slop =
        kSlopScreenPixels * ui.layout.scale * float(image.imageWidth) / std::max(image.width, 1.0f);
    if (drag_) {
        const InputEvents& events = inputEvents();
        if (events.tapped(GLFW_KEY_ESCAPE) || events.pressed(GLFW_MOUSE_BUTTON_RIGHT)) {
            if (applied_) ui.cancelDrag();
            drag_.reset();
            heldAfterCancel_ = true;
            return true;
        }
        dragTo(ui, image);
        if (!ImGui::IsMouseDown(ImGuiMouseButton_Left) && !events.pressed(GLFW_MOUSE_BUTTON_LEFT)) {
            if (applied_) ui.endDrag();
            drag_.reset();
        }
        return true;
    }
    hovered_ = kNoHandle;
    if (!gizmo || io.KeyAlt) return false;
    const bool overWindow = ImGui::IsWindowHovered(ImGuiHoveredFlags_AnyWindow);
    if (!overWindow && image.contains(io.MousePos.x, io.MousePos.y)) {
        hovered_ =
            gizmoHandleAt(*gizmo, viewOf(ui, image), toImage(image, io.MousePos.x, io.MousePos.y), slop);
    }
    const std::optional<ScreenPoint> press = inputEvents().pressed(GLFW_MOUSE_BUTTON_LEFT);
    if (!press || overWindow || !image.contains(press->x, press->y)) return false;
    const Vec2 at = toImage(image, press->x, press->y);
    const int handle = gizmoHandleAt(*gizmo, viewOf(ui, image), at, slop);
    if (handle == kNoHandle) return false;
    drag_.emplace(*gizmo, handle, viewOf(ui, image), at);
    dragged_ = *selected;
    if (selected->object >= 0) pressTransform_ = ui.doc().scene.objects[size_t(selected->object)].transform;
    applied_ = false;
    lastX_ = press->x;
    lastY_ = press->y;
    lastCtrl_ = io.KeyCtrl;
    hovered_ = handle;
    ui.endDrag();  // whatever step was open before is not this drag's
    return true;
}

void GizmoTool::toolbarItems() {
    const struct {
        GizmoMode mode;
        const char* label;
        const char* tip;
    } modes[] = {
        {GizmoMode::Translate, "Move", "Move along an axis, or across the view from the centre (1)"},
        {GizmoMode::Rotate, "Rotate", "Turn about an axis (2)"},
        {GizmoMode::Scale, "Scale", "Stretch along the object's own axes, or evenly from the centre (3)"}};
    for (const auto& m : modes) {
        const bool on = mode_ == m.mode;
        if (on) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
        if (ImGui::SmallButton(m.label)) mode_ = m.mode;
        if (on) ImGui::PopStyleColor();
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", m.tip);
        ImGui::SameLine();
    }
    if (ImGui::SmallButton(space_ == GizmoSpace::World ? "World" : "Local"))
        space_ = space_ == GizmoSpace::World ? GizmoSpace::Local : GizmoSpace::World;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Axes of the world or of the object (L); scale always uses the object's");
    ImGui::SameLine();
    ImGui::Checkbox("Snap", &snap_);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "Round each drag to the steps (right click to set them); Ctrl flips it while dragging");
    if (ImGui::BeginPopupContextItem("snap steps")) {
        ImGui::SetNextItemWidth(120.0f);
        ImGui::DragFloat("move step", &steps_.translate, 0.01f, 0.001f, 1000.0f, "%.3f");
        ImGui::SetNextItemWidth(120.0f);
        ImGui::DragFloat("rotate step (deg)", &steps_.rotateDegrees, 0.5f, 0.5f, 180.0f, "%.1f");
        ImGui::SetNextItemWidth(120.0f);
        ImGui::DragFloat("scale step", &steps_.scale, 0.01f, 0.01f, 10.0f, "%.2f");
        ImGui::EndPopup();
    }
}

void GizmoTool::draw(const EditorUi& ui, const ImageRect& image) {
    if (image.imageWidth == 0) return;
    // Where the selection is now (during a drag too: the gizmo follows what it moves).
    const std::optional<Target> selected = target(ui);
    const std::optional<Gizmo> gizmo = selected ? place(ui, image, *selected) : std::nullopt;
    if (!gizmo) return;
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    draw->PushClipRect(ImVec2(image.x, image.y), ImVec2(image.x + image.width, image.y + image.height), true);
    const float thickness = 2.5f * ui.layout.scale, tip = 6.0f * ui.layout.scale;
    const int active = drag_ ? drag_->handle() : hovered_;
    for (const GizmoShape& shape : gizmoShapes(*gizmo, viewOf(ui, image))) {
        const ImU32 colour = handleColour(shape.handle, shape.handle == active);
        std::vector<ImVec2> points;
        for (const Vec2 p : shape.points) points.push_back(toScreen(image, p));
        if (shape.handle == kCentreHandle) {
            if (mode_ == GizmoMode::Scale)
                draw->AddCircleFilled(points[0], tip, colour);
            else
                draw->AddCircle(points[0], 1.5f * tip, colour, 0, thickness);
            continue;
        }
        draw->AddPolyline(points.data(), int(points.size()), colour, shape.closed ? ImDrawFlags_Closed : 0,
                          thickness);
        if (mode_ == GizmoMode::Rotate || points.size() != 2) continue;
        const ImVec2 end = points[1];
        if (mode_ == GizmoMode::Scale) {
            draw->AddRectFilled(ImVec2(end.x - tip, end.y - tip), ImVec2(end.x + tip, end.y + tip), colour);
        } else {  // an arrowhead along the axis as drawn
            const float dx = end.x - points[0].x, dy = end.y - points[0].y,
                        len = std::max(std::hypot(dx, dy), 1e-3f);
            const float ux = dx / len, uy = dy / len;
            draw->AddTriangleFilled(ImVec2(end.x + ux * 2.0f * tip, end.y + uy * 2.0f * tip),
                                    ImVec2(end.x - uy * tip, end.y + ux * tip),
                                    ImVec2(end.x + uy * tip, end.y - ux * tip), colour);
        }
    }
    draw->PopClipRect();
}

}  // namespace pt::editor
