// Environment: what lights the scene from afar, a constant colour or an equirectangular HDR
// image, with its strength and rotation about +Y. Each change is an undoable edit whose sync
// rebuilds the light table (the image's importance-sampling table with it).
#include <filesystem>
#include <string>

#include "assets/input_error.h"
#include "editor/scene_edits.h"
#include "editor/ui/file_picker.h"
#include "editor/ui/widgets.h"

namespace pt::editor {

namespace {

namespace fs = std::filesystem;

void loadImage(EditorUi& ui, const std::string& path) {
    try {
        ui.apply(setEnvironmentImage(ui.doc(), path));
        ui.notify("Environment: " + path);
    } catch (const InputError& error) {
        ui.showError(error.what());  // the current environment stays
    }
}

}  // namespace

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
        tooltipIfCut("Colour");
        closeStepIfReleased(ui);
    }
    static FilePicker picker({".hdr", ".exr"}, false);
    if (ImGui::Button("Choose image...")) {
        const std::string& source = ui.doc().scene.sourcePath;
        const std::string folder = source.empty() ? "" : fs::absolute(source).parent_path().string();
        picker.start(e.imagePath.empty() ? (folder.empty() ? "" : folder + "/") : e.imagePath, folder);
        ImGui::OpenPopup("Environment image");
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("An equirectangular HDR image (.hdr or .exr) to light the scene");
    if (ImGui::BeginPopupModal("Environment image", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        const bool chosen = picker.draw("Path", 620.0f, 260.0f);
        if (ImGui::Button("Load") || chosen) {
            loadImage(ui, picker.path());
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (dialogCancelled()) ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
    changed |= sliderFloat(ui, "Strength", &e.intensity, 0.0f, 100.0f, "%.3f", ImGuiSliderFlags_Logarithmic);
    changed |= sliderFloat(ui, "Rotation (deg)", &e.rotationDegrees, -180.0f, 180.0f, "%.1f");
    if (changed) ui.apply(setEnvironment(ui.doc(), e));
}

}  // namespace pt::editor
