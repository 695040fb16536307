#pragma once
// The corners of a compressed BVH's leaf triangles (render/kernel/leaf_triangle.h), gathered from
// a scene's positions: by the host's collapse (render/compile/wide_blases.cpp) and, after a refit
// has moved the positions, by the CUDA backend (render/backend/cuda/compressed_refit.cu).
#include "render/kernel/render_scene.h"

namespace pt {

// Mesh-local primitive `primitive` of `blas` as a leaf triangle. A sphere BLAS's entries keep
// their primitive only: its leaves are tested through the index path.
PT_HD LeafTriangle gatherLeafTriangle(const TriangleIndices* triangles, const Vec3* positions,
                                      const BlasRef& blas, uint32_t primitive) {
    if (blas.kind != GeometryKind::Triangles)
        return makeLeafTriangle(Vec3(0.0f), Vec3(0.0f), Vec3(0.0f), primitive);
    const TriangleIndices t = triangles[blas.primitiveOffset + primitive];
    return makeLeafTriangle(positions[t.v0], positions[t.v1], positions[t.v2], primitive);
}

}  // namespace pt
