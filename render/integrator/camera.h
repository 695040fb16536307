#pragma once
// Camera rays: pinhole or thin lens, with a box-filtered jitter inside the pixel.
#include "render/kernel/render_scene.h"
#include "render/math/ray.h"
#include "render/sampling/warp.h"

namespace pt {

struct Camera;  // render/scene/scene.h: the editable form, which per-ray code does not include

// Host: the render form of a Camera for an image of width x height pixels.
RenderCamera makeRenderCamera(const Camera& camera, uint32_t width, uint32_t height);

// Host: where world point `p` lands in the image (pixels, y down), the inverse of a pinhole
// camera ray through the pixel; `depth` receives its distance along the view direction (<= 0:
// behind the camera, where the pixel means nothing).
Vec2 projectToImage(const RenderCamera& camera, Vec3 p, uint32_t width, uint32_t height, float* depth);

// Primary ray through pixel (x, y) with `pixelJitter` in [0,1)^2 inside the pixel and
// `lensSample` in [0,1)^2 on the aperture. The direction is unit length. Image y grows down.
PT_HD Ray generateCameraRay(const RenderCamera& camera, uint32_t width, uint32_t height, uint32_t x,
                            uint32_t y, Vec2 pixelJitter, Vec2 lensSample) {
    const float ndcX = 2.0f * ((float(x) + pixelJitter.x) / float(width)) - 1.0f;
    const float ndcY = 1.0f - 2.0f * ((float(y) + pixelJitter.y) / float(height));
    const Vec3 direction = normalize(camera.forward + camera.right * ndcX + camera.up * ndcY);
    Ray ray;
    if (camera.lensRadius <= 0.0f) {
        ray.origin = camera.origin;
        ray.direction = direction;
        return ray;
    }
    // Thin lens: every ray through the pixel meets at the plane of focus.
    const float tFocus = camera.focusDistance / dot(direction, camera.forward);
    const Vec3 focusPoint = camera.origin + direction * tFocus;
    const Vec2 lens = squareToConcentricDisk(lensSample) * camera.lensRadius;
    const Vec3 rightUnit = normalize(camera.right), upUnit = normalize(camera.up);
    ray.origin = camera.origin + rightUnit * lens.x + upUnit * lens.y;
    ray.direction = normalize(focusPoint - ray.origin);
    return ray;
}

}  // namespace pt
