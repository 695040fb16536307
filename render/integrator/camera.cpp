#include "render/integrator/camera.h"

#include <cmath>

#include "render/scene/scene.h"

namespace pt {

RenderCamera makeRenderCamera(const Camera& camera, uint32_t width, uint32_t height) {
    RenderCamera rc;
    rc.origin = camera.position;
    Vec3 forward = camera.lookAt - camera.position;
    if (lengthSquared(forward) == 0.0f) forward = {0.0f, 0.0f, -1.0f};
    rc.forward = normalize(forward);
    Vec3 right = cross(rc.forward, camera.up);
    if (lengthSquared(right) < 1e-12f) {  // up parallel to the view: pick any perpendicular
        right = cross(rc.forward, std::fabs(rc.forward.y) < 0.9f ? Vec3{0, 1, 0} : Vec3{1, 0, 0});
    }
    right = normalize(right);
    const Vec3 up = cross(right, rc.forward);
    const float fov = std::fmin(std::fmax(camera.verticalFovDegrees, 1e-3f), 179.0f);
    const float tanHalf = std::tan(0.5f * fov * kPi / 180.0f);
    const float aspect = float(width) / float(height == 0 ? 1 : height);
    rc.right = right * (tanHalf * aspect);
    rc.up = up * tanHalf;
    rc.lensRadius = std::fmax(camera.apertureRadius, 0.0f);
    const float lookDistance = length(camera.lookAt - camera.position);
    rc.focusDistance = camera.focusDistance > 0.0f ? camera.focusDistance
                       : lookDistance > 0.0f       ? lookDistance
                                                   : 1.0f;
    return rc;
}

Vec2 projectToImage(const RenderCamera& camera, Vec3 p, uint32_t width, uint32_t height, float* depth) {
    const Vec3 d = p - camera.origin;
    const float z = dot(d, camera.forward) / length(camera.forward);
    if (depth) *depth = z;
    // generateCameraRay's direction is forward + right ndcX + up ndcY: scaled to reach d.
    const float along = dot(d, camera.forward) / lengthSquared(camera.forward);
    const float ndcX = dot(d, camera.right) / (lengthSquared(camera.right) * along);
    const float ndcY = dot(d, camera.up) / (lengthSquared(camera.up) * along);
    return {0.5f * (ndcX + 1.0f) * float(width), 0.5f * (1.0f - ndcY) * float(height)};
}

}  // namespace pt
