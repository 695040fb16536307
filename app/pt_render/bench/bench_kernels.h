#pragma once
// The kernel variants of the CUDA backend (render/backend/cuda/kernel_variants.h): for each,
// the features it is compiled for and, per kernel, registers, local memory (stack and spills)
// and the instruction count of its machine code, read from the compiled code.
#include "pt_render/bench/bench_report.h"

namespace pt::cli {

// Adds a "kernels" section to the report; nothing without a CUDA build.
void benchKernelVariants(BenchReport& report);

}  // namespace pt::cli
