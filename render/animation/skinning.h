#pragma once
// Skins (glTF 2.0 section 3.7.3) on the host: the joint matrices of a pose, the checks a
// file's weights get, and a skinned mesh's vertices from its bind pose (skin_vertex.h per
// vertex, on all cores).
#include <cstdint>
#include <vector>

#include "render/animation/keyframes.h"
#include "render/animation/skin_vertex.h"

namespace pt {

struct Skin {
    std::vector<uint32_t> joints;              // node indices
    std::vector<Affine3> inverseBindMatrices;  // one per joint (the identity where the file gives none)
};

// Global transforms of nodes from their poses and parents (-1: a root). Throws
// std::invalid_argument for a parent index out of range or a cycle.
std::vector<Affine3> globalTransforms(const std::vector<int32_t>& parents,
                                      const std::vector<NodePose>& poses);

// Joint j's matrix: inverse(meshNodeGlobal) x global(joint j) x inverseBind j. The skinned
// vertices are then in the mesh node's space, which its instance transform takes to the world,
// so the mesh node's own transform does not move them (glTF: only the joints do).
std::vector<Affine3> jointMatrices(const Skin& skin, const std::vector<Affine3>& nodeGlobals,
                                   const Affine3& meshNodeGlobal);

// What normalizeInfluences found.
struct InfluenceCheck {
    uint32_t renormalized = 0;  // vertices whose weights did not sum to 1 (within 1e-3)
    uint32_t unweighted = 0;    // vertices with no weight at all: left unskinned
};

// Checks every vertex's influences against a skin of `jointCount` joints and scales weights
// that do not sum to one to do so. Throws std::invalid_argument naming the vertex where a
// weight is negative or not finite, or a weighted joint index is past the skin's joints (an
// unweighted one may be anything, as glTF allows).
InfluenceCheck normalizeInfluences(std::vector<JointInfluences>& influences, uint32_t jointCount);

// The skinned positions, normals and tangents of a mesh's bind-pose vertices (normals and
// tangents may be empty: their outputs are then left as they are). Outputs are resized to
// the inputs.
struct BindPose {
    const std::vector<Vec3>& positions;
    const std::vector<Vec3>& normals;
    const std::vector<Vec4>& tangents;
    const std::vector<JointInfluences>& influences;  // parallel to positions, normalised
};
void skinVertices(const std::vector<Affine3>& jointMatrices, const BindPose& bind,
                  std::vector<Vec3>& positions, std::vector<Vec3>& normals, std::vector<Vec4>& tangents);

}  // namespace pt
