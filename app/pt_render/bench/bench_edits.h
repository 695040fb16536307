#pragma once
// Edit-to-frame latency for `pt-render bench`, measured through the editor's own path
// (pt::editor::EditorSession): a command is executed, the session syncs the backend, renders
// one pass and reads the frame the viewport would show. So the figures are the editor's.
#include "pt_render/bench/bench_render.h"

namespace pt::cli {

// Runs on a fresh backend of `backendName`, the scene at its own size.
void benchEdits(const std::string& backendName, Scene scene, const BenchSettings& settings,
                BenchReport& report);

// The same through the editor's render thread (pt::editor::RenderWorker) rendering without
// pause, so each edit arrives during a pass: with the pass interrupted and, as the baseline,
// left to finish (bench_edit_in_flight.cpp).
void benchEditInFlight(const std::string& backendName, const Scene& scene, const BenchSettings& settings,
                       BenchReport& report);

}  // namespace pt::cli
