#pragma once
// Merging small instances into one world-space BLAS.
//
// A two-level BVH pays at every instance a ray enters: a trip from the TLAS leaf into the
// instance (its record, the ray taken into object space) and a walk down a BLAS of its own,
// and where instance boxes overlap (walls around the objects of a room; the 37 parts of a
// glTF model, each a single-use mesh) a ray enters several. Copying the triangles of such
// instances into world space and building one BVH over them turns those walks into one, with
// the SAH free to split across what were instance boundaries. pbrt-v4 and Cycles do the same
// for single-use meshes (pbrt flattens non-instanced shapes into its top-level aggregate;
// Cycles' BVH2 merges object BVHs unless an object is instanced).
//
// Which instances merge: triangle meshes without morph targets (their vertices move under
// edits), of at most kMaxMergedMeshTriangles, used once or copied at most kMaxCopiedTriangles
// times over, placed near the origin for their size (merged_geometry.cpp says why); up to
// kMaxMergedTriangles copies in all; nothing when fewer than two instances would. The merged instances stay
// in the instance list (their materials, emitters, picking and AOV ids are theirs); only the TLAS skips them,
// holding one entry for the merged BLAS instead. A hit in it reports the instance and mesh-local triangle it
// came from, so shading never knows. Edits keep the choice: a moved instance's copies are rewritten (and the
// merged BLAS refitted), a hidden one's collapse to a point no ray hits.
#include <cstdint>
#include <vector>

namespace pt {

struct CompiledScene;
struct Scene;

constexpr uint32_t kMaxMergedMeshTriangles = 1u << 16;
constexpr uint32_t kMaxMergedTriangles = 1u << 21;
constexpr uint32_t kMaxCopiedTriangles = 1u << 16;

// One merged instance's copies in the merged arrays.
struct MergedPiece {
    uint32_t sceneInstance = 0;  // Scene::instances index
    uint32_t mesh = 0;
    uint32_t firstVertex = 0;    // into CompiledScene::positions
    uint32_t firstTriangle = 0;  // merged-BLAS-local
    uint32_t vertexCount = 0;
};

struct MergedGeometry {
    uint32_t blas = 0xffffffffu;  // CompiledScene::blases index (after the meshes'), or none
    std::vector<MergedPiece> pieces;
    std::vector<bool> sceneInstanceMerged;  // per Scene instance

    bool active() const { return !pieces.empty(); }
};

// Chooses the instances to merge and appends the merged BLAS's triangles (its vertices left
// for bakeMergedGeometry). After flattenGeometry, before compileInstances. The pieces are in
// instance order: a tie in t inside the merged BLAS goes to its lower primitive, and so to
// the lower instance, as between instances (tlas_traversal.h).
void planMergedGeometry(const Scene& scene, CompiledScene& out);

// Whether the plan still fits the scene: the same instance list, each piece's instance still
// placing a mesh of the same size. Deleting, adding or re-meshing instances needs a new plan
// (a full compile).
bool mergedPlanHolds(const Scene& scene, const CompiledScene& out);

// Writes the merged vertices (world positions of the pieces' current instances; a hidden
// instance's collapse to one point) and the hit map (CompiledScene::mergedTriangles) from the
// compiled instance list. Returns whether any vertex changed. Part of compileInstances.
// Throws std::invalid_argument where !mergedPlanHolds.
bool bakeMergedGeometry(const Scene& scene, CompiledScene& out);

}  // namespace pt
