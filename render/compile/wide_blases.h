#pragma once
// The CPU backend's 8-wide BLASes (issue 21): every BLAS of a compiled scene collapsed from its
// binary tree into CompiledScene::blasWideNodes (render/bvh/wide_bvh.h), which the shared
// traversal walks on the host where they exist (blas_traversal.h), with the leaves of triangle
// BLASes as blocks of four triangles (CompiledScene::blasTriangleBlocks). The binary nodes and
// the positions stay the source: a host refit refreshes the wide boxes and the blocks.
#include <cstdint>
#include <utility>
#include <vector>

#include "render/bvh/compressed_wide_bvh.h"
#include "render/compile/compile_scene.h"

namespace pt {

// Fills blasWideNodes, blasWideRoots, wideSourceNodes, blasTriangleBlocks and
// blasFirstTriangleBlock from the binary BLASes.
void buildWideBlases(CompiledScene& compiled);

// Every BLAS's compressed 8-wide form (the CUDA traversal's, compressed_wide_bvh.h), one after
// another in shared arrays, child and primitive bases counting from the arrays' starts. A BLAS
// `skip` marks (its binary tree is not the compiled one: a deferred mesh's stand-in leaf holds
// more primitives than a compressed leaf can) gets an empty tree, which keeps the ranges in
// order. Throws std::invalid_argument where the entries would pass kCompressedPrimitiveLimit.
struct CompressedBlases {
    CompressedWideBvh forms;
    std::vector<uint32_t> roots;  // per BLAS: its root in forms.nodes, the first node it fills
    // BLAS `blas`'s nodes [first, end) and entries [first, end) in `forms`.
    std::pair<uint32_t, uint32_t> nodeRange(uint32_t blas) const;
    std::pair<uint32_t, uint32_t> primRange(uint32_t blas) const;
};
CompressedBlases compressBlases(const CompiledScene& compiled, const std::vector<uint8_t>& skip);

// Fills blasCompressedNodes, blasCompressedPrims, blasCompressedTriangles, blasCompressedRoots
// and compressedSourceNodes from compressBlases, the deferred BLASes skipped.
void buildCompressedBlases(CompiledScene& compiled);

// Compressed nodes [first, end) of BLAS `blas` in blasCompressedNodes.
std::pair<uint32_t, uint32_t> compressedNodeRange(const CompiledScene& compiled, uint32_t blas);
// Its entries [first, end) in blasCompressedPrims and blasCompressedTriangles.
std::pair<uint32_t, uint32_t> compressedPrimRange(const CompiledScene& compiled, uint32_t blas);

// After refitBlasOnHost(compiled, blas): its wide boxes (both forms, where the scene has them)
// from its binary ones, and its triangle blocks and compressed leaf triangles from the positions.
void refreshWideBlas(CompiledScene& compiled, uint32_t blas);

}  // namespace pt
