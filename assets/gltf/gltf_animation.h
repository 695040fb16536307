#pragma once
// glTF skins and animations (glTF 2.0 sections 3.7.3 and 3.11) read into an AnimationRig
// (render/animation/rig.h): the node hierarchy with every node's rest pose, the animations'
// samplers and channels, the skins' joints and inverse bind matrices. Which instances and
// meshes the rig moves is added as the nodes are placed (gltf_import.cpp) and instantiated
// (scene_loader.cpp). Internal to pt_assets.
#include <optional>

#include "assets/gltf/gltf_context.h"
#include "render/animation/rig.h"

namespace pt {

// The file's rig; nullopt where it has neither skins nor animations. InputError for what a
// rig cannot be made of (a sampler whose key times do not increase, an inverse bind matrix
// that is not affine, a joint naming a missing node); a warning for channels that cannot be
// honoured (no target node, a path other than translation, rotation, scale or weights, a node
// given as a matrix, weights of a node without morph targets), which are left out.
std::optional<AnimationRig> readGltfRig(const GltfContext& ctx);

// After the meshes are imported: the nodes whose morph weights an animation drives, with the
// Scene mesh each deforms.
void addGltfMorphedNodes(const GltfContext& ctx, AnimationRig& rig);

// The skin of `node` applied to a Scene mesh of its own: checks and normalises the imported
// mesh's influences against the skin (InputError naming the node where they do not fit; one
// warning where weights were renormalised) and returns the rig's record of it. nullopt, with a
// warning, where the mesh has no JOINTS_0/WEIGHTS_0 to skin with.
std::optional<SkinnedMesh> gltfSkinnedMesh(const GltfContext& ctx, const AnimationRig& rig, int node,
                                           const ImportedMesh& imported, uint32_t sceneMesh);

}  // namespace pt
