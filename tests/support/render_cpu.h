#pragma once
// Renders a scene on the CPU backend for tests, and fails the test on non-finite samples.
#include <gtest/gtest.h>

#include <vector>

#include "render/backend/cpu/cpu_backend.h"

namespace pt::test {

inline std::vector<float> renderCpu(const Scene& scene, uint32_t spp, const IntegratorToggles& toggles = {}) {
    CpuBackend backend;
    backend.setToggles(toggles);
    backend.sync(scene, SceneChanges::All, {});
    backend.render(spp);
    EXPECT_EQ(backend.stats().nonfiniteSamples, 0u);
    std::vector<float> rgba;
    backend.readBeauty(rgba);
    return rgba;
}

// What a backend holds now, as images (RGBA float).
inline std::vector<float> beautyOf(const Backend& backend) {
    std::vector<float> rgba;
    backend.readBeauty(rgba);
    return rgba;
}
inline std::vector<float> aovOf(const Backend& backend, Aov aov) {
    std::vector<float> rgba;
    backend.readAov(aov, rgba);
    return rgba;
}

// The mean of channel `channel` (0 = R) over all pixels.
inline double meanChannel(const std::vector<float>& rgba, int channel) {
    double sum = 0.0;
    for (size_t i = 0; i < rgba.size() / 4; ++i) sum += rgba[i * 4 + size_t(channel)];
    return sum / double(rgba.size() / 4);
}

}  // namespace pt::test
