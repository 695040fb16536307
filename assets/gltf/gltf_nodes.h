#pragma once
// The node hierarchy of the glTF scene to show: the default scene, else scene 0, else every
// root node (a node no other node lists as a child). World transforms compose TRS or matrix
// down the tree; a node reached twice (a cycle, or two parents) is an InputError, and the
// walk uses an explicit stack so a deep hierarchy cannot overflow ours. Internal to pt_assets.
#include <optional>
#include <vector>

#include "assets/gltf/gltf_context.h"
#include "render/math/affine.h"

namespace pt {

struct GltfNodeVisit {
    int node = 0;
    Affine3 world;  // node to file root
};

// The rotation of quaternion (x, y, z, w), renormalised (exporters round them); an InputError
// naming `element` when it has no length.
Affine3 gltfRotation(const GltfContext& ctx, double x, double y, double z, double w,
                     const std::string& element);

// Pre-order, children in file order.
std::vector<GltfNodeVisit> walkGltfScene(const GltfContext& ctx);

// The first perspective camera in `visits`: its world position, view along its -Z, up along
// its +Y, and yfov. Orthographic cameras get a warning and are skipped.
std::optional<Camera> gltfCamera(const GltfContext& ctx, const std::vector<GltfNodeVisit>& visits);

}  // namespace pt
