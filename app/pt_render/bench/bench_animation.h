#pragma once
// Per-frame update figures for `pt-render bench` on a scene with animations (issue 19): each
// frame poses every rig (host) and syncs the backend (skin, BLAS refit or rebuild, TLAS), the
// work between one frame of an animation and the first sample of the next. Timed with
// skinning on the host and, where the backend skins on its device, there, in the same run, so
// the ratio says what the GPU skin saves.
#include <string>

#include "pt_render/bench/bench_render.h"

namespace pt::cli {

// Nothing where the scene has no animation. Runs on a fresh backend of `backendName`.
void benchAnimation(const std::string& backendName, Scene scene, const BenchSettings& settings,
                    BenchReport& report);

}  // namespace pt::cli
