#pragma once
// A glTF mesh as one Scene Mesh: every primitive's triangles appended, one slot per imported
// primitive (skipped primitives get none), the glTF material of each slot remembered for
// the placements. Built once per glTF mesh however many nodes use it. Internal to pt_assets.
#include <optional>
#include <string>

#include "assets/gltf_context.h"

namespace pt {

// `element` names the referrer for messages (e.g. "nodes[4]"). nullopt: the mesh has no
// triangles to draw (a warning says so) and is not placed.
const std::optional<ImportedMesh>& importGltfMesh(GltfContext& ctx, int mesh,
                                                  const std::string& element);

}  // namespace pt
