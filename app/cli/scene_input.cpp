#include "cli/scene_input.h"

#include <cstdio>
#include <stdexcept>

#include "assets/scene_loader.h"
#include "render/util/stopwatch.h"

namespace pt::cli {

SceneInput loadSceneInput(const std::string& path, ProgressBar& progress) {
    const auto start = Clock::now();
    LoadResult result = loadScene(path, progress.callback());
    progress.finish();
    if (!result.ok()) throw std::runtime_error(result.error);
    SceneInput input{std::move(*result.scene), 0.0};
    input.loadSeconds = secondsSince(start);
    for (const std::string& warning : input.scene.warnings) {
        std::fprintf(stderr, "warning: %s\n", warning.c_str());
    }
    return input;
}

}  // namespace pt::cli
