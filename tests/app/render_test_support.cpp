#include "render_test_support.h"

#include <gtest/gtest.h>

#include "assets/scene_loader.h"

namespace pt::test {

Scene loadSceneOrFail(const std::string& path) {
    LoadResult result = loadScene(path);
    if (!result.ok()) {
        ADD_FAILURE() << result.error;
        return Scene{};
    }
    return std::move(*result.scene);
}

double relativeMse(const std::vector<float>& image, const std::vector<float>& reference) {
    constexpr double kEpsilon = 1e-2;  // keeps near-black pixels from dominating
    double sum = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < reference.size() && i < image.size(); ++i) {
        if (i % 4 == 3) continue;
        const double d = double(image[i]) - reference[i];
        sum += d * d / (double(reference[i]) * reference[i] + kEpsilon);
        ++n;
    }
    return n ? sum / double(n) : 0.0;
}

}  // namespace pt::test
