#include "pt_render/bench/bench_animation.h"

#include <algorithm>
#include <map>
#include <memory>

#include "pt_render/bench/bench_sync.h"
#include "render/util/stopwatch.h"

namespace pt::cli {

namespace {

constexpr double kFramesPerSecond = 30.0;

// What one site's frames cost: the whole update, the host's pose, and each sync step, per
// frame (a step run several times in a frame, once per mesh, summed).
struct FrameFigures {
    std::vector<double> update, pose;
    std::map<std::string, std::vector<double>> steps;
    std::map<std::string, int> actions;
};

double longestDuration(const Scene& scene, const std::vector<int32_t>& chosen) {
    double longest = 0.0;
    for (size_t r = 0; r < chosen.size(); ++r) {
        if (chosen[r] >= 0)
            longest = std::max(longest, double(scene.rigs[r].animations[size_t(chosen[r])].duration()));
    }
    return longest;
}

FrameFigures timeFrames(Backend& backend, Scene& scene, const std::vector<int32_t>& chosen, SkinningSite site,
                        uint32_t frames) {
    const double duration = std::max(longestDuration(scene, chosen), 1.0 / kFramesPerSecond);
    FrameFigures figures;
    for (uint32_t f = 0; f <= frames; ++f) {
        // Frames at 30 fps through the animation, wrapping: every frame a new pose.
        const float time = float(std::fmod(double(f + 1) / kFramesPerSecond, duration));
        const auto start = Clock::now();
        const SceneDelta delta = poseAnimations(scene, chosen, time, site);
        const double posed = secondsSince(start);
        const SyncReport sync = backend.sync(scene, delta, {});
        const double updated = secondsSince(start);
        if (f == 0) continue;  // warm-up: first refits allocate and measure the built SAH
        figures.update.push_back(updated);
        figures.pose.push_back(posed);
        std::map<std::string, double> frameSteps;
        for (const SyncStep& step : sync.steps) frameSteps[step.name] += step.seconds;
        for (const auto& [name, seconds] : frameSteps) figures.steps[name].push_back(seconds);
        ++figures.actions[sync.action];
    }
    return figures;
}

std::string actionCounts(const std::map<std::string, int>& actions) {
    std::string note;
    for (const auto& [action, count] : actions)
        note += (note.empty() ? "" : ", ") + std::to_string(count) + " " + action;
    return note;
}

const char* siteName(SkinningSite site) {
    return site == SkinningSite::Device ? "skin on GPU" : "skin on host";
}

}  // namespace

void benchAnimation(const std::string& backendName, Scene scene, const BenchSettings& settings,
                    BenchReport& report) {
    bool animated = false;
    for (const AnimationRig& rig : scene.rigs) animated |= !rig.animations.empty();
    if (!animated) return;
    const std::vector<int32_t> chosen = chooseAnimations(scene, "");
    std::unique_ptr<Backend> backend = createBackend(backendName);
    backend->setToggles(settings.toggles);
    std::vector<SkinningSite> sites = {SkinningSite::Host};
    if (backend->capabilities().skinsOnDevice) sites.push_back(SkinningSite::Device);
    uint32_t vertices = 0;
    for (const AnimationRig& rig : scene.rigs) {
        for (const SkinnedMesh& skinned : rig.skinnedMeshes)
            vertices += uint32_t(skinned.bindPositions.size());
    }
    const uint32_t frames = std::max(4 * settings.runs, 12u);
    std::map<SkinningSite, double> updateMedian;
    for (const SkinningSite site : sites) {
        skinPendingOnHost(scene);
        syncSettled(*backend, scene, SceneChanges::All);
        const FrameFigures figures = timeFrames(*backend, scene, chosen, site, frames);
        updateMedian[site] = median(figures.update);
        report.add({"animation", "frame update (pose + sync)", siteName(site), 1e3 * updateMedian[site], "ms",
                    std::to_string(frames) + " frames at 30 fps, " + std::to_string(vertices) +
                        " skinned vertices; " + actionCounts(figures.actions)});
        report.add({"animation", "pose (host)", siteName(site), 1e3 * median(figures.pose), "ms", ""});
        for (const auto& [step, seconds] : figures.steps) {
            report.add({"animation", step, siteName(site), 1e3 * median(seconds), "ms",
                        seconds.size() < frames ? "in " + std::to_string(seconds.size()) + " frames" : ""});
        }
    }
    if (sites.size() == 2) {
        report.add({"animation", "frame update, host skin / GPU skin", "",
                    updateMedian[SkinningSite::Host] / updateMedian[SkinningSite::Device], "x", "same run"});
    }
}

}  // namespace pt::cli
