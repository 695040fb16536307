#include "editor/selection_box.h"

#include "render/integrator/camera.h"

namespace pt::editor {

std::optional<WorldBox> selectionBounds(const Scene& scene, int32_t object, int32_t instance) {
    WorldBox box{Vec3(kInf), Vec3(-kInf)};
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        const bool selected = object >= 0 ? scene.instances[i].object == object : int32_t(i) == instance;
        Vec3 a, b;
        if (selected && scene.instanceBounds(i, a, b)) {
            box.lo = vmin(box.lo, a);
            box.hi = vmax(box.hi, b);
        }
    }
    if (!(box.lo.x <= box.hi.x)) return std::nullopt;
    return box;
}

std::vector<ImageSegment> boxInImage(const WorldBox& box, const Camera& camera, uint32_t width,
                                     uint32_t height) {
    std::vector<ImageSegment> segments;
    if (width == 0 || height == 0) return segments;
    const RenderCamera render = makeRenderCamera(camera, width, height);
    Vec2 corner[8];
    bool inFront[8];
    for (int c = 0; c < 8; ++c) {
        const Vec3 p{c & 1 ? box.hi.x : box.lo.x, c & 2 ? box.hi.y : box.lo.y, c & 4 ? box.hi.z : box.lo.z};
        float depth = 0.0f;
        corner[c] = projectToImage(render, p, width, height, &depth);
        inFront[c] = depth > 0.0f;
    }
    // The 12 edges join corners that differ in one bit (one axis).
    for (int c = 0; c < 8; ++c) {
        for (const int axis : {1, 2, 4}) {
            const int other = c | axis;
            if (other != c && inFront[c] && inFront[other]) segments.push_back({corner[c], corner[other]});
        }
    }
    return segments;
}

}  // namespace pt::editor
