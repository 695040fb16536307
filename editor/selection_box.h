#pragma once
// The selection as the viewport outlines it: the world bounding box of the selected object (all
// its instances) or instance, its 12 edges projected into the render's pixels through the
// scene's camera. Edges with an end behind the camera are left out (their projection would
// fold through infinity).
#include <cstdint>
#include <vector>

#include "render/scene/scene.h"

namespace pt::editor {

struct ImageSegment {
    Vec2 a, b;  // render pixels, y down
};

// `object` >= 0: that SceneObject's instances; else `instance` (a Scene::instances index); none
// where neither names geometry.
std::vector<ImageSegment> selectionBoxInImage(const Scene& scene, int32_t object, int32_t instance,
                                              uint32_t width, uint32_t height);

}  // namespace pt::editor
