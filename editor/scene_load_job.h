#pragma once
// SceneLoadJob: loads a scene file on its own thread so the window keeps drawing (and shows the
// loader's progress) while a large glTF is read and checked.
#include <atomic>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "assets/scene_loader.h"

namespace pt::editor {

class SceneLoadJob {
public:
    explicit SceneLoadJob(std::string path);
    ~SceneLoadJob();
    SceneLoadJob(const SceneLoadJob&) = delete;
    SceneLoadJob& operator=(const SceneLoadJob&) = delete;

    const std::string& path() const { return path_; }
    bool done() const { return done_; }
    std::string stage() const;
    double fraction() const;
    LoadResult take();  // only once done()

private:
    std::string path_;
    mutable std::mutex mutex_;
    std::string stage_ = "load";
    double fraction_ = 0.0;
    LoadResult result_;
    std::atomic<bool> done_{false};
    std::thread thread_;
};

}  // namespace pt::editor
