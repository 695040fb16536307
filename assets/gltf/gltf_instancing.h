#pragma once
// EXT_mesh_gpu_instancing: a node whose mesh is drawn at many transforms (forests, crowds, bolts;
// gltfpack and Blender write it). Each instance's TRANSLATION, ROTATION and SCALE compose in the
// node's local space, under the node's own transform; the mesh is drawn only as the instances.
// Internal to pt_assets.
#include <vector>

#include "assets/gltf/gltf_context.h"
#include "render/math/affine.h"

namespace pt {

// The instances' local transforms of `node`, in order; empty when the node is not instanced.
// Attribute accessors are bounds-checked like every accessor and must agree on the count;
// rotations may be normalized integers, as the extension allows, and are renormalised.
std::vector<Affine3> gltfInstanceTransforms(const GltfContext& ctx, int node);

}  // namespace pt
