#pragma once
// A glTF mesh as one Scene Mesh: every primitive's triangles appended, one slot per imported
// primitive (skipped primitives get none), the glTF material of each slot remembered for
// the placements, morph targets merged like the vertices they move and applied with the
// file's default weights. Built once per glTF mesh however many nodes use it. Internal to pt_assets.
#include <optional>
#include <string>

#include "assets/gltf/gltf_context.h"

namespace pt {

// `element` names the referrer for messages (e.g. "nodes[4]"). nullopt: the mesh has no
// triangles to draw (a warning says so) and is not placed.
const std::optional<ImportedMesh>& importGltfMesh(GltfContext& ctx, int mesh, const std::string& element);

// Poses the mesh for glTF node `node`, which uses it: its morph weights are the node's
// `weights`, else the glTF mesh's. A Scene mesh is shared by every node that uses it, so the
// first node (`firstUse`, in scene order) sets the mesh's default pose; a later node that asks
// for another gets a warning naming it. InputError when the node's weights do not match the
// mesh's target count.
void poseGltfMeshForNode(GltfContext& ctx, int node, const ImportedMesh& mesh, bool firstUse);

}  // namespace pt
