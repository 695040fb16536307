#pragma once
// Four triangles of a CPU BVH leaf stored side by side (issue 21), so one SSE pass runs the
// watertight test (render/bvh/triangle_lanes.inl) on all four, and one AVX2 pass on two
// consecutive blocks: their corners as structure of arrays, and which mesh-local primitive
// each lane is. A leaf of fewer triangles
// repeats its first in the lanes it leaves unused: a repeated triangle gives the same hit at
// the same t, which the walk's tie rule (lower primitive wins) turns into the same answer, so
// no lane mask is needed. Copies of the mesh's positions: a refit refreshes them
// (wide_blases.h). 160 bytes.
#include <cstdint>

namespace pt {

struct alignas(16) TriangleBlock {
    static constexpr uint32_t kWidth = 4;

    float corner[3][3][kWidth];  // [corner p0/p1/p2][axis x/y/z][lane]
    uint32_t primitive[kWidth];  // mesh-local primitive index, as BlasRef leaves hold them
};
static_assert(sizeof(TriangleBlock) == 160, "TriangleBlock: 160 bytes");

}  // namespace pt
