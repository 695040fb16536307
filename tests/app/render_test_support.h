#pragma once
// Loading scenes and comparing images for image tests.
#include <string>
#include <vector>

#include "render/scene/scene.h"
#include "support/render_cpu.h"

namespace pt::test {

Scene loadSceneOrFail(const std::string& path);

// Relative MSE of `image` against `reference` (RGB, RGBA layout): mean of
// (x - r)^2 / (r^2 + epsilon), the error measure of the convergence reports.
double relativeMse(const std::vector<float>& image, const std::vector<float>& reference);

}  // namespace pt::test
