#include "editor/picking.h"

#include <cmath>

#include "render/integrator/camera.h"

namespace pt::editor {

Ray viewportRay(const Camera& camera, uint32_t width, uint32_t height, float px, float py) {
    const float x = std::floor(px), y = std::floor(py);
    Camera pinhole = camera;
    pinhole.apertureRadius = 0.0f;  // the lens centre: picking must not depend on depth of field
    const RenderCamera centre = makeRenderCamera(pinhole, width, height);
    return generateCameraRay(centre, width, height, uint32_t(std::fmax(x, 0.0f)),
                             uint32_t(std::fmax(y, 0.0f)), Vec2(px - x, py - y), Vec2(0.5f, 0.5f));
}

PickResult pick(Backend& backend, const Scene& scene, float px, float py) {
    PickResult result;
    const uint32_t width = backend.width(), height = backend.height();
    if (width == 0 || height == 0 || px < 0.0f || py < 0.0f || px >= float(width) || py >= float(height))
        return result;
    const Ray ray = viewportRay(scene.camera, width, height, px, py);
    std::vector<Hit> hits;
    backend.traceRays({ray}, false, 1, &hits);
    if (hits.empty() || !hits[0].valid()) return result;
    result.instance = backend.sceneInstance(hits[0].instance);
    if (result.instance >= 0 && size_t(result.instance) < scene.instances.size())
        result.object = scene.instances[size_t(result.instance)].object;
    result.distance = hits[0].t * length(ray.direction);
    const RenderCamera rc = makeRenderCamera(scene.camera, width, height);
    result.focusDistance = result.distance * std::fabs(dot(normalize(ray.direction), rc.forward));
    return result;
}

}  // namespace pt::editor
