// Render settings: backend, resolution, depth, samples per frame and target, the integrator's
// switches and every optimization toggle of the active backend (with why one is inactive).
#include <algorithm>
#include <string>

#include "editor/scene_edits.h"
#include "editor/ui/widgets.h"
#include "render/backend/toggle_table.h"

namespace pt::editor {
namespace {

void backendChoice(EditorUi& ui) {
    const char* names[] = {"cpu", "cuda"};
    int current = ui.backendName == "cuda" ? 1 : 0;
    const bool picked = ImGui::Combo("Backend", &current, names, 2);
    tooltipIfCut("Backend");
    if (picked && names[current] != ui.backendName) ui.switchBackend(names[current]);
}

// One checkbox per row of the toggle table (render/backend/toggle_table.h); the scheduling
// rows only where the backend schedules paths on a GPU.
bool toggleCheckboxes(IntegratorToggles& t, ToggleScope scope) {
    bool changed = false;
    for (const ToggleRow& row : toggleTable()) {
        if (row.scope != scope) continue;
        // A schedule named by hand means nothing while the auto schedule picks one.
        const bool disabled = row.id == ToggleId::Megakernel && t.autoSchedule;
        ImGui::BeginDisabled(disabled);
        bool on = row.get(t);
        if (checkbox(row.label, &on)) {
            row.set(t, on);
            changed = true;
        }
        ImGui::EndDisabled();
    }
    return changed;
}

void integratorSwitches(EditorUi& ui) {
    IntegratorToggles t = ui.doc().toggles;
    bool changed = toggleCheckboxes(t, ToggleScope::Integrator);
    changed |= sliderFloat(ui, "Firefly clamp (0 = off)", &t.clampRadiance, 0.0f, 100.0f, "%.2f",
                           ImGuiSliderFlags_Logarithmic);
    if (ui.backendCaps.gpuScheduling) {
        ImGui::Separator();
        ImGui::TextUnformatted("GPU scheduling");
        changed |= toggleCheckboxes(t, ToggleScope::GpuScheduling);
        changed |= sliderFloat(ui, "Rebuild at SAH ratio", &t.rebuildSahRatio, 1.0f, 4.0f);
    }
    if (changed) ui.apply(setToggles(ui.doc(), t));
}

void toggleStates(EditorUi& ui) {
    for (const ToggleState& s : ui.worker.status().toggles) {
        if (s.requested && !s.active)
            ImGui::TextDisabled("%s: inactive (%s)", s.name.c_str(), s.note.c_str());
    }
}

// Whether the render follows the viewport, and at what scale of its pixels; off, it renders at
// the Resolution below (the scene's own unless edited).
void renderSize(EditorUi& ui) {
    if (ui.options.width > 0) {
        ImGui::TextDisabled("Render size fixed by --size");
        return;
    }
    ViewerSettings v = ui.doc().viewer;
    bool changed = checkbox("Follow the viewport", &v.followViewport);
    constexpr float kScales[] = {1.0f, 0.75f, 0.5f, 0.25f};
    const char* names[] = {"100%", "75%", "50%", "25%"};
    int current = 0;
    for (int i = 0; i < 4; ++i) current = v.resolutionScale == kScales[i] ? i : current;
    ImGui::SameLine();
    ImGui::SetNextItemWidth(80.0f);
    ImGui::BeginDisabled(!v.followViewport);
    const bool picked = ImGui::Combo("Scale", &current, names, 4);
    tooltipIfCut("Scale");
    if (picked) {
        v.resolutionScale = kScales[current];
        changed = true;
    }
    ImGui::EndDisabled();
    if (changed) ui.apply(setViewer(ui.doc(), v));
}

}  // namespace

void drawRenderPanel(EditorUi& ui) {
    if (!ImGui::CollapsingHeader("Render settings")) return;
    backendChoice(ui);
    renderSize(ui);
    RenderSettings r = ui.doc().scene.render;
    int size[2] = {int(r.width), int(r.height)};
    int depth = int(r.maxDepth);
    bool changed = false;
    ImGui::BeginDisabled(ui.followsViewport());
    const bool typed = ImGui::InputInt2("Resolution", size, ImGuiInputTextFlags_EnterReturnsTrue);
    tooltipIfCut("Resolution");
    if (typed && size[0] > 0 && size[1] > 0) {
        r.width = uint32_t(size[0]);
        r.height = uint32_t(size[1]);
        changed = true;
    }
    ImGui::EndDisabled();
    const bool slid = ImGui::SliderInt("Max depth", &depth, 1, 64);
    tooltipIfCut("Max depth");
    if (slid) {
        r.maxDepth = uint32_t(depth);
        changed = true;
    }
    closeStepIfReleased(ui);
    if (changed) ui.apply(setRenderSettings(ui.doc(), r));
    ViewerSettings v = ui.doc().viewer;
    int perFrame = int(std::max(v.samplesPerFrame, 1u)), target = int(v.targetSpp);
    bool autoPasses = v.samplesPerFrame == 0;
    bool viewerChanged = checkbox("Automatic samples per frame", &autoPasses);
    ImGui::BeginDisabled(autoPasses);
    viewerChanged |= ImGui::SliderInt("Samples per frame", &perFrame, 1, 64);
    tooltipIfCut("Samples per frame");
    ImGui::EndDisabled();
    closeStepIfReleased(ui);
    viewerChanged |= ImGui::InputInt("Stop at spp (0 = never)", &target);
    tooltipIfCut("Stop at spp (0 = never)");
    closeStepIfReleased(ui);
    if (viewerChanged) {
        v.samplesPerFrame = autoPasses ? 0u : uint32_t(std::max(perFrame, 1));
        v.targetSpp = uint32_t(std::max(target, 0));
        ui.apply(setViewer(ui.doc(), v));
    }
    integratorSwitches(ui);
    toggleStates(ui);
}

}  // namespace pt::editor
