#pragma once
// Ray sets for traversal benchmarks, made beforehand on the host so only traversal is timed:
// camera rays through every pixel, one cosine-distributed bounce from each camera hit, and one
// shadow ray from each camera hit towards a light sample.
#include <vector>

#include "render/compile/compile_scene.h"
#include "render/math/ray.h"

namespace pt::cli {

struct BenchRays {
    std::vector<Ray> primary, diffuse, shadow;
};

// `scene` was compiled for an image of width x height (its camera).
BenchRays makeBenchRays(const CompiledScene& scene, uint32_t width, uint32_t height, uint32_t seed);

}  // namespace pt::cli
