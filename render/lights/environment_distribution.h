#pragma once
// Host: the importance-sampling distribution of an equirectangular environment image
// (render/lights/environment_sampling.h samples it), and the environment's average radiance.
#include <vector>

#include "render/kernel/render_scene.h"
#include "render/scene/scene.h"

namespace pt {

struct EnvironmentDistribution {
    uint32_t width = 0, height = 0;     // grid = image pixels; 0 x 0: nothing to sample
    std::vector<float> pdf;             // height x width, density on the unit square (mean 1)
    std::vector<float> marginalCdf;     // height + 1
    std::vector<float> conditionalCdf;  // height x (width + 1)
    // Mean luminance over the sphere of directions (solid-angle weighted), before intensity.
    double averageLuminance = 0.0;
};

// Cell (x, y) weighs the mean luminance of the image's reconstruction over the cell (the
// exact mean of bilinear filtering, or the texel itself for nearest filtering) times
// sin(theta) at the cell's centre, so a cell is never given zero probability where the
// lookup can return light. An all-black image gives an empty distribution.
EnvironmentDistribution buildEnvironmentDistribution(const Texture& image);

}  // namespace pt
