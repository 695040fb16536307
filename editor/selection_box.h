#pragma once
// The selection as the viewport outlines it: the world bounding box of the selected object (all
// its instances) or instance, its 12 edges projected into the render's pixels through the
// scene's camera. Edges with an end behind the camera are left out (their projection would
// fold through infinity). The box walks the meshes' vertices, so the window keeps it until the
// selection or the document changes; the projection is redone each frame.
#include <cstdint>
#include <optional>
#include <vector>

#include "render/scene/scene.h"

namespace pt::editor {

struct WorldBox {
    Vec3 lo, hi;
};

struct ImageSegment {
    Vec2 a, b;  // render pixels, y down
};

// `object` >= 0: that SceneObject's instances; else `instance` (a Scene::instances index); none
// where neither names geometry.
std::optional<WorldBox> selectionBounds(const Scene& scene, int32_t object, int32_t instance);
std::vector<ImageSegment> boxInImage(const WorldBox& box, const Camera& camera, uint32_t width,
                                     uint32_t height);

}  // namespace pt::editor
