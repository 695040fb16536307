#pragma once
// The viewport's transform gizmo without a window: where its handles lie in the image, which one
// the cursor is over, and what a drag from the press to the cursor makes of the selection's
// transform. The window draws the handles and turns every drag position into one command that
// folds into the drag's undo step (editor/ui/gizmo_tool.h).
//
// Translate moves along an axis, or in the plane facing the camera from the centre handle.
// Rotate turns about an axis by the angle the cursor sweeps around the pivot on screen (as
// Blender's rotate does: it keeps working where the ring is seen edge-on). Scale stretches along
// the selection's own axes whatever the space (a world-axis stretch of a rotated object is a
// shear that a translate/rotate/scale transform cannot hold), or uniformly from the centre.
// Snapping rounds the drag's amount, not the result, to a step (Blender's increment snapping).
// The handles keep one size on screen at any distance.
#include <cstdint>
#include <optional>
#include <vector>

#include "render/kernel/render_scene.h"
#include "render/scene/scene.h"

namespace pt::editor {

enum class GizmoMode : uint8_t { Translate, Rotate, Scale };
enum class GizmoSpace : uint8_t { World, Local };

struct GizmoSnap {
    float translate = 0.1f;  // world units
    float rotateDegrees = 15.0f;
    float scale = 0.1f;  // steps of the scale factor
};

// What the gizmo is seen through: the scene's camera over the render's image (pixels, y down).
struct GizmoView {
    Camera camera;
    uint32_t width = 0, height = 0;
};

// Handles 0-2 are the axes X, Y, Z; the centre moves in the view plane or scales uniformly.
constexpr int kNoHandle = -1;
constexpr int kCentreHandle = 3;

struct Gizmo {
    GizmoMode mode = GizmoMode::Translate;
    Vec3 pivot;           // world: the placement's origin
    Vec3 axes[3];         // world, unit length
    float size = 1.0f;    // world length of an axis handle and radius of a ring
    float pixels = 1.0f;  // what `size` spans in the image across the view at the pivot
};

// The gizmo of `placement` (object-to-world), its axes `handlePixels` long in the image; none
// where the pivot is behind the camera or the placement is degenerate.
std::optional<Gizmo> placeGizmo(const Affine3& placement, GizmoMode mode, GizmoSpace space,
                                const GizmoView& view, float handlePixels);

// A handle as drawn, in image pixels: an axis is a segment from the pivot out, a ring a closed
// loop (only its parts in front of the camera), the centre one point. Axes seen end-on (shorter
// on screen than a fifth of their length) are left out: they could not be dragged with any
// precision.
struct GizmoShape {
    int handle = kNoHandle;
    std::vector<Vec2> points;
    bool closed = false;
};
std::vector<GizmoShape> gizmoShapes(const Gizmo& gizmo, const GizmoView& view);

// The handle within `slopPixels` of `cursor` (image pixels), the nearest where several are.
int gizmoHandleAt(const Gizmo& gizmo, const GizmoView& view, Vec2 cursor, float slopPixels);

// What a drag does, relative to the transform at the press.
struct GizmoEdit {
    Vec3 translate{0.0f, 0.0f, 0.0f};  // world
    Vec3 rotationAxis{0.0f, 1.0f, 0.0f};
    float rotationRadians = 0.0f;  // about rotationAxis (world, unit) through the pivot
    Vec3 scale{1.0f, 1.0f, 1.0f};  // along the placement's own axes
};

// One drag of one handle, from the press (image pixels) on.
class GizmoDrag {
public:
    GizmoDrag(const Gizmo& gizmo, int handle, const GizmoView& view, Vec2 press);
    // The edit with the cursor at `cursor`; `snap` null for a free drag. Rotation follows the
    // cursor round and round (more than half a turn is not folded back).
    GizmoEdit moveTo(Vec2 cursor, const GizmoSnap* snap);
    int handle() const { return handle_; }
    const GizmoView& view() const { return view_; }  // the press's: cursors are in its pixels

private:
    float axisParameter(Vec2 cursor) const;  // along the dragged axis, through the cursor's ray
    float screenAngle(Vec2 cursor) const;    // about the pivot on screen, counter-clockwise

    Gizmo gizmo_;
    int handle_;
    GizmoView view_;
    RenderCamera camera_;  // view_'s, made once
    Vec2 press_, pivotPixel_;
    float pressParameter_ = 0.0f;
    Vec3 pressPoint_;  // the centre's drag: the press on the view plane
    float lastAngle_ = 0.0f, sweptRadians_ = 0.0f;
};

// The transform after the drag: rotation about the placement's origin, scale along its axes.
Affine3 applyGizmoEdit(const Affine3& start, const GizmoEdit& edit);
// As scene JSON keeps it: a translate/rotate/scale stays one (its Euler angles chosen nearest to
// the start's, so the Inspector's numbers do not jump by 360 or flip), a matrix stays a matrix.
ObjectTransform applyGizmoEdit(const ObjectTransform& start, const GizmoEdit& edit);

}  // namespace pt::editor
