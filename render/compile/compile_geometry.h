#pragma once
// The geometry half of compileRenderScene: concatenating meshes into global arrays and
// building one BLAS per mesh. BLAS i belongs to Scene::meshes[i].
#include "render/bvh/aabb.h"
#include "render/compile/compile_scene.h"
#include "render/util/large_array.h"

namespace pt {

// Fills positions/normals/uvs/triangles/spheres/slots and one BlasRef per mesh (BVH fields
// left for buildBlases). Throws std::invalid_argument on an index past its mesh's vertices.
void flattenGeometry(const Scene& scene, CompiledScene& out);

// Builds the BLASes (binned SAH, meshes in parallel) and fills the BlasRef BVH fields: one
// per mesh, and the merged BLAS (merged_geometry.h) where there is one. Meshes of at least
// `deferFrom` primitives (0: none) get a stand-in and a CompiledScene::deferredBlases entry.
void buildBlases(CompiledScene& out, const ProgressFn& progress, uint32_t deferFrom = 0);

// The box of primitive p of `blas` as `out` holds it now (what builds and refits start from).
Aabb primitiveBounds(const CompiledScene& out, const BlasRef& blas, uint32_t p);

// primitiveBounds of every primitive of `blas`, in parallel: what a build of it takes (a
// DeferredBlas's caller computes them when it can best afford to).
LargeArray<Aabb> primitiveBoundsOf(const CompiledScene& out, const BlasRef& blas);

// The union of those boxes, in parallel, without storing them: a deferred BLAS's root box.
Aabb unionOfPrimitiveBounds(const CompiledScene& out, const BlasRef& blas);

}  // namespace pt
