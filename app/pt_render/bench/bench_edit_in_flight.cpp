// Edit to first frame with the editor's render thread running, as a user meets it: the edit
// arrives while a pass is in flight. Measured twice in one run, with the pass interrupted
// (EditorSession's default: the edit waits for one sample or wave) and left to finish (the
// baseline: the edit also waits for the rest of the pass).
#include <chrono>
#include <cstdio>
#include <random>
#include <thread>

#include "editor/editor_session.h"
#include "editor/render_worker.h"
#include "editor/scene_edits.h"
#include "pt_render/bench/bench_edits.h"

namespace pt::cli {
namespace {

using editor::EditorSession;
using editor::RenderWorker;

// Polls `done` every 0.1 ms; false after a minute (a stuck render thread).
template <typename Done>
bool waitFor(Done done) {
    const auto deadline = Clock::now() + std::chrono::seconds(60);
    while (!done()) {
        if (Clock::now() > deadline) return false;
        std::this_thread::sleep_for(std::chrono::microseconds(100));
    }
    return true;
}

// Median milliseconds from a camera edit to its first frame, over `edits` edits each made at a
// random moment of the pass in flight.
double medianEditToFrame(const std::string& backendName, const Scene& scene, const BenchSettings& settings,
                         bool interrupts, uint32_t edits, double* secondsPerPass) {
    EditorSession session(createBackend(backendName));
    session.setPassInterrupts(interrupts);
    session.adopt(scene);
    session.execute(editor::setToggles(session.document(), settings.toggles));
    RenderWorker worker(session);
    worker.setHostFrames(false);  // the frame's copy is not what is measured
    if (!waitFor([&] { return worker.status().secondsPerPass > 0.0; })) return 0.0;
    std::mt19937 rng(7);
    std::vector<double> toFrame;
    for (uint32_t run = 0; run <= edits; ++run) {
        *secondsPerPass = worker.status().secondsPerPass;
        std::uniform_real_distribution<double> phase(0.0, *secondsPerPass);
        std::this_thread::sleep_for(std::chrono::duration<double>(phase(rng)));
        worker.edit([run](EditorSession& s) {
            Camera camera = s.document().scene.camera;
            camera.position.x += run % 2 ? 1e-3f : -1e-3f;
            s.execute(editor::setCamera(s.document(), camera));
        });
        if (!waitFor([&] { return session.lastEdit().complete; })) return 0.0;
        if (run > 0) toFrame.push_back(session.lastEdit().toFrameSeconds);  // run 0: warm-up
    }
    return median(toFrame) * 1e3;
}

}  // namespace

void benchEditInFlight(const std::string& backendName, const Scene& scene, const BenchSettings& settings,
                       BenchReport& report) {
    const uint32_t edits = 4 * settings.runs;  // the phase is random: more runs for a steady median
    double secondsPerPass = 0.0;
    const double waits = medianEditToFrame(backendName, scene, settings, false, edits, &secondsPerPass);
    const double interrupts = medianEditToFrame(backendName, scene, settings, true, edits, &secondsPerPass);
    char pass[96];
    std::snprintf(pass, sizeof pass, "camera edits at random moments of a %.3g ms pass",
                  secondsPerPass * 1e3);
    report.add({"edit during a pass", "camera (orbit)", "pass finishes first (baseline)", waits, "ms", pass});
    char ratio[64];
    std::snprintf(ratio, sizeof ratio, "%.2fx faster than the baseline",
                  interrupts > 0.0 ? waits / interrupts : 0.0);
    report.add({"edit during a pass", "camera (orbit)", "pass interrupted", interrupts, "ms", ratio});
}

}  // namespace pt::cli
