#pragma once
// What the commands that render a scene (render, bench, reference, converge, stress) share:
// the --backend, --size, --seed, --max-depth, --threads and --quiet options, a backend with
// the scene loaded and synced, and the thread limit.
#include <tbb/global_control.h>

#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>

#include "cli/cli_options.h"
#include "cli/progress_bar.h"
#include "render/backend/backend.h"
#include "render/scene/scene.h"

namespace pt::cli {

struct RenderSetup {
    std::string backend = "cpu";
    std::optional<std::pair<uint32_t, uint32_t>> size;
    std::optional<uint32_t> seed, maxDepth, threads;
    bool quiet = false;
};

const std::set<std::string>& renderSetupValuedFlags();  // --backend --size --seed --max-depth --threads
const std::set<std::string>& renderSetupSwitches();     // --quiet
RenderSetup parseRenderSetup(const Options& options);

// Size, seed and depth of the command line over the scene's own.
void applyRenderSetup(const RenderSetup& setup, Scene& scene);

// Caps TBB's threads at --threads for the lifetime of the returned object (null: no cap).
std::unique_ptr<tbb::global_control> limitThreads(const RenderSetup& setup);

// A backend of the setup's kind with `toggles`, synced with the whole of `scene` (BVH built).
std::unique_ptr<Backend> syncedBackend(const RenderSetup& setup, const IntegratorToggles& toggles,
                                       const Scene& scene, ProgressBar& bar);

}  // namespace pt::cli
