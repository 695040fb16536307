#pragma once
// Vertex normals for importers whose files leave them out. Area-weighted: a vertex's normal
// is the normalized sum of the un-normalized cross products of the triangles that use it, so
// large triangles count more than slivers and a vertex used by one triangle (unshared, as for
// flat shading) gets exactly that triangle's normal. Internal to pt_assets.
#include <cstdint>
#include <vector>

#include "render/math/vec.h"

namespace pt {

// Fills normals[v] for every v with regenerate[v] set, from the triangles that use it.
// Vertices whose triangles all have zero area get +Z, so every normal is a finite unit
// vector. `normals` and `regenerate` have one entry per position; indices must be
// < positions.size(). With `groups` (one id per vertex, ids < positions.size()), vertices of
// one group pool their triangles and share one normal: OBJ vertices split only by a UV seam
// stay smooth across it.
void generateAreaWeightedNormals(const std::vector<Vec3>& positions, const std::vector<uint32_t>& indices,
                                 const std::vector<bool>& regenerate, std::vector<Vec3>& normals,
                                 const std::vector<uint32_t>* groups = nullptr);

}  // namespace pt
