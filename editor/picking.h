#pragma once
// Picking: what is under a point of the viewport, found by tracing one camera ray through the
// backend's own BVH (so it agrees with what is drawn, hidden objects included).
#include <cstdint>

#include "render/backend/backend.h"

namespace pt::editor {

struct PickResult {
    int32_t instance = -1;       // Scene::instances index; -1 when nothing was hit
    int32_t object = -1;         // that instance's SceneObject, or -1
    float distance = 0.0f;       // along the ray, world units
    float focusDistance = 0.0f;  // along the camera's view direction (Camera::focusDistance's measure)
    bool hit() const { return instance >= 0; }
};

// The camera ray through image point (px, py) in pixels of a width x height image (y grows
// down), through the centre of the lens.
Ray viewportRay(const Camera& camera, uint32_t width, uint32_t height, float px, float py);

// `backend` must be synced with `scene`.
PickResult pick(Backend& backend, const Scene& scene, float px, float py);

}  // namespace pt::editor
