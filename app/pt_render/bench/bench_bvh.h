#pragma once
// BVH build figures for `pt-render bench`: the CPU binned SAH builder and, with the CUDA
// backend, the GPU LBVH builder on the scene's largest mesh (time, Mtris/s, SAH cost relative
// to the binned SAH build), BLAS refit on the GPU, and the TLAS build on each.
#include <cstdint>

#include "pt_render/bench/bench_report.h"
#include "render/backend/backend.h"
#include "render/compile/compile_scene.h"

namespace pt::cli {

// The GPU figures come from the backend (Backend::measureDeviceBvh); none where it has no
// device builders.
void benchBvhBuilds(const CompiledScene& scene, Backend& backend, uint32_t runs, BenchReport& report);

}  // namespace pt::cli
