// The status bar: the last notice on the left (saved, exported, a screenshot, a loaded scene's
// warnings), the render's progress on the right (a stage under way, or samples and their rate,
// or the target reached).
#include <cstdio>
#include <string>

#include "editor/ui/widgets.h"

namespace pt::editor {

void drawStatusBar(EditorUi& ui, float width, float height) {
    const float barHeight = ImGui::GetFrameHeight();
    ImGui::SetNextWindowPos(ImVec2(0.0f, height - barHeight));
    ImGui::SetNextWindowSize(ImVec2(width, barHeight));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImGui::GetStyle().FramePadding);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowRounding, 0.0f);
    ImGui::Begin("##status", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoBringToFrontOnFocus);
    const WorkerStatus status = ui.worker.status();
    const BackendStats& stats = ui.lastFrame.stats;
    char progress[160];
    if (!status.stage.empty()) {
        std::snprintf(progress, sizeof progress, "%s %d%%", status.stage.c_str(),
                      int(status.fraction * 100.0));
    } else if (status.converged) {
        std::snprintf(progress, sizeof progress, "%u spp: target reached", stats.samplesPerPixel);
    } else {
        const double rate = status.secondsPerPass > 0.0 ? 1.0 / status.secondsPerPass : 0.0;
        std::snprintf(progress, sizeof progress, "%u spp, %.1f spp/s, %ux%u", stats.samplesPerPixel, rate,
                      ui.lastFrame.width, ui.lastFrame.height);
    }
    const float progressWidth = ImGui::CalcTextSize(progress).x;
    // The notice, cut to the room left of the progress (its whole text in a tooltip).
    ImGui::PushClipRect(ImGui::GetCursorScreenPos(), ImVec2(width - progressWidth - 24.0f, height), true);
    ImGui::TextUnformatted(ui.notice.c_str());
    ImGui::PopClipRect();
    if (ImGui::IsItemHovered() && !ui.notice.empty()) ImGui::SetTooltip("%s", ui.notice.c_str());
    ImGui::SameLine(width - progressWidth - 12.0f);
    ImGui::TextUnformatted(progress);
    ImGui::End();
    ImGui::PopStyleVar(2);
}

}  // namespace pt::editor
