#pragma once
// BVH build figures for `pt-render bench`: the CPU binned SAH builder and, with the CUDA
// backend, the GPU LBVH builder on the scene's largest mesh (time, Mtris/s, SAH cost relative
// to the binned SAH build), BLAS refit on the GPU, and the TLAS build on each.
#include <cstdint>

#include "bench_report.h"
#include "render/scene/compile_scene.h"

namespace pt::cli {

void benchBvhBuilds(const CompiledScene& scene, bool gpu, uint32_t runs, BenchReport& report);

}  // namespace pt::cli
