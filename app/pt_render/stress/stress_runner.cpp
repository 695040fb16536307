#include "pt_render/stress/stress_runner.h"

#include <stdexcept>

#include "assets/scene_loader.h"

namespace pt::cli {

namespace {

Scene loadOrThrow(const std::string& path) {
    LoadResult result = loadScene(path);
    if (!result.ok()) throw std::runtime_error(result.error);
    return std::move(*result.scene);
}

}  // namespace

StressRunner::StressRunner(std::string backend, bool quick, std::string scenesFolder)
    : backend_(std::move(backend)), quick_(quick), scenesFolder_(std::move(scenesFolder)) {}

StressBudget StressRunner::budget(StressScale scale) const {
    // Quick: the whole suite in well under a minute on two cores; full: noise low enough to
    // see biases of a few percent.
    switch (scale) {
        case StressScale::Box: return quick_ ? StressBudget{32, 32, 16, 4} : StressBudget{96, 96, 64, 4};
        case StressScale::Furnace: return quick_ ? StressBudget{16, 16, 16, 4} : StressBudget{64, 64, 64, 4};
        case StressScale::Accumulation:
            return quick_ ? StressBudget{1, 1, 250000, 4} : StressBudget{4, 4, 250000, 4};
    }
    return {};
}

BatchedImage StressRunner::render(const std::string& scenePath, StressScale scale, const SceneEdit& edit,
                                  uint32_t seed) {
    Scene scene = loadOrThrow(scenesFolder_ + "/" + scenePath);
    warnings_ = scene.warnings;
    if (edit) edit(scene);
    const StressBudget b = budget(scale);
    scene.render.width = b.width;
    scene.render.height = b.height;
    scene.render.seed = seed * b.batches;
    std::unique_ptr<Backend> backend = createBackend(backend_);
    backend->sync(scene, SceneChanges::All);
    return renderBatches(*backend, scene, b.sppPerBatch, b.batches);
}

const BatchedImage& StressRunner::baseline(const std::string& scene, StressScale scale) {
    const std::string key = scene + "#" + std::to_string(int(scale));
    auto cached = baselines_.find(key);
    if (cached == baselines_.end())
        cached = baselines_.emplace(key, render(scene, scale, {}, kBaselineSeed)).first;
    return cached->second;
}

std::string StressRunner::loadError(const std::string& scene) const {
    const LoadResult result = loadScene(scenesFolder_ + "/" + scene);
    return result.ok() ? "" : result.error;
}

}  // namespace pt::cli
