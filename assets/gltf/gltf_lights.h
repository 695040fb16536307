#pragma once
// KHR_lights_punctual: the lights that nodes of the shown scene carry, placed by the node
// hierarchy (position at the node's origin, shining along its -Z). Internal to pt_assets.
#include <vector>

#include "assets/gltf/gltf_context.h"
#include "assets/gltf/gltf_nodes.h"

namespace pt {

// In file space. InputError for a node naming a light that does not exist, an unknown light
// type, or values outside the extension's ranges (negative intensity, cone angles outside
// 0 <= inner < outer <= pi/2); nodes with a zero scale are skipped with a warning.
std::vector<Light> gltfLights(const GltfContext& ctx, const std::vector<GltfNodeVisit>& visits);

}  // namespace pt
