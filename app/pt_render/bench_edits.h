#pragma once
// Edit-to-frame latency for `pt-render bench`, measured through the editor's own path
// (pt::editor::EditorSession): a command is executed, the session syncs the backend, renders
// one pass and reads the frame the viewport would show. So the figures are the editor's.
#include "bench_render.h"

namespace pt::cli {

// Runs on a fresh backend of `backendName`, the scene at its own size.
void benchEdits(const std::string& backendName, Scene scene, const BenchSettings& settings, BenchReport& report);

}  // namespace pt::cli
