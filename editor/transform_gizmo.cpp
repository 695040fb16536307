#include "editor/transform_gizmo.h"

#include <algorithm>
#include <cmath>

#include "render/integrator/camera.h"

namespace pt::editor {
namespace {

constexpr int kRingSegments = 64;
constexpr float kMinScale = 0.01f;  // no drag scales through zero (a mirror is typed, not dragged)

Vec3 column(const Affine3& m, int c) { return {m.at(0, c), m.at(1, c), m.at(2, c)}; }

float distanceToSegment(Vec2 p, Vec2 a, Vec2 b) {
    const Vec2 ab = b - a, ap = p - a;
    const float lengthSq = ab.x * ab.x + ab.y * ab.y;
    const float t = lengthSq > 0.0f ? std::clamp((ap.x * ab.x + ap.y * ab.y) / lengthSq, 0.0f, 1.0f) : 0.0f;
    const Vec2 d = p - (a + ab * t);
    return std::sqrt(d.x * d.x + d.y * d.y);
}

float distance2d(Vec2 a, Vec2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

// The pinhole ray through an image point (pixels, y down; outside the image too, where a drag
// goes on) from the lens centre: the ray every thin-lens ray through it meets at the focal plane.
// generateCameraRay's direction, at a continuous point.
Ray cursorRay(const RenderCamera& camera, const GizmoView& view, Vec2 cursor) {
    const float ndcX = 2.0f * cursor.x / float(view.width) - 1.0f;
    const float ndcY = 1.0f - 2.0f * cursor.y / float(view.height);
    Ray ray;
    ray.origin = camera.origin;
    ray.direction = normalize(camera.forward + camera.right * ndcX + camera.up * ndcY);
    return ray;
}

RenderCamera renderCameraOf(const GizmoView& view) {
    return makeRenderCamera(view.camera, view.width, view.height);
}

// Where `p` lands in the image; none behind the camera.
std::optional<Vec2> toImage(const RenderCamera& camera, const GizmoView& view, Vec3 p) {
    float depth = 0.0f;
    const Vec2 at = projectToImage(camera, p, view.width, view.height, &depth);
    if (!(depth > 0.0f)) return std::nullopt;
    return at;
}

float snapTo(float value, float step) { return step > 0.0f ? std::round(value / step) * step : value; }

// Rotation by `radians` about the unit `axis` (Rodrigues, as a glTF quaternion).
Affine3 axisRotation(Vec3 axis, float radians) {
    const float s = std::sin(0.5f * radians);
    return rotationTransform({axis.x * s, axis.y * s, axis.z * s, std::cos(0.5f * radians)});
}

// ObjectTransform's Euler angles (R = Rz Ry Rx, degrees) of the rotation `r`, of the two
// solutions (and their 360-degree turns) the one nearest `near`.
Vec3 eulerDegreesNear(const Affine3& r, Vec3 near) {
    const float toDegrees = 180.0f / kPi;
    const float sy = -r.at(2, 0), cy = std::hypot(r.at(0, 0), r.at(1, 0));
    const float y = std::atan2(sy, cy);  // not asin(sy): ill-conditioned near +-90 degrees
    Vec3 a[2];
    if (cy < 1e-5f) {  // gimbal lock: only x + z (or x - z) is defined; keep x
        const float x = near.x / toDegrees;
        const float z = std::atan2(-r.at(0, 1), r.at(1, 1)) + (sy > 0.0f ? x : -x);
        a[0] = a[1] = Vec3(x, y, z) * toDegrees;
    } else {
        const float x = std::atan2(r.at(2, 1), r.at(2, 2)),
                    z = std::atan2(r.at(1, 0), r.at(0, 0));  // cos y > 0
        a[0] = Vec3(x, y, z) * toDegrees;
        a[1] = Vec3(x + kPi, kPi - y, z + kPi) * toDegrees;
    }
    const auto unwrap = [](float angle, float target) {
        return angle + 360.0f * std::round((target - angle) / 360.0f);
    };
    float best = INFINITY;
    Vec3 result = a[0];
    for (const Vec3& candidate : a) {
        const Vec3 u{unwrap(candidate.x, near.x), unwrap(candidate.y, near.y), unwrap(candidate.z, near.z)};
        const float d = lengthSquared(u - near);
        if (d < best) best = d, result = u;
    }
    return result;
}

// ObjectTransform's column-major 4x4 (the inverse of ObjectTransform::toAffine's matrix case).
void toMatrix(const Affine3& a, float m[16]) {
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 4; ++c) m[4 * c + r] = a.at(r, c);
    }
}

}  // namespace

std::optional<Gizmo> placeGizmo(const Affine3& placement, GizmoMode mode, GizmoSpace space,
                                const GizmoView& view, float handlePixels) {
    if (view.width == 0 || view.height == 0) return std::nullopt;
    Gizmo g;
    g.mode = mode;
    g.pivot = placement.translation();
    const bool local = space == GizmoSpace::Local || mode == GizmoMode::Scale;
    for (int i = 0; i < 3; ++i) {
        Vec3 world(0.0f);
        world[i] = 1.0f;
        const Vec3 axis = local ? column(placement, i) : world;
        if (!(lengthSquared(axis) > 1e-20f)) return std::nullopt;
        g.axes[i] = normalize(axis);
    }
    const RenderCamera camera = renderCameraOf(view);
    float depth = 0.0f;
    projectToImage(camera, g.pivot, view.width, view.height, &depth);
    if (!(depth > 0.0f)) return std::nullopt;
    // A pixel at depth z spans 2 z tan(fov / 2) / height world units (|camera.up| = tan(fov / 2)).
    g.size = handlePixels * depth * 2.0f * length(camera.up) / float(view.height);
    g.pixels = handlePixels;
    return g;
}

std::vector<GizmoShape> gizmoShapes(const Gizmo& gizmo, const GizmoView& view) {
    std::vector<GizmoShape> shapes;
    const RenderCamera camera = renderCameraOf(view);  // once: a ring projects 64 points
    const std::optional<Vec2> pivot = toImage(camera, view, gizmo.pivot);
    if (!pivot) return shapes;
    for (int i = 0; i < 3; ++i) {
        const Vec3 axis = gizmo.axes[i];
        GizmoShape shape;
        shape.handle = i;
        if (gizmo.mode == GizmoMode::Rotate) {
            // The ring in the plane across the axis.
            const Vec3 u = normalize(cross(axis, std::fabs(axis.x) < 0.9f ? Vec3(1, 0, 0) : Vec3(0, 1, 0)));
            const Vec3 v = cross(axis, u);
            bool whole = true;
            for (int k = 0; k < kRingSegments; ++k) {
                const float a = 2.0f * kPi * float(k) / float(kRingSegments);
                const std::optional<Vec2> p =
                    toImage(camera, view, gizmo.pivot + (u * std::cos(a) + v * std::sin(a)) * gizmo.size);
                if (p) shape.points.push_back(*p);
                whole = whole && p.has_value();
            }
            shape.closed = whole;
        } else {
            const std::optional<Vec2> end = toImage(camera, view, gizmo.pivot + axis * gizmo.size);
            // Seen end-on, or its tip behind the camera: not a handle one can drag along.
            if (!end || distance2d(*pivot, *end) < 0.2f * gizmo.pixels) continue;
            shape.points = {*pivot, *end};
        }
        shapes.push_back(std::move(shape));
    }
    if (gizmo.mode != GizmoMode::Rotate) shapes.push_back({kCentreHandle, {*pivot}, false});
    return shapes;
}

int gizmoHandleAt(const Gizmo& gizmo, const GizmoView& view, Vec2 cursor, float slopPixels) {
    int best = kNoHandle;
    float bestDistance = slopPixels;
    for (const GizmoShape& shape : gizmoShapes(gizmo, view)) {
        float d = INFINITY;
        const size_t n = shape.points.size();
        if (n == 1) d = distance2d(cursor, shape.points[0]) - slopPixels;  // the centre: a disc twice as wide
        for (size_t k = 0; k + 1 < n + (shape.closed ? 1 : 0); ++k) {
            d = std::min(d, distanceToSegment(cursor, shape.points[k], shape.points[(k + 1) % n]));
        }
        if (d <= bestDistance) bestDistance = d, best = shape.handle;
    }
    return best;
}

GizmoDrag::GizmoDrag(const Gizmo& gizmo, int handle, const GizmoView& view, Vec2 press)
    : gizmo_(gizmo), handle_(handle), view_(view), camera_(renderCameraOf(view)), press_(press) {
    pivotPixel_ = toImage(camera_, view, gizmo.pivot).value_or(press);
    if (handle_ >= 0 && handle_ < 3) pressParameter_ = axisParameter(press);
    lastAngle_ = screenAngle(press);
    const Ray ray = cursorRay(camera_, view, press);
    const float across = dot(ray.direction, camera_.forward);
    pressPoint_ = ray.origin + ray.direction * (dot(gizmo.pivot - ray.origin, camera_.forward) / across);
}

float GizmoDrag::axisParameter(Vec2 cursor) const {
    // The cursor slid onto the axis as drawn, then the axis point under it: the point of the axis
    // line nearest that ray (both directions unit length). Without the slide, a cursor off the
    // line would meet the axis where the skew lines pass closest, not where it looks.
    const Vec3 a = gizmo_.axes[handle_];
    const std::optional<Vec2> tip = toImage(camera_, view_, gizmo_.pivot + a * gizmo_.size);
    if (tip) {
        const Vec2 along = *tip - pivotPixel_, off = cursor - pivotPixel_;
        const float lengthSq = along.x * along.x + along.y * along.y;
        if (lengthSq > 0.0f) cursor = pivotPixel_ + along * ((off.x * along.x + off.y * along.y) / lengthSq);
    }
    const Ray ray = cursorRay(camera_, view_, cursor);
    const Vec3 w = gizmo_.pivot - ray.origin;
    const float b = dot(a, ray.direction), denominator = 1.0f - b * b;
    if (denominator < 1e-6f) return pressParameter_;  // the axis along the ray: no movement
    return (b * dot(ray.direction, w) - dot(a, w)) / denominator;
}

float GizmoDrag::screenAngle(Vec2 cursor) const {
    return std::atan2(-(cursor.y - pivotPixel_.y), cursor.x - pivotPixel_.x);  // image y grows down
}

GizmoEdit GizmoDrag::moveTo(Vec2 cursor, const GizmoSnap* snap) {
    GizmoEdit edit;
    const bool axis = handle_ >= 0 && handle_ < 3;
    switch (gizmo_.mode) {
        case GizmoMode::Translate:
            if (axis) {
                const float amount = axisParameter(cursor) - pressParameter_;
                edit.translate = gizmo_.axes[handle_] * (snap ? snapTo(amount, snap->translate) : amount);
            } else {
                const Ray ray = cursorRay(camera_, view_, cursor);
                const Vec3 facing = camera_.forward;
                const Vec3 at = ray.origin + ray.direction * (dot(pressPoint_ - ray.origin, facing) /
                                                              dot(ray.direction, facing));
                Vec3 d = at - pressPoint_;
                if (snap)
                    d = {snapTo(d.x, snap->translate), snapTo(d.y, snap->translate),
                         snapTo(d.z, snap->translate)};
                edit.translate = d;
            }
            break;
        case GizmoMode::Rotate: {
            // The angle swept on screen, unwrapped frame to frame; it turns about the axis the
            // right-handed way where the axis points at the viewer, the other way where it points away.
            const float angle = screenAngle(cursor);
            float step = angle - lastAngle_;
            step -= 2.0f * kPi * std::round(step / (2.0f * kPi));
            sweptRadians_ += step;
            lastAngle_ = angle;
            const Vec3 toViewer = view_.camera.position - gizmo_.pivot;
            const float sign = dot(gizmo_.axes[std::max(handle_, 0)], toViewer) >= 0.0f ? 1.0f : -1.0f;
            float radians = sign * sweptRadians_;
            if (snap) radians = snapTo(radians, snap->rotateDegrees * kPi / 180.0f);
            edit.rotationAxis = gizmo_.axes[std::max(handle_, 0)];
            edit.rotationRadians = radians;
            break;
        }
        case GizmoMode::Scale: {
            float factor = 1.0f;
            if (axis) {
                const float now = axisParameter(cursor);
                factor = std::fabs(pressParameter_) > 1e-6f * gizmo_.size ? now / pressParameter_ : 1.0f;
            } else {
                factor = distance2d(cursor, pivotPixel_) / std::max(distance2d(press_, pivotPixel_), 1.0f);
            }
            if (snap) factor = 1.0f + snapTo(factor - 1.0f, snap->scale);
            factor = std::max(factor, kMinScale);
            edit.scale = axis ? Vec3(1.0f) : Vec3(factor);
            if (axis) edit.scale[handle_] = factor;
            break;
        }
    }
    return edit;
}

Affine3 applyGizmoEdit(const Affine3& start, const GizmoEdit& edit) {
    Affine3 linear = start * scaleTransform(edit.scale);  // stretched along its own axes
    for (Vec4& row : linear.rows) row.w = 0.0f;
    Affine3 result = axisRotation(edit.rotationAxis, edit.rotationRadians) * linear;  // about its origin
    const Vec3 origin = start.translation() + edit.translate;
    result.rows[0].w = origin.x;
    result.rows[1].w = origin.y;
    result.rows[2].w = origin.z;
    return result;
}

ObjectTransform applyGizmoEdit(const ObjectTransform& start, const GizmoEdit& edit) {
    ObjectTransform t = start;
    if (t.useMatrix) {
        toMatrix(applyGizmoEdit(start.toAffine(), edit), t.matrix);
        return t;
    }
    t.translate += edit.translate;
    t.scale *= edit.scale;
    if (edit.rotationRadians != 0.0f) {
        ObjectTransform rotationOnly;
        rotationOnly.rotateDegrees = start.rotateDegrees;
        const Affine3 r = axisRotation(edit.rotationAxis, edit.rotationRadians) * rotationOnly.toAffine();
        t.rotateDegrees = eulerDegreesNear(r, start.rotateDegrees);
    }
    return t;
}

}  // namespace pt::editor
