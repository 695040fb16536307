#pragma once
// Morph targets (glTF 2.0 section 3.7.2.2) on the host Scene: a Mesh with targets keeps its
// undeformed vertices (basePositions, baseNormals) and per-target deltas, and its positions
// and normals hold the deformation for the current weights. Editing a weight changes vertex
// positions only, so the backend refits that mesh's BLAS (SceneChanges for vertex edits).
#include "render/scene/scene.h"

namespace pt {

// Sets mesh.positions = basePositions + sum_i morphWeights[i] * positionDeltas[i], and the
// normals likewise, renormalized (a zero or non-finite sum keeps the base normal). Weights are
// used as given: glTF allows any real value. A zero weight adds nothing, so all-zero weights
// restore the base vertices bit for bit. A mesh without targets is left untouched.
// Throws std::invalid_argument when morphWeights or a target's deltas do not match the
// mesh (a broken invariant: importers and the editor keep them in step).
void applyMorphWeights(Mesh& mesh);

bool hasMorphTargets(const Mesh& mesh);

}  // namespace pt
