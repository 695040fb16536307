#pragma once
// Intel Embree 3 as the baseline of `pt-render bench --backend cpu` (issue 21): the bench's
// ray sets traced by Embree over the same triangles and spheres (one Embree scene per BLAS,
// instanced as the TLAS instances them; the merged BLAS as it is; spheres as Embree's point
// spheres), single rays and, for closest hits, its
// 8-ray packets where the CPU runs them natively; our best rate (single rays or packets) over
// Embree's best; the share of
// rays whose hits agree; and Embree's medium-quality build of the largest mesh beside our
// binned SAH build. Built where CMake finds Embree (Debian's libembree-dev: PT_HAVE_EMBREE);
// elsewhere one row says it was left out.
#include <vector>

#include "pt_render/bench/bench_report.h"
#include "render/bvh/hit.h"
#include "render/compile/compile_scene.h"
#include "render/math/ray.h"

namespace pt::cli {

// One ray set as our backend traced it.
struct TracedRaySet {
    const char* name = "";
    const std::vector<Ray>* rays = nullptr;
    bool anyHit = false;
    double mraysPerSecond = 0.0;  // ours, the median run
    std::vector<Hit> hits;        // ours, the last run
};

// `singleRates`: each set's single-ray rate (benchPackets); ours is the faster of it and the
// set's own.
void benchEmbree(const CompiledScene& compiled, const std::vector<TracedRaySet>& sets,
                 const std::vector<double>& singleRates, uint32_t runs, BenchReport& report);

}  // namespace pt::cli
