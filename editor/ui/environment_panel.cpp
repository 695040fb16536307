// Environment: what lights the scene from afar, a constant colour or an equirectangular HDR
// image, with its strength and rotation about +Y. Each change is an undoable edit whose sync
// rebuilds the light table (the image's importance-sampling table with it).
#include <cstdio>
#include <filesystem>
#include <string>

#include "assets/input_error.h"
#include "editor/scene_edits.h"
#include "editor/ui/widgets.h"

namespace pt::editor {

void drawEnvironmentPanel(EditorUi& ui) {
    if (!ImGui::CollapsingHeader("Environment")) return;
    Environment e = ui.doc().scene.environment;
    bool changed = false;
    if (e.texture >= 0) {
        ImGui::Text("Image: %s", std::filesystem::path(e.imagePath).filename().string().c_str());
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", e.imagePath.c_str());
        ImGui::SameLine();
        if (ImGui::SmallButton("Remove")) {
            e.texture = -1;
            e.imagePath.clear();
            changed = true;
        }
    } else {
        changed |=
            ImGui::ColorEdit3("Colour", &e.color.x, ImGuiColorEditFlags_HDR | ImGuiColorEditFlags_Float);
        closeStepIfReleased(ui);
    }
    static char path[1024] = "";
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - 90.0f);
    ImGui::InputTextWithHint("##environment image", ".hdr or .exr path", path, sizeof path);
    ImGui::SameLine();
    if (ImGui::Button("Load image") && path[0] != '\0') {
        try {
            ui.apply(setEnvironmentImage(ui.doc(), path));
            ui.notify(std::string("Environment: ") + path);
        } catch (const InputError& error) {
            ui.showError(error.what());  // the current environment stays
        }
    }
    changed |= sliderFloat(ui, "Strength", &e.intensity, 0.0f, 100.0f, "%.3f", ImGuiSliderFlags_Logarithmic);
    changed |= sliderFloat(ui, "Rotation (deg)", &e.rotationDegrees, -180.0f, 180.0f, "%.1f");
    if (changed) ui.apply(setEnvironment(ui.doc(), e));
}

}  // namespace pt::editor
