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

}  // namespace pt::test
