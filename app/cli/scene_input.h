#pragma once
// Loading the SCENE argument for every subcommand, with progress and timing.
#include <string>

#include "cli/progress_bar.h"
#include "render/scene/scene.h"

namespace pt::cli {

struct SceneInput {
    Scene scene;
    double loadSeconds = 0.0;
};

// Throws std::runtime_error carrying the loader's message (file and element named).
SceneInput loadSceneInput(const std::string& path, ProgressBar& progress);

}  // namespace pt::cli
