#pragma once
// Loads a scene for a test, failing the test (not crashing) with the loader's message.
#include <gtest/gtest.h>

#include <string>

#include "assets/scene_loader.h"

namespace pt::test {

inline Scene loadSceneOrFail(const std::string& path, const ProgressFn& progress = {}) {
    LoadResult result = loadScene(path, progress);
    if (!result.ok()) ADD_FAILURE() << result.error;
    return result.ok() ? std::move(*result.scene) : Scene{};
}

}  // namespace pt::test
