#include "scene_input.h"

#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "assets/scene_loader.h"

namespace pt::cli {

SceneInput loadSceneInput(const std::string& path, ProgressBar& progress) {
    const auto start = std::chrono::steady_clock::now();
    LoadResult result = loadScene(path, progress.callback());
    progress.finish();
    if (!result.ok()) throw std::runtime_error(result.error);
    SceneInput input{std::move(*result.scene), 0.0};
    input.loadSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (const std::string& warning : input.scene.warnings) {
        std::fprintf(stderr, "warning: %s\n", warning.c_str());
    }
    return input;
}

}  // namespace pt::cli
