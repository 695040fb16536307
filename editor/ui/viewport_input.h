#pragma once
// Viewport mouse and keyboard: orbit (middle or right drag, or Alt+left), pan (Shift+middle or
// Shift+right), zoom
// (wheel), WASD fly (Q/E down/up), click to select what is under the cursor, double-click to
// focus depth of field there; the transform gizmo over the selection has the mouse first.
// Shortcuts: Ctrl+Z / Ctrl+Shift+Z (or Ctrl+Y), Ctrl+O, Ctrl+S,
// Ctrl+E, Delete, Ctrl+D, H, F12 (screenshot).
#include "editor/ui/display_view.h"
#include "editor/ui/editor_ui.h"
#include "editor/ui/gizmo_tool.h"

namespace pt::editor {

class ViewportInput {
public:
    // Call once per frame after ImGui::NewFrame(). Returns true when F12 asked for a screenshot.
    bool handle(EditorUi& ui, const ImageRect& image, float frameSeconds);
    // A camera drag or fly is under way: the window draws every frame meanwhile.
    bool moving() const { return dragging_ || flying_ || gizmo_.dragging(); }
    // The transform gizmo over the selection (it takes the mouse first: gizmo_tool.h).
    GizmoTool& gizmo() { return gizmo_; }

private:
    void navigate(EditorUi& ui, const ImageRect& image, float frameSeconds);
    void clickTools(EditorUi& ui, const ImageRect& image);
    bool shortcuts(EditorUi& ui);

    GizmoTool gizmo_;
    bool dragging_ = false;  // a camera drag is under way (one undo step)
    bool flying_ = false;
    float pressX_ = 0, pressY_ = 0;
};

}  // namespace pt::editor
