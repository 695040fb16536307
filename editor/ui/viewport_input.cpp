#include "editor/ui/viewport_input.h"

#include <cmath>
#include <optional>

#include "editor/camera_controller.h"
#include "editor/object_edits.h"
#include "editor/scene_edits.h"
#include "editor/ui/gl.h"
#include "editor/ui/input_events.h"
#include "editor/ui/widgets.h"

namespace pt::editor {
namespace {

constexpr float kClickSlop = 3.0f;  // pixels a click may move and still select

// Runs a pick on the backend between passes; the image point is in render pixels.
PickResult pickAt(EditorUi& ui, const ImageRect& image, float x, float y) {
    PickResult result;
    const float px = image.toImageX(x), py = image.toImageY(y);
    ui.worker.withBackend([&](EditorSession& s) { result = s.pick(px, py); });
    return result;
}

}  // namespace

void ViewportInput::navigate(EditorUi& ui, const ImageRect& image, float frameSeconds) {
    const ImGuiIO& io = ImGui::GetIO();
    const bool over = image.contains(io.MousePos.x, io.MousePos.y);
    const Camera& camera = ui.doc().scene.camera;
    const float h = image.height;
    const bool middle = ImGui::IsMouseDown(ImGuiMouseButton_Middle);
    const bool altLeft = io.KeyAlt && ImGui::IsMouseDown(ImGuiMouseButton_Left);
    // The right button too: many window managers take Alt+left-drag to move the window, and a
    // laptop's touchpad may have no middle button.
    const bool rightDrag = ImGui::IsMouseDown(ImGuiMouseButton_Right);
    if ((middle || altLeft || rightDrag) && (dragging_ || (over && !io.WantCaptureMouse))) {
        const ImVec2 d = io.MouseDelta;
        if (d.x != 0.0f || d.y != 0.0f) {
            const Camera next =
                io.KeyShift ? panCamera(camera, d.x, d.y, h) : orbitCamera(camera, d.x, d.y, h);
            ui.apply(setCamera(ui.doc(), next));
        }
        dragging_ = true;
    } else if (dragging_) {
        dragging_ = false;
        ui.endDrag();
    }
    if (over && !io.WantCaptureMouse && io.MouseWheel != 0.0f) {
        ui.apply(setCamera(ui.doc(), dollyCamera(camera, io.MouseWheel)));
        ui.endDrag();
    }
    if (io.WantCaptureKeyboard || io.KeyCtrl) return;
    const InputEvents& keys = inputEvents();  // held from a press without Ctrl or Alt
    const auto held = [&keys](int key) { return float(keys.heldPlain(key)); };
    const float forward = held(GLFW_KEY_W) - held(GLFW_KEY_S);
    const float right = held(GLFW_KEY_D) - held(GLFW_KEY_A);
    const float up = held(GLFW_KEY_E) - held(GLFW_KEY_Q);
    if (forward != 0.0f || right != 0.0f || up != 0.0f) {
        const float speed = flySpeedFor(ui.doc().scene) * (io.KeyShift ? 4.0f : 1.0f);
        ui.apply(setCamera(ui.doc(), flyCamera(camera, forward, right, up, frameSeconds, speed)));
        flying_ = true;
    } else if (flying_) {
        flying_ = false;
        ui.endDrag();
    }
}

void ViewportInput::clickTools(EditorUi& ui, const ImageRect& image) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantCaptureMouse || io.KeyAlt) return;
    const ImVec2 m = io.MousePos;
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
        pressX_ = m.x;
        pressY_ = m.y;
    }
    // From the press events' own times and places (input_events.h): at a few frames a second
    // ImGui's frame-time double-click misses most.
    if (const std::optional<ScreenPoint> at = inputEvents().doubleClick(GLFW_MOUSE_BUTTON_LEFT);
        at && image.contains(at->x, at->y)) {
        const PickResult hit = pickAt(ui, image, at->x, at->y);
        if (hit.hit()) {
            Camera c = ui.doc().scene.camera;
            c.focusDistance = hit.focusDistance;
            ui.apply(setCamera(ui.doc(), c));
            ui.endDrag();
        }
        return;
    }
    if (!image.contains(m.x, m.y)) return;
    if (ImGui::IsMouseReleased(ImGuiMouseButton_Left) && std::fabs(m.x - pressX_) <= kClickSlop &&
        std::fabs(m.y - pressY_) <= kClickSlop) {
        const PickResult hit = pickAt(ui, image, m.x, m.y);
        if (!hit.hit())
            ui.selection = {};
        else if (hit.object >= 0)
            ui.selection = {Selection::Kind::Object, hit.object, hit.instance};
        else
            ui.selection = {Selection::Kind::Instance, hit.instance, hit.instance};
    }
}

bool ViewportInput::shortcuts(EditorUi& ui) {
    const ImGuiIO& io = ImGui::GetIO();
    const InputEvents& keys = inputEvents();  // each press with the modifiers it came with
    const bool screenshot = keys.tapped(GLFW_KEY_F12);
    if (io.WantTextInput) return screenshot;
    if (keys.chord(GLFW_KEY_Z, kModCtrl)) ui.undo();
    if (keys.chord(GLFW_KEY_Z, kModCtrl | kModShift) || keys.chord(GLFW_KEY_Y, kModCtrl)) ui.redo();
    if (keys.chord(GLFW_KEY_O, kModCtrl)) ui.showOpenDialog = true;
    if (keys.chord(GLFW_KEY_S, kModCtrl)) ui.showSaveDialog = true;
    if (keys.chord(GLFW_KEY_E, kModCtrl)) ui.showExportDialog = true;
    if (keys.chord(GLFW_KEY_Q, kModCtrl)) ui.quit(glfwGetCurrentContext());
    const Selection& sel = ui.selection;
    if (sel.kind != Selection::Kind::Object || sel.index < 0 || io.WantCaptureKeyboard) return screenshot;
    const uint32_t object = uint32_t(sel.index);
    if (keys.chord(GLFW_KEY_DELETE, 0)) {
        ui.apply(deleteObject(ui.doc(), object));
        ui.selection = {};
    } else if (keys.chord(GLFW_KEY_D, kModCtrl)) {
        ui.duplicateBeside(object);
    } else if (keys.chord(GLFW_KEY_H, 0) || keys.chord(GLFW_KEY_H, kModShift)) {
        ui.apply(setObjectHidden(ui.doc(), object, !objectHidden(ui.doc().scene, object)));
    }
    return screenshot;
}

bool ViewportInput::handle(EditorUi& ui, const ImageRect& image, float frameSeconds) {
    // A camera drag under way keeps the mouse; else the gizmo may take it.
    if (dragging_ || !gizmo_.handle(ui, image)) {
        navigate(ui, image, frameSeconds);
        clickTools(ui, image);
    }
    return shortcuts(ui);
}

}  // namespace pt::editor
