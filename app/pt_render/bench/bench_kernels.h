#pragma once
// The kernel variants of a GPU backend (Backend::kernelFigures): for each, the features it is
// compiled for and, per kernel, registers, local memory (stack and spills) and the instruction
// count of its machine code, read from this executable with cuobjdump.
#include "pt_render/bench/bench_report.h"
#include "render/backend/backend.h"

namespace pt::cli {

// Adds a "kernels" section to the report; nothing where the backend compiles no variants.
void benchKernelVariants(const Backend& backend, BenchReport& report);

}  // namespace pt::cli
