// Display: what the viewport shows (the beauty or one AOV) and how (exposure, tone mapper).
// Display changes never restart accumulation; switching the AOV starts accumulating that AOV.
#include <string>

#include "editor/scene_edits.h"
#include "editor/ui/widgets.h"

namespace pt::editor {

void drawDisplayPanel(EditorUi& ui, const DisplayView& view) {
    if (!ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen)) return;
    ViewerSettings v = ui.doc().viewer;
    bool changed = false;
    const std::string current = v.aov < 0 ? "beauty" : aovName(Aov(v.aov));
    if (ImGui::BeginCombo("AOV", current.c_str())) {
        if (ImGui::Selectable("beauty", v.aov < 0)) v.aov = -1, changed = true;
        for (int32_t a = 0; a < int32_t(Aov::Count); ++a) {
            if (ImGui::Selectable(aovName(Aov(a)), v.aov == a)) v.aov = a, changed = true;
        }
        ImGui::EndCombo();
    }
    changed |= sliderFloat(ui, "Exposure (stops)", &v.display.exposureStops, -10.0f, 10.0f, "%.2f");
    int op = int(v.display.toneMapper);
    if (ImGui::Combo("Tone mapper", &op, "Standard (sRGB)\0Reinhard\0ACES fitted\0")) {
        v.display.toneMapper = ToneMapper(op);
        changed = true;
    }
    if (v.display.toneMapper == ToneMapper::Reinhard) {
        changed |= sliderFloat(ui, "White point", &v.display.whitePoint, 0.1f, 100.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
    }
    if (changed) ui.apply(setViewer(ui.doc(), v));
    if (v.aov >= 0) {
        const Aov aov = Aov(v.aov);
        if (aov == Aov::Depth || aov == Aov::BvhCost || aov == Aov::SampleCount || aov == Aov::Variance) {
            // The heat map's legend: black at 0 through blue, green and yellow to red at the maximum.
            ImGui::Text("Heat map: 0 (black) ... %.4g (red)", double(view.aovMaximum()));
        } else if (aov == Aov::InstanceId || aov == Aov::MaterialId) {
            ImGui::TextDisabled("False colours; exact ids are in exported EXRs.");
        }
    }
}

}  // namespace pt::editor
