#include "editor/scene_load_job.h"

namespace pt::editor {

SceneLoadJob::SceneLoadJob(std::string path) : path_(std::move(path)) {
    thread_ = std::thread([this] {
        LoadResult result = loadScene(path_, [this](const std::string& stage, double f) {
            std::lock_guard<std::mutex> lock(mutex_);
            stage_ = stage;
            fraction_ = f;
        });
        std::lock_guard<std::mutex> lock(mutex_);
        result_ = std::move(result);
        done_ = true;
    });
}

SceneLoadJob::~SceneLoadJob() { thread_.join(); }

std::string SceneLoadJob::stage() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return stage_;
}

double SceneLoadJob::fraction() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return fraction_;
}

LoadResult SceneLoadJob::take() {
    std::lock_guard<std::mutex> lock(mutex_);
    return std::move(result_);
}

}  // namespace pt::editor
