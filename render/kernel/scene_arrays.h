// The arrays of a RenderScene, listed once (Cycles' kernel/data_arrays.h is the model). Each
// place that holds or copies every array (RenderScene's spans, CompiledScene's vectors and its
// view(), the CUDA backend's device buffers, their view and their memory table) defines the
// entry macros, includes this file, and so cannot miss one; the file undefines them again.
//
//   PT_SCENE_ARRAY(Type, name, label)
//       an array CompiledScene holds as std::vector<Type> name
//   PT_SCENE_LIGHT_ARRAY(Type, name, compiledMember, label)
//       an array of the light table or the environment's distribution, which CompiledScene
//       holds as compiledMember; defaults to PT_SCENE_ARRAY(Type, name, label)
//
// `label` names the array in `pt-render bench`'s device memory table.
// No include guard: it is meant to be included more than once.

#ifndef PT_SCENE_ARRAY
#error "define PT_SCENE_ARRAY(Type, name, label) before including scene_arrays.h"
#endif
#ifndef PT_SCENE_LIGHT_ARRAY
#define PT_SCENE_LIGHT_ARRAY(Type, name, compiledMember, label) PT_SCENE_ARRAY(Type, name, label)
#endif

// Geometry, all meshes concatenated.
PT_SCENE_ARRAY(Vec3, positions, "positions")
PT_SCENE_ARRAY(Vec3, normals, "normals")    // parallel to positions where a mesh has them
PT_SCENE_ARRAY(Vec2, uvs, "uvs")            // parallel to positions where a mesh has them
PT_SCENE_ARRAY(Vec4, tangents, "tangents")  // parallel to positions, or empty when no mesh has any
PT_SCENE_ARRAY(TriangleIndices, triangles, "triangles")
PT_SCENE_ARRAY(Vec4, spheres, "spheres")  // xyz center, w radius (object space)
// Parallel to triangles: each one's mesh slot.
PT_SCENE_ARRAY(uint32_t, triangleSlots, "triangle material slots")
PT_SCENE_ARRAY(uint32_t, sphereSlots, "sphere material slots")  // parallel to spheres

// Two-level BVH.
PT_SCENE_ARRAY(BlasRef, blases, "BLAS refs")
PT_SCENE_ARRAY(BvhNode, blasNodes, "BLAS nodes")
PT_SCENE_ARRAY(uint32_t, blasPrimIndices, "BLAS primitive indices")
// The CPU's 8-wide form of the BLASes (render/bvh/wide_bvh.h; IntegratorToggles::wideBvh): each
// BLAS's root node in blasWideNodes, or none (empty) where the binary nodes are walked, as
// on the GPU, which never allocates them.
PT_SCENE_ARRAY(WideBvhNode, blasWideNodes, "BLAS wide nodes (CPU)")
PT_SCENE_ARRAY(uint32_t, blasWideRoots, "BLAS wide roots (CPU)")
// The leaves of triangle BLASes' wide forms, four triangles a block (render/kernel/triangle_block.h):
// a wide leaf of a triangle BLAS indexes its first block here (its blocks are consecutive),
// where a sphere BLAS's indexes blasPrimIndices. Empty without the wide forms.
PT_SCENE_ARRAY(TriangleBlock, blasTriangleBlocks, "BLAS triangle blocks (CPU)")
// The CUDA traversal's compressed 8-wide form of the BLASes (render/bvh/compressed_wide_bvh.h;
// IntegratorToggles::wideBvh): each BLAS's root node in blasCompressedNodes, or
// kNoCompressedRoot where its binary nodes are walked (a BLAS rebuilt on the GPU); empty where
// no BLAS has one. Leaves index blasCompressedPrims, whose entries are mesh-local primitives,
// and, for triangle BLASes, blasCompressedTriangles in parallel: the same triangles with their
// corners (leaf_triangle.h), gathered again when a refit moves them.
PT_SCENE_ARRAY(CompressedWideNode, blasCompressedNodes, "BLAS compressed 8-wide nodes")
PT_SCENE_ARRAY(uint32_t, blasCompressedPrims, "BLAS compressed primitive indices")
PT_SCENE_ARRAY(LeafTriangle, blasCompressedTriangles, "BLAS compressed leaf triangles")
PT_SCENE_ARRAY(uint32_t, blasCompressedRoots, "BLAS compressed roots")
PT_SCENE_ARRAY(RenderInstance, instances, "instances")
PT_SCENE_ARRAY(BvhNode, tlasNodes, "TLAS nodes")
// The CPU's 8-wide form of the TLAS, made beside the 8-wide BLASes (empty without them, and on
// the GPU): its leaves index tlasInstanceIndices as the binary ones do.
PT_SCENE_ARRAY(WideBvhNode, tlasWideNodes, "TLAS wide nodes (CPU)")
// TLAS leaf entries are instance indices, and instances.count for the merged BLAS: small
// instances' triangles copied into world space (merged_geometry.h), traced with no instance
// transform; each of its hits maps back through mergedTriangles.
PT_SCENE_ARRAY(uint32_t, tlasInstanceIndices, "TLAS instance indices")
PT_SCENE_ARRAY(MergedTriangle, mergedTriangles, "merged triangles (hit map)")

// Shading.
PT_SCENE_ARRAY(uint32_t, instanceMaterials, "instance materials")
PT_SCENE_ARRAY(Material, materials, "materials")
PT_SCENE_ARRAY(TextureView, textures, "texture views")
PT_SCENE_ARRAY(uint8_t, texels8, "texels (8-bit)")
PT_SCENE_ARRAY(float, texelsF, "texels (float)")

// Lights: one alias table over every light NEE samples.
PT_SCENE_LIGHT_ARRAY(Emitter, emitters, emitters.emitters, "emitters")
PT_SCENE_LIGHT_ARRAY(AliasEntry, emitterAlias, emitters.alias, "emitter alias table")
PT_SCENE_ARRAY(PunctualLight, punctualLights, "punctual lights")
// The environment image's sampling distribution (render/lights/environment_sampling.h).
// Density on the unit square, distHeight x distWidth:
PT_SCENE_LIGHT_ARRAY(float, envPdf, environmentDistribution.pdf, "environment pdf")
// distHeight + 1, over rows:
PT_SCENE_LIGHT_ARRAY(float, envMarginalCdf, environmentDistribution.marginalCdf, "environment marginal cdf")
// distHeight x (distWidth + 1), within each row:
PT_SCENE_LIGHT_ARRAY(float, envConditionalCdf, environmentDistribution.conditionalCdf,
                     "environment conditional cdf")

#undef PT_SCENE_ARRAY
#undef PT_SCENE_LIGHT_ARRAY
