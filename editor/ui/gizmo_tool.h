#pragma once
// The transform gizmo in the viewport: its handles drawn over the selected object or instance,
// a drag of one that moves, turns or scales it as one undo step (each frame of the drag a
// command that folds into the step; Esc or a right click cancels the drag), and its items of the
// viewport's toolbar (mode, world or local axes, snapping and its steps). Keys: 1 move,
// 2 rotate, 3 scale, L world/local; Ctrl held during a drag flips snapping. The geometry is
// editor/transform_gizmo.h.
#include <optional>

#include "editor/transform_gizmo.h"
#include "editor/ui/display_view.h"
#include "editor/ui/editor_ui.h"

namespace pt::editor {

class GizmoTool {
public:
    // Once a frame before the viewport's clicks: true while the gizmo has the mouse (a press on
    // a handle, or its drag), which is then no click to select or orbit.
    bool handle(EditorUi& ui, const ImageRect& image);
    void draw(const EditorUi& ui, const ImageRect& image);
    // Mode, world or local axes, snapping and its steps: the viewport toolbar's first items.
    void toolbarItems();
    bool dragging() const { return drag_.has_value(); }

private:
    struct Target {  // what the gizmo moves: an object, or an instance no object owns
        int32_t object = -1, instance = -1;
        Affine3 placement;
    };
    std::optional<Target> target(const EditorUi& ui) const;
    std::optional<Gizmo> place(const EditorUi& ui, const ImageRect& image, const Target& target) const;
    void keys();
    void dragTo(EditorUi& ui, const ImageRect& image);

    GizmoMode mode_ = GizmoMode::Translate;
    GizmoSpace space_ = GizmoSpace::World;
    bool snap_ = false;
    GizmoSnap steps_;
    int hovered_ = kNoHandle;
    std::optional<GizmoDrag> drag_;
    Target dragged_;                  // the target as it was at the press
    ObjectTransform pressTransform_;  // its object's transform then
    bool applied_ = false;            // the drag has made a command (something to cancel)
    bool heldAfterCancel_ = false;    // a cancel's button is still down
    float lastX_ = 0, lastY_ = 0;
    bool lastCtrl_ = false;
};

}  // namespace pt::editor
