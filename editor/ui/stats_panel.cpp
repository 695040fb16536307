// Stats: samples, frame times, throughput, scene features and the kernel variant, what the last
// edit made the backend do and how long it took to reach the screen, memory. The overlay keeps
// the main figures in the viewport's corner, seen whatever panels are open above Stats.
#include <algorithm>
#include <numeric>
#include <string>
#include <vector>

#include "editor/ui/error_plot.h"
#include "editor/ui/widgets.h"
#include "render/compile/scene_features.h"

namespace pt::editor {

namespace {

// Error against the reference image (Display > Reference image), live: the last figures, the
// verdict of the curve's last decade (as pt-render converge judges it) and the log-log plot.
void drawErrorAgainstReference(EditorUi& ui) {
    const auto reference = ui.worker.errors().reference();
    if (!reference) return;
    ImGui::Separator();
    ImGui::TextWrapped("Error against %s", reference->path.c_str());
    const std::string problem = ui.worker.errors().problem();
    if (!problem.empty()) {
        ImGui::TextColored(ImVec4(1, 0.6f, 0.3f, 1), "Not measured: %s", problem.c_str());
        return;
    }
    const std::vector<ErrorPoint> curve = ui.worker.errors().curve();
    if (!curve.empty()) {
        const ErrorPoint& last = curve.back();
        ImGui::Text("relMSE %.3g  RMSE %.3g  MAPE %.2f%%  (%u spp, %.2f s)", last.error.relMse,
                    last.error.rmse, last.error.mape, last.spp, last.seconds);
        const TailSlope fit = fitTailSlope(curve, reference->noiseRelMse);
        if (fit.points >= 3 && !fit.exact) {
            const bool stuck = biasedOrStuck(fit);
            ImGui::TextColored(
                stuck ? ImVec4(1, 0.4f, 0.4f, 1) : ImVec4(0.6f, 0.9f, 0.6f, 1), "slope %.2f: %s", fit.slope,
                stuck ? "the error has stopped falling (biased, or the reference differs)" : "converging");
        }
    }
    drawErrorPlot(curve, reference->noiseRelMse, 140.0f);
}

// What the scene uses and, on the GPU, the kernel variant that renders it. These come with each
// frame's BackendStats (copied on the render thread in RenderWorker::publishFrame), never from
// the backend itself. When an edit adds a feature (say, a clearcoat slider moved off 0), the
// backend recomputes the features at the sync that edit triggers (updateFeatures), and the CUDA
// backend switches to a kernel variant that covers them before it renders the next samples, so
// no sample is ever rendered by a kernel missing code the scene needs; the first frame after
// the edit shows the new set here.
void drawFeatures(const BackendStats& s) {
    ImGui::TextWrapped("Features: %s", describeFeatures(s.features).c_str());
    if (!s.kernelVariant.empty()) {
        ImGui::TextWrapped("Kernel: %s (%s)", s.kernelVariant.c_str(),
                           describeFeatures(s.kernelFeatures).c_str());
    }
    if (s.schedule.empty()) return;
    // Under the auto schedule, the rates its trial measured on this scene (0: not run yet).
    if (s.megakernelRate > 0.0 || s.wavefrontRate > 0.0) {
        ImGui::Text("Schedule: %s (auto: megakernel %.0f, wavefront %.0f spp/s)", s.schedule.c_str(),
                    s.megakernelRate, s.wavefrontRate);
    } else {
        ImGui::Text("Schedule: %s", s.schedule.c_str());
    }
    if (!s.walk.empty()) ImGui::Text("BVH walk: %s nodes", s.walk.c_str());
}

float meanFrameMillis(const EditorUi& ui) {
    if (ui.frameMillis.empty()) return 0.0f;
    return std::accumulate(ui.frameMillis.begin(), ui.frameMillis.end(), 0.0f) / float(ui.frameMillis.size());
}

double megaraysPerSecond(const BackendStats& s) {
    return s.renderSeconds > 0 ? double(s.rays) / s.renderSeconds / 1e6 : 0.0;
}

}  // namespace

void drawStatsOverlay(EditorUi& ui, const ImageRect& image) {
    if (!ui.layout.statsOverlay || image.imageWidth == 0) return;
    const WorkerStatus status = ui.worker.status();
    const BackendStats& s = ui.lastFrame.stats;
    // The bottom right corner: the toolbar holds the top left, and a narrow viewport puts the
    // top right next to it.
    ImGui::SetNextWindowPos(ImVec2(image.x + image.width - 6.0f, image.y + image.height - 6.0f),
                            ImGuiCond_Always, ImVec2(1.0f, 1.0f));
    ImGui::SetNextWindowBgAlpha(0.55f);
    ImGui::Begin("##stats overlay", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                     ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs);
    ImGui::Text("%s %ux%u  %u spp%s", ui.backendName.c_str(), ui.lastFrame.width, ui.lastFrame.height,
                s.samplesPerPixel, status.converged ? " (done)" : "");
    ImGui::Text("%.1f ms/pass  %.1f Mrays/s  UI %.1f ms", status.secondsPerPass * 1e3, megaraysPerSecond(s),
                double(meanFrameMillis(ui)));
    const EditLatency edit = ui.session.lastEdit();
    if (!edit.label.empty()) {
        if (edit.complete)
            ImGui::Text("%s: first frame %.1f ms", edit.label.c_str(), edit.toFrameSeconds * 1e3);
        else
            ImGui::Text("%s: ...", edit.label.c_str());
    }
    if (status.deviceMemoryBytes > 0)
        ImGui::Text("GPU %.1f MiB", double(status.deviceMemoryBytes) / (1024.0 * 1024.0));
    ImGui::End();
}

void drawStatsPanel(EditorUi& ui) {
    if (!ImGui::CollapsingHeader("Stats", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const WorkerStatus status = ui.worker.status();
    const BackendStats& s = ui.lastFrame.stats;
    ImGui::Text("Backend: %s   %ux%u", ui.backendName.c_str(), ui.lastFrame.width, ui.lastFrame.height);
    if (!ui.framePath.empty()) ImGui::TextWrapped("Frames: %s", ui.framePath.c_str());
    if (!ui.glRenderer.empty()) ImGui::TextWrapped("GL: %s", ui.glRenderer.c_str());
    ImGui::Text("Samples: %u spp%s", s.samplesPerPixel, status.converged ? " (target reached)" : "");
    if (!ui.frameMillis.empty()) {
        const float mean = meanFrameMillis(ui);
        ImGui::Text("UI: %.1f ms/frame (%.0f frames/s)", double(mean),
                    mean > 0 ? 1000.0 / double(mean) : 0.0);
        ImGui::PlotLines("##frame ms", ui.frameMillis.data(), int(ui.frameMillis.size()), 0,
                         "ms per UI frame", 0.0f, 100.0f, ImVec2(0, 40));
    }
    ImGui::Text("Render: %.1f ms/pass, %.1f Mrays/s", status.secondsPerPass * 1e3, megaraysPerSecond(s));
    if (ui.doc().viewer.denoise && status.denoiseSeconds > 0.0) {
        ImGui::Text("Denoise: %.2f ms a frame", status.denoiseSeconds * 1e3);
    }
    ImGui::Text("Scene: %llu triangles, %u instances", static_cast<unsigned long long>(s.triangles),
                s.instances);
    drawFeatures(s);
    if (s.nonfiniteSamples > 0) {
        ImGui::TextColored(ImVec4(1, 0.5f, 0.3f, 1), "%llu non-finite samples dropped",
                           static_cast<unsigned long long>(s.nonfiniteSamples));
    }
    const EditLatency edit = ui.session.lastEdit();
    if (!edit.label.empty()) {
        ImGui::Separator();
        ImGui::TextWrapped("Last edit: %s", edit.label.c_str());
        ImGui::Text("Triggered: %s (sync %.2f ms)", edit.action.empty() ? "..." : edit.action.c_str(),
                    edit.syncSeconds * 1e3);
        if (edit.complete) ImGui::Text("Edit to first frame: %.2f ms", edit.toFrameSeconds * 1e3);
        // The user's wait: from the input event to the swapped window frame that shows the edit.
        const std::deque<ScreenLatencyRecord>& shown = ui.screenLatency.recent();
        if (!shown.empty()) {
            ImGui::Text("Input to screen: %.1f ms (median of %zu: %.1f ms)", shown.back().inputToSwapMillis(),
                        shown.size(), ui.screenLatency.recentMedianMillis());
        }
        // Each step of that sync (an animation frame: skin, BLAS refit or rebuild, TLAS).
        for (const SyncStep& step : ui.session.lastSync().steps) {
            if (step.seconds > 0.0) ImGui::BulletText("%s: %.3f ms", step.name.c_str(), step.seconds * 1e3);
        }
    }
    if (!status.pathsAlivePerBounce.empty()) {
        std::vector<float> alive(status.pathsAlivePerBounce.begin(), status.pathsAlivePerBounce.end());
        ImGui::PlotHistogram("##alive", alive.data(), int(alive.size()), 0, "paths alive per bounce", 0.0f,
                             alive.front(), ImVec2(0, 50));
        ImGui::Text("bounce 0: %u paths, last (%zu): %u", status.pathsAlivePerBounce.front(),
                    alive.size() - 1, status.pathsAlivePerBounce.back());
    }
    if (status.deviceMemoryBytes > 0) {
        ImGui::Text("GPU memory: %.1f MiB", double(status.deviceMemoryBytes) / (1024.0 * 1024.0));
    }
    drawErrorAgainstReference(ui);
    if (!status.stage.empty())
        ImGui::ProgressBar(float(status.fraction), ImVec2(-1, 0), status.stage.c_str());
    if (!status.error.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", status.error.c_str());
}

}  // namespace pt::editor
