#include "cli/render_setup.h"

namespace pt::cli {

const std::set<std::string>& renderSetupValuedFlags() {
    static const std::set<std::string> flags = {"--backend", "--size", "--seed", "--max-depth", "--threads"};
    return flags;
}

const std::set<std::string>& renderSetupSwitches() {
    static const std::set<std::string> switches = {"--quiet"};
    return switches;
}

RenderSetup parseRenderSetup(const Options& o) {
    RenderSetup s;
    s.backend = o.value("--backend").value_or("cpu");
    s.size = o.size("--size");
    s.seed = o.nonNegativeInt("--seed");
    s.maxDepth = o.nonNegativeInt("--max-depth");
    s.threads = o.positiveInt("--threads");
    s.quiet = o.has("--quiet");
    return s;
}

void applyRenderSetup(const RenderSetup& setup, Scene& scene) {
    if (setup.size) std::tie(scene.render.width, scene.render.height) = *setup.size;
    if (setup.seed) scene.render.seed = *setup.seed;
    if (setup.maxDepth) scene.render.maxDepth = *setup.maxDepth;
}

std::unique_ptr<tbb::global_control> limitThreads(const RenderSetup& setup) {
    if (!setup.threads) return nullptr;
    return std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                 *setup.threads);
}

std::unique_ptr<Backend> syncedBackend(const RenderSetup& setup, const IntegratorToggles& toggles,
                                       const Scene& scene, ProgressBar& bar) {
    std::unique_ptr<Backend> backend = createBackend(setup.backend);
    backend->setToggles(toggles);
    backend->sync(scene, SceneChanges::All, bar.callback());
    bar.finish();
    return backend;
}

}  // namespace pt::cli
