#pragma once
// The CPU backend's 4-wide BLASes (issue 21): every BLAS of a compiled scene collapsed from its
// binary tree into CompiledScene::blasWideNodes (render/bvh/wide_bvh.h), which the shared
// traversal walks on the host where they exist (blas_traversal.h). The binary nodes stay the
// source: a host refit refreshes the wide boxes from them.
#include <cstdint>
#include <utility>

#include "render/compile/compile_scene.h"

namespace pt {

// Fills blasWideNodes, blasWideRoots and wideSourceNodes from the binary BLASes.
void buildWideBlases(CompiledScene& compiled);

// Fills blasCompressedNodes, blasCompressedPrims, blasCompressedRoots and
// compressedSourceNodes (the CUDA traversal's 8-wide form, compressed_wide_bvh.h). Child and
// primitive bases are made absolute: the walk reads the whole scene's arrays.
void buildCompressedBlases(CompiledScene& compiled);

// Compressed nodes [first, end) of BLAS `blas` in blasCompressedNodes.
std::pair<uint32_t, uint32_t> compressedNodeRange(const CompiledScene& compiled, uint32_t blas);

// After refitBlasOnHost(compiled, blas): its wide boxes (both forms, where the scene has them)
// from its binary ones.
void refreshWideBlas(CompiledScene& compiled, uint32_t blas);

}  // namespace pt
