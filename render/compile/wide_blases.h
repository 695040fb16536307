#pragma once
// The CPU backend's 4-wide BLASes (issue 21): every BLAS of a compiled scene collapsed from its
// binary tree into CompiledScene::blasWideNodes (render/bvh/wide_bvh.h), which the shared
// traversal walks on the host where they exist (blas_traversal.h). The binary nodes stay the
// source: a host refit refreshes the wide boxes from them.
#include <cstdint>

#include "render/compile/compile_scene.h"

namespace pt {

// Fills blasWideNodes, blasWideRoots and wideSourceNodes from the binary BLASes.
void buildWideBlases(CompiledScene& compiled);

// After refitBlasOnHost(compiled, blas): its wide boxes from its binary ones. Nothing where
// the scene has no wide BLASes.
void refreshWideBlas(CompiledScene& compiled, uint32_t blas);

}  // namespace pt
