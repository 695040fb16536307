#pragma once
// The CPU backend's 8-wide BLASes (issue 21): every BLAS of a compiled scene collapsed from its
// binary tree into CompiledScene::blasWideNodes (render/bvh/wide_bvh.h), which the shared
// traversal walks on the host where they exist (blas_traversal.h), with the leaves of triangle
// BLASes as blocks of four triangles (CompiledScene::blasTriangleBlocks). The binary nodes and
// the positions stay the source: a host refit refreshes the wide boxes and the blocks.
#include <cstdint>
#include <utility>

#include "render/compile/compile_scene.h"

namespace pt {

// Fills blasWideNodes, blasWideRoots, wideSourceNodes, blasTriangleBlocks and
// blasFirstTriangleBlock from the binary BLASes.
void buildWideBlases(CompiledScene& compiled);

// Fills blasCompressedNodes, blasCompressedPrims, blasCompressedTriangles, blasCompressedRoots
// and compressedSourceNodes (the CUDA traversal's 8-wide form, compressed_wide_bvh.h). Child
// and primitive bases are made absolute: the walk reads the whole scene's arrays.
void buildCompressedBlases(CompiledScene& compiled);

// Compressed nodes [first, end) of BLAS `blas` in blasCompressedNodes.
std::pair<uint32_t, uint32_t> compressedNodeRange(const CompiledScene& compiled, uint32_t blas);
// Its entries [first, end) in blasCompressedPrims and blasCompressedTriangles.
std::pair<uint32_t, uint32_t> compressedPrimRange(const CompiledScene& compiled, uint32_t blas);

// After refitBlasOnHost(compiled, blas): its wide boxes (both forms, where the scene has them)
// from its binary ones, and its triangle blocks and compressed leaf triangles from the positions.
void refreshWideBlas(CompiledScene& compiled, uint32_t blas);

}  // namespace pt
