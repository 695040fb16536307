#pragma once
// Comparing images for image tests (and the helpers they load and render with).
#include <string>
#include <vector>

#include "render/scene/scene.h"
#include "support/load_scene.h"
#include "support/render_cpu.h"

namespace pt::test {

// Relative error of block means: the images (width x height, RGBA) are averaged over
// block x block pixel tiles, and the mean over tiles and channels of |x - r| / (r + 0.01) is
// returned. Averaging first makes it robust to the few bright outliers (caustic paths) that
// dominate a per-pixel relMSE at low sample counts, while any bias of a few percent shows.
double blockRelativeError(const std::vector<float>& image, const std::vector<float>& reference,
                          uint32_t width, uint32_t height, uint32_t block);

}  // namespace pt::test
