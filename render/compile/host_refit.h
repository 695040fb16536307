#pragma once
// Refitting BLASes on the host: the CPU backend's answer to moved vertices (morph weights, a
// sculpt, skinning) and to a moved instance of the merged BLAS, where the CUDA backend refits on
// the device. A refit keeps the tree and recomputes its boxes; the caller compares the SAH cost
// with the one the tree had as built and rebuilds past a threshold (DESIGN: refit or rebuild).
#include <optional>
#include <vector>

#include "render/compile/compile_scene.h"
#include "render/scene/scene_changes.h"

namespace pt {

// Recomputes every box of BLAS `blas` from its primitives as `compiled` holds them now. Nodes
// are stored parents before children (binned_sah_builder.cpp), so one sweep from the last node
// back to the root sees every child before its parent.
void refitBlasOnHost(CompiledScene& compiled, uint32_t blas);

// sahCost() of BLAS `blas` as it stands.
float blasSahCost(const CompiledScene& compiled, uint32_t blas);

// Copies into `compiled` the vertices (positions, normals, tangents) and spheres of the meshes
// whose positions moved, among those `touched` names, and returns those meshes; nothing where
// a mesh changed size or kind or a mesh was added or removed (a topology edit: compile again).
// Mesh i owns BLAS i.
std::optional<std::vector<uint32_t>> copyMovedMeshes(const Scene& scene, const TouchedIds& touched,
                                                     CompiledScene& compiled);

}  // namespace pt
