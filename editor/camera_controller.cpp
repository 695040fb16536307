#include "editor/camera_controller.h"

#include <algorithm>
#include <cmath>

namespace pt::editor {
namespace {

struct ViewFrame {
    Vec3 forward, right, up;
    float distance;
};

ViewFrame viewFrame(const Camera& c) {
    Vec3 offset = c.lookAt - c.position;
    float distance = length(offset);
    if (!(distance > 0.0f)) {
        offset = Vec3(0.0f, 0.0f, -1.0f);
        distance = 1.0f;
    }
    const Vec3 forward = offset / distance;
    Vec3 right = cross(forward, c.up);
    if (lengthSquared(right) < 1e-12f)
        right = cross(forward, std::fabs(forward.y) < 0.9f ? Vec3(0, 1, 0) : Vec3(1, 0, 0));
    right = normalize(right);
    return {forward, right, cross(right, forward), distance};
}

// Rodrigues' rotation of v about the unit axis k by `angle` radians.
Vec3 rotateAbout(Vec3 v, Vec3 k, float angle) {
    const float c = std::cos(angle), s = std::sin(angle);
    return v * c + cross(k, v) * s + k * (dot(k, v) * (1.0f - c));
}

}  // namespace

Camera orbitCamera(const Camera& camera, float dxPixels, float dyPixels, float viewportHeight) {
    const ViewFrame f = viewFrame(camera);
    const float radiansPerPixel =
        kPi / std::max(viewportHeight, 1.0f);  // a full-height drag turns 180 degrees
    Vec3 toEye = camera.position - camera.lookAt;
    if (!(length(toEye) > 0.0f)) toEye = -f.forward;
    toEye = rotateAbout(toEye, Vec3(0.0f, 1.0f, 0.0f), -dxPixels * radiansPerPixel);
    const Vec3 right = rotateAbout(f.right, Vec3(0.0f, 1.0f, 0.0f), -dxPixels * radiansPerPixel);
    // Tilt, clamped to stay 1 degree away from straight up or down.
    const float elevation = std::asin(std::clamp(toEye.y / length(toEye), -1.0f, 1.0f));
    const float limit = 0.5f * kPi - kPi / 180.0f;
    const float target = std::clamp(elevation + dyPixels * radiansPerPixel, -limit, limit);
    toEye = rotateAbout(toEye, right, -(target - elevation));
    Camera out = camera;
    out.position = camera.lookAt + toEye;
    out.up = Vec3(0.0f, 1.0f, 0.0f);
    return out;
}

Camera panCamera(const Camera& camera, float dxPixels, float dyPixels, float viewportHeight) {
    const ViewFrame f = viewFrame(camera);
    // World units per pixel at the look-at distance.
    const float fov = std::clamp(camera.verticalFovDegrees, 1e-3f, 179.0f) * kPi / 180.0f;
    const float scale = 2.0f * f.distance * std::tan(0.5f * fov) / std::max(viewportHeight, 1.0f);
    const Vec3 move = f.right * (-dxPixels * scale) + f.up * (dyPixels * scale);
    Camera out = camera;
    out.position = camera.position + move;
    out.lookAt = camera.lookAt + move;
    return out;
}

Camera dollyCamera(const Camera& camera, float wheelSteps) {
    const ViewFrame f = viewFrame(camera);
    const float distance = std::max(f.distance * std::pow(0.85f, wheelSteps), 1e-6f);
    Camera out = camera;
    out.position = camera.lookAt - f.forward * distance;
    return out;
}

Camera flyCamera(const Camera& camera, float forward, float right, float up, float seconds, float speed) {
    const ViewFrame f = viewFrame(camera);
    const Vec3 move =
        (f.forward * forward + f.right * right + Vec3(0.0f, 1.0f, 0.0f) * up) * (speed * seconds);
    Camera out = camera;
    out.position = camera.position + move;
    out.lookAt = camera.lookAt + move;
    return out;
}

float flySpeedFor(const Scene& scene) {
    Vec3 lo, hi;
    scene.worldBounds(lo, hi);
    const float size = length(hi - lo);
    return std::isfinite(size) && size > 0.0f ? size / 4.0f : 1.0f;
}

}  // namespace pt::editor
